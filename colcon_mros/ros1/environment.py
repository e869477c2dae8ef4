# SPDX-License-Identifier: BSD-3-Clause
"""What genmros needs of the ROS 1 installation, checked with a clear message.

genmsg (the parser), empy 3 (the templates) and rospkg (where the ROS
environment's packages are) come with ROS: Debian's python3-genmsg,
python3-empy and python3-rospkg, or a sourced ROS setup (Noetic's
/opt/ros/noetic/setup.bash puts genmsg on PYTHONPATH).
"""

from colcon_mros.core.python_modules import require_modules

REQUIRED_MODULES = {
    'genmsg': 'genmsg (Debian: apt-get install python3-genmsg; ROS Noetic: source '
              '/opt/ros/noetic/setup.bash)',
    'em': 'empy 3 (Debian: apt-get install python3-empy; Ubuntu + Noetic: python3-empy)',
    'rospkg': 'rospkg (Debian: apt-get install python3-rospkg; ROS Noetic: source '
              '/opt/ros/noetic/setup.bash)',
}


def require_ros_python():
    """Raise a one-line GenmrosError if this interpreter cannot import genmsg,
    empy or rospkg. Finding them is enough (importing rospkg would cost a
    generator run, which never needs it, a tenth of its start-up)."""
    require_modules(list(REQUIRED_MODULES), REQUIRED_MODULES.get)
