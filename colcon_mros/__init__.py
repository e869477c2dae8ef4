# SPDX-License-Identifier: BSD-3-Clause
"""colcon-mros: mROS v1 (ROS 1) and mros2 (ROS 2) message headers for
firmware, from the ROS build.

docs/design.md maps the subpackages and their layers; tests/test_layers.py
holds every import to them.
"""

__version__ = '0.1.1'
