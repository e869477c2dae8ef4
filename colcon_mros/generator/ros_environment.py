"""What genmros needs of the ROS installation, checked with a clear message.

genmsg (the parser), empy 3 (the templates) and rospkg (where the ROS
environment's packages are) come with ROS: Debian's python3-genmsg,
python3-empy and python3-rospkg, or a sourced ROS setup (Noetic's
/opt/ros/noetic/setup.bash puts genmsg on PYTHONPATH). Without them the
modules that generate cannot even be imported; this says so in one line
instead of a traceback.
"""

import importlib.util
import sys

from colcon_mros.errors import GenmrosError

REQUIRED_MODULES = (
    ('genmsg', 'genmsg (Debian: apt-get install python3-genmsg; ROS Noetic: source '
               '/opt/ros/noetic/setup.bash)'),
    ('em', 'empy 3 (Debian: apt-get install python3-empy; Ubuntu + Noetic: python3-empy)'),
    ('rospkg', 'rospkg (Debian: apt-get install python3-rospkg; ROS Noetic: source '
               '/opt/ros/noetic/setup.bash)'),
)


def importable(module):
    """Whether this interpreter finds module, without importing it."""
    try:
        return importlib.util.find_spec(module) is not None
    except (ImportError, ValueError):
        return False


def require_ros_python():
    """Raise a one-line GenmrosError if this interpreter cannot import genmsg,
    empy or rospkg. Finding them is enough (importing rospkg would cost a
    generator run, which never needs it, a tenth of its start-up)."""
    for module, what in REQUIRED_MODULES:
        if not importable(module):
            raise GenmrosError('%s cannot import %s; install or source %s, or run genmros with '
                               'the Python that has it' % (sys.executable, module, what))
