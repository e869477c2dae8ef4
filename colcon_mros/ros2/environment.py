"""What the ROS 2 front end needs of the installation, checked with a clear message.

rosidl's Python packages (rosidl_adapter, rosidl_parser, rosidl_pycommon)
and empy 3 come with ROS 2's build side: Debian's python3-rosidl, or a
sourced ROS 2 setup (Humble's /opt/ros/humble/setup.bash puts them on
PYTHONPATH).
"""

import sys

from colcon_mros.errors import GenmrosError
from colcon_mros.generator.ros_environment import importable

REQUIRED_MODULES = ('rosidl_adapter', 'rosidl_parser', 'rosidl_pycommon', 'em')


def require_rosidl():
    """Raise a one-line GenmrosError if this interpreter cannot import rosidl or empy."""
    for module in REQUIRED_MODULES:
        if not importable(module):
            raise GenmrosError('%s cannot import %s; install rosidl (Debian: apt-get install '
                               'python3-rosidl; ROS 2 Humble: source /opt/ros/humble/setup.bash), '
                               'or run genmros with the Python that has it'
                               % (sys.executable, module))
