# SPDX-License-Identifier: BSD-3-Clause
"""Find ROS packages and the directories that hold their .msg and .srv files.

Three places hold packages: a workspace's source tree (found with catkin_pkg,
as catkin and colcon find it), installed prefixes given by the user
(``<prefix>/share/<pkg>``, install and devel spaces), and the ROS
environment: what rospkg finds on ROS_PACKAGE_PATH (where nothing is
sourced, the distribution's default: Debian's /usr/share), then the spaces
on CMAKE_PREFIX_PATH. A workspace package hides an installed one of the
same name.
"""

import os
import re

from colcon_mros.errors import GenmrosError
from colcon_mros.ros1.definition import Definition


class Package:
    """A package's name and its msg/ and srv/ directories."""

    def __init__(self, name, msg_dirs, srv_dirs):
        self.name = name
        self.msg_dirs = [d for d in msg_dirs if os.path.isdir(d)]
        self.srv_dirs = [d for d in srv_dirs if os.path.isdir(d)]

    def message_files(self):
        return _files(self.msg_dirs, '.msg')

    def service_files(self):
        return _files(self.srv_dirs, '.srv')

    def definitions(self):
        """The package's .msg and .srv files, as :class:`Definition` values."""
        return [Definition(self.name, path)
                for path in self.message_files() + self.service_files()]

    def type_names(self):
        """Names of every type the package defines, services' halves included."""
        return {name for definition in self.definitions() for name in definition.type_names}


def _files(directories, extension):
    found = {}
    for directory in directories:
        for name in sorted(os.listdir(directory)):
            if name.endswith(extension) and name not in found:
                found[name] = os.path.join(directory, name)
    return [found[name] for name in sorted(found)]


def _package(name, root):
    return Package(name, [os.path.join(root, 'msg')], [os.path.join(root, 'srv')])


def environment_packages():
    """{name: Package} for the packages of the ROS environment: rospkg's
    (ROS_PACKAGE_PATH, as rospack sees it), then the install and devel
    spaces on CMAKE_PREFIX_PATH that rospkg does not see."""
    import rospkg  # a ROS dependency, checked by ros_environment

    ros_packages = rospkg.RosPack(rospkg.get_ros_paths())
    packages = {}
    for name in sorted(ros_packages.list()):
        package = _package(name, ros_packages.get_path(name))
        if package.msg_dirs or package.srv_dirs:
            packages[name] = package
    prefixes = [p for p in os.environ.get('CMAKE_PREFIX_PATH', '').split(os.pathsep) if p]
    for name, package in installed_packages(prefixes).items():
        packages.setdefault(name, package)
    return packages


def workspace_packages(workspace):
    """{name: Package} for the packages in a workspace's source tree."""
    # Imported here: catkin_pkg takes most of genmros' start-up time, and
    # generator mode, which catkin runs once per .msg file, never needs it.
    from catkin_pkg.packages import find_packages

    source = os.path.join(workspace, 'src')
    if not os.path.isdir(source):
        source = workspace
    if not os.path.isdir(source):
        raise GenmrosError('workspace not found', workspace)
    try:
        found = find_packages(source)
    except Exception as error:  # catkin_pkg raises plain exceptions for bad manifests
        raise GenmrosError('cannot read packages: %s' % error, source)
    packages = {}
    for relative, manifest in found.items():
        root = os.path.join(source, relative)
        packages[manifest.name] = _package(manifest.name, root)
    return packages


_MSG_INCLUDE_DIRS = re.compile(r'set\(\w+_MSG_INCLUDE_DIRS\s+"([^"]*)"\)')


def _devel_space_msg_dirs(share):
    """The msg directories a catkin devel space's <pkg>-msg-paths.cmake names
    (a devel space keeps no package.xml or .msg files, only this pointer to
    the sources), or [] for an install space."""
    name = os.path.basename(share)
    paths_file = os.path.join(share, 'cmake', '%s-msg-paths.cmake' % name)
    if not os.path.isfile(paths_file):
        return []
    with open(paths_file) as stream:
        return [d for match in _MSG_INCLUDE_DIRS.finditer(stream.read())
                for d in match.group(1).split(';') if d]


def installed_packages(prefixes):
    """{name: Package} for the packages under <prefix>/share (install spaces,
    Debian's /usr, catkin devel spaces); earlier prefixes win."""
    packages = {}
    for prefix in prefixes:
        share = os.path.join(prefix, 'share')
        if not os.path.isdir(share):
            continue
        for name in sorted(os.listdir(share)):
            root = os.path.join(share, name)
            devel_msg_dirs = _devel_space_msg_dirs(root)
            has_manifest = os.path.isfile(os.path.join(root, 'package.xml'))
            if name in packages or not (devel_msg_dirs or has_manifest):
                continue
            # A devel space's srv/ sits beside the msg/ its sources have.
            msg_dirs = list(dict.fromkeys([os.path.join(root, 'msg')] + devel_msg_dirs))
            srv_dirs = [os.path.join(root, 'srv')] + [os.path.join(os.path.dirname(d), 'srv')
                                                      for d in devel_msg_dirs]
            package = Package(name, msg_dirs, list(dict.fromkeys(srv_dirs)))
            if package.msg_dirs or package.srv_dirs:
                packages[name] = package
    return packages


def split_msg_paths(paths):
    """(installed prefixes, source trees) of paths: a directory with share/
    is an installed prefix (an install or devel space, an export dir), any
    other a source tree searched for package.xml (the old --msg-path, the
    mROS v1 PC target's and fit check's package paths). The CMake module's
    PACKAGE_PATHS and the make fragment's MROS_MSG_PATHS follow the same
    rule to pass each path as --prefix or --workspace."""
    for path in paths:
        if not os.path.isdir(path):
            raise GenmrosError('not a directory: a package path is a source tree of packages or '
                               'an installed prefix (with share/<pkg>/msg)', path)
    prefixes = [path for path in paths if os.path.isdir(os.path.join(path, 'share'))]
    return prefixes, [path for path in paths if path not in prefixes]


def msg_search_path(packages):
    """genmsg's search path, {package: [msg directories]}."""
    return {name: package.msg_dirs for name, package in packages.items() if package.msg_dirs}


def parse_include_flags(flags):
    """genmsg's ``-I pkg:dir`` flags as {package: [dirs]}."""
    search_path = {}
    for flag in flags:
        package, separator, directory = flag.partition(':')
        if not separator or not package or not directory:
            raise GenmrosError("bad include path '%s' (expected PACKAGE:DIRECTORY)" % flag)
        search_path.setdefault(package, []).append(directory)
    return search_path
