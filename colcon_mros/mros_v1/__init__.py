# SPDX-License-Identifier: BSD-3-Clause
"""The mROS v1 back end: C++ message headers for the mROS v1 library.

:mod:`.cpp` spells the ROS 1 type model in C++, :mod:`.names` hands the
names its headers own to the core's escaping, :mod:`.render` renders the
logic-free templates in ``templates/`` beside the static headers in
``support/``. What the library is, as far as the headers and a firmware's
aggregates need it, is here too: its settings headers and the rule table
of what a type needs of them (:mod:`.rules`), the fit check (:mod:`.fit`)
and its compile-time form (:mod:`.fit_check_header`), the per-firmware
aggregates (:mod:`.aggregates`) and an app's layout (:mod:`.app`). What runs
the library (the PC target, its patches, the fit report) is in
:mod:`colcon_mros.library_tools.mros_v1`.
"""
