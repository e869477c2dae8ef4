# SPDX-License-Identifier: BSD-3-Clause
"""Where ROS is, for the tests, the benchmarks and the main job: read from
the environment as genmros reads it, so that they run wherever ROS is
(a sourced /opt/ros/<distro>, a copy, Debian's /usr).

- ROS 1: the installed prefixes on CMAKE_PREFIX_PATH (catkin's), then the
  parents of the share directories on ROS_PACKAGE_PATH (rospkg's); the
  message packages' definitions under ``<prefix>/share/<pkg>/msg`` and
  ``srv``; gencpp's and genpy's scripts under ``<prefix>/lib/<generator>``
  and gencpp's templates under ``<prefix>/share/gencpp``.
- ROS 2: the prefixes on AMENT_PREFIX_PATH.

Where a variable is not set, Debian 12's layout is the default: its ROS 1
and ROS 2's build side are installed under /usr and need no sourcing.

The ROS 2 nodes (rclpy) of the main job, the mros2 tests and the benches run
in a venv of ROS 2 wheels that scripts/setup.sh --tests makes: Kilted's,
build/ros2-wheels, unless GENMROS_ROS2_WHEELS names another (Jazzy's,
build/ros2-wheels-jazzy).
"""

import functools
import glob
import os

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
# Where Debian 12 installs ROS, with nothing sourced.
DEBIAN_PREFIX = '/usr'
# The venvs of ROS 2 wheels scripts/setup.sh --tests makes, and the variable that
# chooses one for the ROS 2 nodes.
KILTED_WHEELS = os.path.join(REPO, 'build', 'ros2-wheels')
JAZZY_WHEELS = os.path.join(REPO, 'build', 'ros2-wheels-jazzy')
ROS2_WHEELS_VARIABLE = 'GENMROS_ROS2_WHEELS'


def _variable_paths(name):
    return [path.rstrip('/') or '/' for path in os.environ.get(name, '').split(os.pathsep)
            if path]


def _unique(paths):
    return list(dict.fromkeys(paths))


def ros1_prefixes():
    """The installed ROS 1 prefixes, first wins (see the module)."""
    prefixes = [p for p in _variable_paths('CMAKE_PREFIX_PATH')
                if os.path.isdir(os.path.join(p, 'share'))]
    prefixes += [os.path.dirname(p) for p in _variable_paths('ROS_PACKAGE_PATH')
                 if os.path.basename(p) == 'share']
    return _unique(prefixes) or [DEBIAN_PREFIX]


def ros2_prefixes():
    """The installed ROS 2 prefixes (AMENT_PREFIX_PATH), first wins."""
    return _variable_paths('AMENT_PREFIX_PATH') or [DEBIAN_PREFIX]


def ros2_wheels():
    """The venv of ROS 2 wheels the ROS 2 nodes run in (see the module)."""
    return os.path.abspath(os.environ.get(ROS2_WHEELS_VARIABLE) or KILTED_WHEELS)


def prefix_arguments(prefixes):
    """genmros' --prefix arguments for prefixes."""
    return [argument for prefix in prefixes for argument in ('--prefix', prefix)]


def _first(prefixes, *relative):
    """The first prefixes/relative that exists, else the first prefix's."""
    paths = [os.path.join(prefix, *relative) for prefix in prefixes]
    return next((path for path in paths if os.path.exists(path)), paths[0])


def ros1_package_dir(package, kind='msg'):
    """The kind (msg or srv) directory of an installed ROS 1 package."""
    return _first(ros1_prefixes(), 'share', package, kind)


def ros2_package_dir(package, kind='msg'):
    """The kind (msg or srv) directory of an installed ROS 2 package."""
    return _first(ros2_prefixes(), 'share', package, kind)


def ros2_include_prefix(directory):
    """The first ROS 2 prefix whose include/ holds directory (Fast DDS'
    fastdds: Debian's libfastrtps-dev in /usr, a distribution's in its
    prefix), else None."""
    return next((prefix for prefix in ros2_prefixes() + [DEBIAN_PREFIX]
                 if os.path.isdir(os.path.join(prefix, 'include', directory))), None)


def ros1_definitions(package, kind='msg'):
    """The sorted paths of an installed ROS 1 package's .msg (kind msg) or
    .srv (kind srv) files."""
    return sorted(glob.glob(os.path.join(ros1_package_dir(package, kind), '*.' + kind)))


@functools.lru_cache(maxsize=None)
def _ros1_message_dirs(prefixes):
    found = {}
    for prefix in prefixes:
        share = os.path.join(prefix, 'share')
        for package in sorted(os.listdir(share)) if os.path.isdir(share) else ():
            msg_dir = os.path.join(share, package, 'msg')
            if os.path.isdir(msg_dir):
                found.setdefault(package, [msg_dir])
    return found


def ros1_search_path():
    """genmsg's search path of the installed ROS 1 message packages:
    {package: [its msg directory]}, a new dict each call."""
    return {package: list(dirs)
            for package, dirs in _ros1_message_dirs(tuple(ros1_prefixes())).items()}


def gencpp():
    """(gencpp's gen_cpp.py, its template directory)."""
    prefixes = ros1_prefixes()
    return (_first(prefixes, 'lib', 'gencpp', 'gen_cpp.py'), _first(prefixes, 'share', 'gencpp'))


def genpy():
    """(genpy's genmsg_py.py, gensrv_py.py)."""
    prefixes = ros1_prefixes()
    return (_first(prefixes, 'lib', 'genpy', 'genmsg_py.py'),
            _first(prefixes, 'lib', 'genpy', 'gensrv_py.py'))
