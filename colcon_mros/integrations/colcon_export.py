# SPDX-License-Identifier: BSD-3-Clause
"""What ``colcon build --mros-export DIR`` exports after the build.

For the ROS 2 (ament) packages it built, DIR gets its mros2 half
(:mod:`colcon_mros.export.mros2_export_dir`). For the catkin packages,
DIR becomes an export dir (:mod:`colcon_mros.export.export_dir`) holding every
message and service of the built packages and of the installed packages they
depend on (std_msgs from Debian included): the headers ``genmros export
--only headers`` writes, and the definitions they come from. A second run
rewrites only what changed and removes what no longer exists; a build of some
packages (``--packages-select``) adds to the export, never shrinks it. A build
that changed no definition the export comes from (and no package's list of
definitions, and not genmros) leaves the export as it is without reading a
definition: the export dir keeps the run record of the last export
(:mod:`colcon_mros.export.run_record`).
"""

import os
import time

from colcon_core.package_selection import get_packages

from colcon_mros.errors import GenmrosError
from colcon_mros.export.export_dir import ExportDir
from colcon_mros.export.run_record import RunRecord, definition_directories, snapshot
from colcon_mros.integrations.installed_files import CMAKE_MODULE, installed_file
from colcon_mros.ros1.environment import require_ros_python


# colcon's package types of the two stacks (colcon-ros).
ROS2_PACKAGE_TYPES = ('ros.ament_cmake',)
ROS1_PACKAGE_TYPES = ('ros.catkin',)


def _ros2_interface_packages(descriptors):
    """The names of the built ROS 2 packages that define interfaces."""
    from colcon_mros.ros2.interfaces import Package
    return sorted(d.name for d in descriptors if d.type in ROS2_PACKAGE_TYPES
                  and Package(d.name, str(d.path)).interfaces)


def _export_ros2(args, workspace, names, export_dir):
    """The mros2 half (:mod:`colcon_mros.export.mros2_export_dir`): the built
    ROS 2 packages' interfaces and every type they contain, from the
    sourced ROS 2 environment and this build's install base."""
    from colcon_mros.export.mros2_export_dir import export_ros2_packages
    from colcon_mros.ros2.environment import require_rosidl
    from colcon_mros.ros2.interfaces import ament_prefixes
    require_rosidl()
    install_base = os.path.abspath(args.install_base)
    prefixes = [install_base] + [os.path.join(install_base, name) for name in names
                                 if os.path.isdir(os.path.join(install_base, name))]
    result = export_ros2_packages(export_dir, workspace, names, prefixes + ament_prefixes())
    print('genmros: mros2 headers of %d message types and %d services in %s'
          % (len(result.messages), len(result.services), os.path.join(export_dir, 'mros2')))


def export_built_packages(args, export_dir):
    """Export the packages colcon built (as selected by args) to export_dir.

    The built packages' types come from their sources, as catkin generates
    them (an install space keeps the files of a deleted .msg); their
    dependencies from the ROS environment.
    """
    if len(args.base_paths) != 1:
        raise GenmrosError('--mros-export needs the packages under one base path, not %s'
                           % ' '.join(args.base_paths), export_dir)
    workspace = os.path.abspath(args.base_paths[0])
    selected = [d.descriptor for d in get_packages(args, recursive_categories=('run',))
                if d.selected]
    ros2_names = _ros2_interface_packages(selected)
    if ros2_names:
        _export_ros2(args, workspace, ros2_names, export_dir)
        if not any(d.type in ROS1_PACKAGE_TYPES for d in selected):
            return
    require_ros_python()
    from colcon_mros.export.firmware_export import ExportRequest, export  # needs genmsg
    from colcon_mros.mros_v1.render import Renderer  # needs empy
    from colcon_mros.ros1.workspace import environment_packages, workspace_packages
    packages = environment_packages()
    packages.update(workspace_packages(workspace))

    names = set()
    for descriptor in selected:
        if descriptor.name in packages:
            names.add(descriptor.name)
            names.update(str(dependency) for dependency in descriptor.get_dependencies()
                         if dependency in packages)
    if not names:
        raise GenmrosError('the built packages define no messages or services; nothing to '
                           'export', export_dir)

    target = ExportDir(export_dir)
    run = Renderer().fingerprint((workspace, sorted(names)))
    last = RunRecord.read(target.colcon_record)
    if last and last.is_current(run):
        print('genmros: the export in %s is up to date' % export_dir)
        return
    started_ns = time.time_ns()
    # Every definition of the named packages, and their directories: a file
    # added to a package counts as a change too.
    named = [path for name in names for path in packages[name].message_files() +
             packages[name].service_files()]
    result = export(ExportRequest(output_dir=target.include_dir, workspaces=[workspace],
                                  package_names=sorted(names), only='headers'))
    exported = {message.package for message in result.messages}
    exported.update(service.package for service in result.services)
    target.replace_packages({name: packages[name] for name in exported}, installed_file(CMAKE_MODULE))
    # Also the definitions of types contained from packages not named.
    sources = {model.source for model in result.messages + result.services} | set(named)
    RunRecord(run, snapshot(sorted(sources) + definition_directories(named), started_ns),
              [target.include_dir, target.cmake_file]).write(target.colcon_record)

