# SPDX-License-Identifier: BSD-3-Clause
"""The shared core both stacks' generators stand on.

C++ spelling that every back end needs (:mod:`.cpp_literals`: string and
number literals and comments; :mod:`.cpp_names`: keywords, the standard
headers' names, and the escaping a back end's reserved names feed),
bounded storage and its options files (:mod:`.storage`), the one order types
are exported in (:mod:`.closure`), empy rendering and static headers
(:mod:`.render`, ``support/mros_message_containers.h``), atomic writes
(:mod:`.output`), a library's settings and the fit line (:mod:`.settings`),
the choices the command line offers (:mod:`.defaults`), and how messages
count things (:mod:`.wording`).

It knows no ROS version, no mROS line and no build tool: it imports only
itself and :mod:`colcon_mros.errors`, and names no library setting.
"""
