# SPDX-License-Identifier: BSD-3-Clause
"""What the ROS 2 front end needs of the installation, checked with a clear message.

rosidl's Python packages (rosidl_adapter, rosidl_parser, and rosidl's
helpers: rosidl_pycommon from rosidl 3.3 on, rosidl_cmake in Humble's 3.1)
and empy 3 come with ROS 2's build side: Debian's python3-rosidl, or a
sourced ROS 2 setup (Humble's /opt/ros/humble/setup.bash puts them on
PYTHONPATH).
"""

from colcon_mros.core.python_modules import require_modules
from colcon_mros.ros2.rosidl import HELPER_MODULES

REQUIRED_MODULES = ('rosidl_adapter', 'rosidl_parser', HELPER_MODULES, 'em')


def require_rosidl():
    """Raise a one-line GenmrosError if this interpreter cannot import rosidl or empy."""
    require_modules(REQUIRED_MODULES, lambda module: (
        'rosidl (Debian: apt-get install python3-rosidl; ROS 2 Humble: source '
        '/opt/ros/humble/setup.bash)'))
