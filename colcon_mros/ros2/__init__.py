# SPDX-License-Identifier: BSD-3-Clause
"""The ROS 2 front end: interface files read with rosidl, as a ROS 2 build reads them.

:mod:`colcon_mros.ros2.interfaces` finds the packages and their ``.msg``,
``.srv`` and ``.idl`` files (a workspace's sources, the installed prefixes);
:mod:`colcon_mros.ros2.parse` turns one file into rosidl's IDL definitions
(``.msg`` and ``.srv`` through rosidl_adapter, as rosidl_generate_interfaces
does) with ``FILE:LINE`` errors; :mod:`colcon_mros.ros2.model` is the type
model the mros2 back end renders: members, CDR alignment and sizes, bounds.
"""
