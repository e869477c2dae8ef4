# SPDX-License-Identifier: BSD-3-Clause
"""The build integrations: where catkin, colcon and rosidl run the
generators, and where the CMake module and the make fragment they and a
firmware use are.

Uses the export and what it stands on; docs/design.md maps the modules and layers.
"""
