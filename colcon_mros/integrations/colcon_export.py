"""What ``colcon build --mros-export DIR`` exports after the build.

DIR becomes an export dir (:mod:`colcon_mros.export.export_dir`) holding every
message and service of the built packages and of the installed packages they
depend on (std_msgs from Debian included): the headers ``genmros export
--only headers`` writes, and the definitions they come from. A second run
rewrites only what changed and removes what no longer exists; a build of some
packages (``--packages-select``) adds to the export, never shrinks it. A build
that changed no definition the export comes from (and no package's list of
definitions, and not genmros) leaves the export as it is without reading a
definition: the export dir keeps a record of the last export's inputs.
"""

import json
import os

from colcon_core.package_selection import get_packages

from colcon_mros.errors import GenmrosError
from colcon_mros.export.export_dir import ExportDir
from colcon_mros.integrations.installed_files import CMAKE_MODULE, installed_file
from colcon_mros.generator.ros_environment import require_ros_python


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
    from colcon_mros.export.firmware_export import ExportRequest, export  # needs genmsg
    from colcon_mros.generator.render import Renderer  # needs empy
    from colcon_mros.generator.workspace import environment_packages, workspace_packages
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
    record = {'genmros': Renderer().fingerprint((workspace, sorted(names))),
              'definitions': _times(_definition_files(packages[name] for name in names))}
    if os.path.isdir(target.include_dir) and _unchanged_since(target.colcon_record(), record):
        print('genmros: the export in %s is up to date' % export_dir)
        return
    result = export(ExportRequest(output_dir=target.include_dir, workspaces=[workspace],
                                  package_names=sorted(names), only='headers'))
    exported = {message.package for message in result.messages}
    exported.update(service.package for service in result.services)
    target.replace_packages({name: packages[name] for name in exported}, installed_file(CMAKE_MODULE))
    # Also the definitions of types contained from packages not named; the
    # named packages' files keep the times they had before the export read them.
    sources = {os.path.abspath(model.source) for model in result.messages + result.services}
    record['definitions'].update(_times(sources - set(record['definitions'])))
    target.record_colcon_export(json.dumps(record, indent=0, sort_keys=True))


def _definition_files(packages):
    return [path for package in packages
            for path in package.message_files() + package.service_files()]


def _times(paths):
    """{path: [modification time in ns, size]}; a missing file is [0, -1]."""
    times = {}
    for path in paths:
        try:
            status = os.stat(path)
            times[os.path.abspath(path)] = [status.st_mtime_ns, status.st_size]
        except FileNotFoundError:
            times[os.path.abspath(path)] = [0, -1]
    return times


def _unchanged_since(recorded, record):
    """Whether record (this build's genmros and definitions) adds nothing to
    recorded (the last export's, as text): the same genmros, the same
    definition files unchanged, and each file recorded unchanged too."""
    try:
        last = json.loads(recorded)
        if last['genmros'] != record['genmros']:
            return False
    except (TypeError, ValueError, KeyError):  # no record, or not one of ours
        return False
    paths = set(last['definitions'])
    if not set(record['definitions']) <= paths:
        return False
    return _times(paths) == last['definitions']
