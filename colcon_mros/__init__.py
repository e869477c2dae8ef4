# SPDX-License-Identifier: BSD-3-Clause
"""colcon-mros: ROS 1 message headers for mROS firmware, from the ROS build.

docs/design.md maps the subpackages and their layers; tests/test_layers.py
holds every import to them.
"""

__version__ = '0.1.0'
