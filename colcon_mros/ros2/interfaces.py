# SPDX-License-Identifier: BSD-3-Clause
"""Find ROS 2 packages and their interface files.

Two places hold them, as a ROS 2 build sees them: a workspace's source tree
(each directory with a package.xml; ``msg/``, ``srv/`` beside it) and the
installed prefixes (``<prefix>/share/<pkg>/msg`` and ``srv``, where
rosidl_generate_interfaces installs the files and their ``.idl`` forms),
from AMENT_PREFIX_PATH where nothing is named. A workspace package hides an
installed one of the same name; a ``.msg`` or ``.srv`` hides the ``.idl``
rosidl made from it.
"""

import os

from colcon_mros.errors import GenmrosError, close_match

INTERFACE_KINDS = ('msg', 'srv')
AMENT_PACKAGE_INDEX = ('ament_index', 'resource_index', 'packages')
# Directories a workspace search does not enter: build output and VCS.
_SKIPPED_DIRS = {'build', 'install', 'log', '.git'}


class Interface:
    """One interface file: package, kind (msg or srv), type name and path."""

    def __init__(self, package, kind, name, path):
        self.package = package
        self.kind = kind
        self.name = name
        self.path = path


class Package:
    """A ROS 2 package's interface files, by type name: those in root's
    msg/ and srv/, or, where interfaces is given ({(kind, name): Interface}),
    exactly those (root None: the package has no directory to read)."""

    def __init__(self, name, root, interfaces=None):
        self.name = name
        self.root = root
        self.interfaces = {} if interfaces is None else dict(interfaces)
        for kind in INTERFACE_KINDS if interfaces is None else ():
            directory = os.path.join(root, kind)
            if not os.path.isdir(directory):
                continue
            for file_name in sorted(os.listdir(directory)):
                stem, extension = os.path.splitext(file_name)
                interface = Interface(name, kind, stem, os.path.join(directory, file_name))
                if extension == '.' + kind:
                    self.interfaces[(kind, stem)] = interface
                elif extension == '.idl':
                    # Unless a .msg or .srv of which it is rosidl's form is beside it.
                    self.interfaces.setdefault((kind, stem), interface)

    def interface(self, kind, name):
        found = self.interfaces.get((kind, name))
        if found is None:
            names = [n for k, n in self.interfaces if k == kind]
            raise GenmrosError("package '%s' has no %s '%s'%s"
                               % (self.name, kind, name, close_match(name, names)))
        return found


def interface_of_file(package, path):
    """The Interface of a file at <anything>/<kind>/<Type>.<extension>."""
    kind = os.path.basename(os.path.dirname(path))
    return Interface(package, kind, os.path.splitext(os.path.basename(path))[0], path)


def _package_name(package_xml):
    from catkin_pkg.package import parse_package
    try:
        return parse_package(package_xml).name
    except Exception as error:  # catkin_pkg raises several types, all for a bad manifest
        raise GenmrosError('bad package manifest: %s' % str(error).splitlines()[0], package_xml)


def workspace_packages(workspace):
    """{name: Package} for the packages with interfaces under a workspace's
    source tree (``WS/src`` if there is one, else ``WS``)."""
    source = os.path.join(workspace, 'src')
    if not os.path.isdir(source):
        source = workspace
    if not os.path.isdir(source):
        raise GenmrosError('no such workspace directory', workspace)
    packages = {}
    for directory, subdirs, files in os.walk(source):
        subdirs[:] = sorted(d for d in subdirs if d not in _SKIPPED_DIRS
                            and not os.path.exists(os.path.join(directory, d, 'COLCON_IGNORE')))
        if 'package.xml' in files:
            subdirs[:] = []
            package = Package(_package_name(os.path.join(directory, 'package.xml')), directory)
            if package.interfaces:
                packages[package.name] = package
    return packages


def installed_packages(prefixes):
    """{name: Package} for the packages installed under prefixes (earlier
    prefixes win, as on AMENT_PREFIX_PATH)."""
    packages = {}
    for prefix in prefixes:
        share = os.path.join(prefix, 'share')
        index = os.path.join(share, *AMENT_PACKAGE_INDEX)
        if not os.path.isdir(index):
            continue
        for name in sorted(os.listdir(index)):
            if name in packages:
                continue
            package = Package(name, os.path.join(share, name))
            if package.interfaces:
                packages[name] = package
    return packages


# ROS 2's own interface packages, each also a wheel on PyPI (ros-<name>):
# an unknown one of these is an installation's to give; any other is the
# user's own, in a workspace.
ROS2_INTERFACE_PACKAGES = frozenset((
    'action_msgs', 'actionlib_msgs', 'builtin_interfaces', 'composition_interfaces',
    'diagnostic_msgs', 'example_interfaces', 'geometry_msgs', 'lifecycle_msgs', 'nav_msgs',
    'rcl_interfaces', 'rmw_dds_common', 'rosgraph_msgs', 'sensor_msgs', 'service_msgs',
    'shape_msgs', 'statistics_msgs', 'std_msgs', 'std_srvs', 'stereo_msgs', 'tf2_msgs',
    'trajectory_msgs', 'type_description_interfaces', 'unique_identifier_msgs',
    'visualization_msgs',
))


def where_packages_come_from(package):
    """Where a package that is not found comes from, for its line: one of
    ROS 2's from a sourced distribution or, where the OS has none (Debian
    12), from ROS 2's wheel of it in a venv (docs/mros2.md); any other from
    the user's workspace."""
    installed = ('AMENT_PREFIX_PATH or --prefix names the installed ones; where no ROS 2 '
                 'distribution is installed, as on Debian 12, a venv with the wheel %s holds it: '
                 '--prefix VENV, docs/mros2.md' % ('ros-' + package.replace('_', '-')))
    if package in ROS2_INTERFACE_PACKAGES:
        return installed
    return ('--workspace DIR names the workspace that holds a package of your own; '
            'AMENT_PREFIX_PATH or --prefix names the installed ones')


def ament_prefixes():
    """The prefixes of the sourced ROS 2 environment (AMENT_PREFIX_PATH)."""
    return [p for p in os.environ.get('AMENT_PREFIX_PATH', '').split(os.pathsep) if p]


def all_packages(workspaces=(), prefixes=None):
    """Workspace packages over the installed ones (AMENT_PREFIX_PATH's
    prefixes where prefixes is None)."""
    packages = installed_packages(ament_prefixes() if prefixes is None else prefixes)
    for workspace in workspaces:
        packages.update(workspace_packages(workspace))
    return packages
