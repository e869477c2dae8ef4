"""What ``colcon build --mros-export DIR`` exports after the build.

DIR becomes an export dir (:mod:`colcon_mros.export_dir`) holding every
message and service of the built packages and of the installed packages they
depend on (std_msgs from Debian included): the headers ``genmros export
--only headers`` writes, and the definitions they come from. A second run
rewrites only what changed and removes what no longer exists; a build of some
packages (``--packages-select``) adds to the export, never shrinks it.
"""

import os

from colcon_core.package_selection import get_packages

from colcon_mros.errors import GenmrosError
from colcon_mros.export_dir import ExportDir
from colcon_mros.installed_files import CMAKE_MODULE, installed_file
from colcon_mros.ros_environment import require_ros_python


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
    require_ros_python()
    from colcon_mros.export import ExportRequest, export  # needs genmsg
    from colcon_mros.workspace import environment_packages, workspace_packages
    packages = environment_packages()
    packages.update(workspace_packages(workspace))

    names = set()
    for decorator in get_packages(args, recursive_categories=('run',)):
        if decorator.selected and decorator.descriptor.name in packages:
            names.add(decorator.descriptor.name)
            names.update(str(dependency) for dependency in decorator.descriptor.get_dependencies()
                         if dependency in packages)
    if not names:
        raise GenmrosError('the built packages define no messages or services; nothing to '
                           'export', export_dir)

    target = ExportDir(export_dir)
    result = export(ExportRequest(target.include_dir, workspaces=[workspace],
                                  package_names=sorted(names), only='headers'))
    exported = {message.package for message in result.messages}
    exported.update(service.package for service in result.services)
    target.replace_packages({name: packages[name] for name in exported}, installed_file(CMAKE_MODULE))
