# SPDX-License-Identifier: BSD-3-Clause
"""The ROS 1 front end: .msg and .srv files read with genmsg.

:mod:`.parse` loads genmsg specs with ``FILE:LINE`` errors (refusing the
names C++ cannot take, with the reserved names a back end hands it),
:mod:`.identity` gives gencpp's MD5 sums and definition texts, and
:mod:`.model` is the type model the mROS v1 back end renders: fields,
constants, wire sizes, the largest frame. :mod:`.definition` names a
definition file, :mod:`.workspace` finds packages, :mod:`.environment`
checks that genmsg is there.
"""
