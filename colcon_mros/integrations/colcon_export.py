# SPDX-License-Identifier: BSD-3-Clause
"""What ``colcon build --mros-export DIR`` exports after the build.

For the ROS 2 (ament) packages it built, DIR gets its mros2 half
(:mod:`colcon_mros.export.mros2_export_dir`), made from their sources, not
from the headers rosidl_generator_mros2 installed; a package the generator
did not run for (its last install has no marker of it) is named in one line
with the fix, and exported all the same. For the catkin packages,
DIR becomes an export dir (:mod:`colcon_mros.export.export_dir`) holding every
message and service of the built packages and of the installed packages they
depend on (std_msgs from Debian included): the headers ``genmros mros-v1-export
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
from colcon_mros.integrations.installed_files import (CMAKE_MODULE, install_prefix,
                                                      installed_file)
from colcon_mros.ros1.environment import require_ros_python


# colcon's package types of the two stacks (colcon-ros).
ROS2_PACKAGE_TYPES = ('ros.ament_cmake',)
ROS1_PACKAGE_TYPES = ('ros.catkin',)


def _ros2_interface_packages(descriptors):
    """The descriptors of the built ROS 2 packages that define interfaces, by name."""
    from colcon_mros.ros2.interfaces import Package
    return sorted((d for d in descriptors if d.type in ROS2_PACKAGE_TYPES
                   and Package(d.name, str(d.path)).interfaces), key=lambda d: d.name)


# Below an install prefix, the ament index resource rosidl_generate_interfaces()
# installs for every interface package: rosidl ran for it.
ROSIDL_INTERFACES_RESOURCE = 'rosidl_interfaces'
# The generator's CMake package below its prefix.
GENERATOR_CONFIG = ('share', 'rosidl_generator_mros2', 'cmake',
                    'rosidl_generator_mros2Config.cmake')
# What _generator_state() finds of a package's last install.
WITH_GENERATOR, WITHOUT_GENERATOR, OLD_LAYOUT, NO_ROSIDL = (
    'with', 'without', 'old layout', 'no rosidl')


def _resource(kind, package):
    return os.path.join('share', 'ament_index', 'resource_index', kind, package)


def _generator_state(package, build_base, prefixes):
    """What installed the package's interfaces: WITH_GENERATOR (the mros2
    generator's marker), OLD_LAYOUT (the shared include/mros2/<pkg> of an
    earlier colcon-mros), WITHOUT_GENERATOR (rosidl's marker alone) or
    NO_ROSIDL. Read from the package's last install, the install_manifest.txt
    CMake rewrites on every install (a merged install keeps the files of
    earlier ones), else from the files in prefixes."""
    from colcon_mros.integrations.rosidl_generator import MARKER_RESOURCE, OLD_INCLUDE_ROOT
    ours = _resource(MARKER_RESOURCE, package)
    rosidls = _resource(ROSIDL_INTERFACES_RESOURCE, package)
    old = os.path.join(*OLD_INCLUDE_ROOT + (package,))
    manifest = os.path.join(build_base, package, 'install_manifest.txt')
    if os.path.isfile(manifest):
        with open(manifest, encoding='utf-8') as stream:
            installed = stream.read().splitlines()

        def has(relative, directory=False):
            ending = os.sep + relative
            if directory:
                return any(ending + os.sep in path for path in installed)
            return any(path.endswith(ending) for path in installed)
    else:
        def has(relative, directory=False):
            check = os.path.isdir if directory else os.path.isfile
            return any(check(os.path.join(prefix, relative)) for prefix in prefixes)
    if has(ours):
        return WITH_GENERATOR
    if has(old, directory=True):
        return OLD_LAYOUT
    if has(rosidls):
        return WITHOUT_GENERATOR
    return NO_ROSIDL


def _generator_prefix():
    """The install prefix of this colcon-mros' rosidl generator, or None
    (a source checkout)."""
    prefix = install_prefix()
    return prefix if os.path.isfile(os.path.join(prefix, *GENERATOR_CONFIG)) else None


def generator_notices(descriptors, build_base, install_base):
    """One line per built interface package whose install lacks the mros2
    generator's headers, saying why and what to do."""
    notices = []
    prefix = _generator_prefix()
    where = prefix or "the generator's install prefix"
    for descriptor in descriptors:
        name = descriptor.name
        prefixes = [install_base, os.path.join(install_base, name)]
        state = _generator_state(name, build_base, prefixes)
        cmake_lists = os.path.join(os.path.abspath(str(descriptor.path)), 'CMakeLists.txt')
        if state == WITHOUT_GENERATOR:
            notices.append(
                'genmros: warning: %s was built without the mros2 generator (its install has '
                'no mros2 headers; they are exported all the same): add '
                'find_package(rosidl_generator_mros2 REQUIRED) before '
                'rosidl_generate_interfaces() in %s, or put %s on AMENT_PREFIX_PATH'
                % (name, cmake_lists, where))
        elif state == OLD_LAYOUT:
            notices.append(
                'genmros: warning: %s was installed by an earlier colcon-mros (its mros2 '
                'headers in the shared include/mros2/, which nothing reads any more): rebuild it'
                % name)
    return notices


def _export_ros2(args, workspace, descriptors, export_dir):
    """The mros2 half (:mod:`colcon_mros.export.mros2_export_dir`): the built
    ROS 2 packages' interfaces and every type they contain, from the
    sourced ROS 2 environment and this build's install base; then a line
    per package the mros2 generator did not run for."""
    from colcon_mros.export.mros2_export_dir import export_ros2_packages
    from colcon_mros.ros2.environment import require_rosidl
    from colcon_mros.ros2.interfaces import ament_prefixes
    require_rosidl()
    names = [d.name for d in descriptors]
    install_base = os.path.abspath(args.install_base)
    prefixes = [install_base] + [os.path.join(install_base, name) for name in names
                                 if os.path.isdir(os.path.join(install_base, name))]
    result = export_ros2_packages(export_dir, workspace, names, prefixes + ament_prefixes())
    print('genmros: mros2 headers of %d message types and %d services in %s'
          % (len(result.messages), len(result.services), os.path.join(export_dir, 'mros2')))
    for notice in generator_notices(descriptors, os.path.abspath(args.build_base), install_base):
        print(notice)


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
    ros2_packages = _ros2_interface_packages(selected)
    if ros2_packages:
        _export_ros2(args, workspace, ros2_packages, export_dir)
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
    target.replace_packages({name: packages[name] for name in exported},
                            installed_file(CMAKE_MODULE))
    # Also the definitions of types contained from packages not named.
    sources = {model.source for model in result.messages + result.services} | set(named)
    RunRecord(run, snapshot(sorted(sources) + definition_directories(named), started_ns),
              [target.include_dir, target.cmake_file]).write(target.colcon_record)
