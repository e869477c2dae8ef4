"""``colcon build --mros-export DIR``: the mROS headers of the built workspace.

Implements colcon-core's ``colcon_core.argument_parser`` extension point
(``ArgumentParserDecoratorExtensionPoint``), registered in setup.cfg. It is
the extension point that sees both a verb's parser and the ``main`` the verb
runs: the decorator adds ``--mros-export`` to the ``build`` verb alone and,
when the flag is given, exports after a successful build, so a failed export
fails ``colcon build`` (colcon prints the one-line error, exit code 1).
Without the flag, colcon runs exactly as before.

DIR receives, for every message and service of the built packages and of the
installed packages they depend on (std_msgs from Debian included)::

    DIR/include/mros_message_support.h, DIR/include/<pkg>/<Type>.h
    DIR/share/<pkg>/package.xml, msg/*.msg, srv/*.srv   read by mros_import_messages()
    DIR/mros_export.cmake                                include() it from a firmware
    DIR/COLCON_IGNORE                                    so no tool takes DIR/share for packages

The headers are those ``genmros export --only headers`` writes; a second run
rewrites only what changed and removes what no longer exists.
"""

import os

from colcon_core.argument_parser import ArgumentParserDecorator
from colcon_core.argument_parser import ArgumentParserDecoratorExtensionPoint
from colcon_core.package_selection import get_packages
from colcon_core.plugin_system import satisfies_version

from colcon_mros.errors import GenmrosError
from colcon_mros.installed_files import CMAKE_MODULE, installed_file
from colcon_mros.output import check_writable, write_files
from colcon_mros.ros_environment import require_ros_python
from colcon_mros.workspace import environment_packages, workspace_packages

CMAKE_FILE = 'mros_export.cmake'
IGNORE_MARKER = 'COLCON_IGNORE'
DEFINITION_KINDS = ('msg', 'srv')


class MrosExportArgumentParserDecorator(ArgumentParserDecoratorExtensionPoint):
    """Adds --mros-export DIR to colcon build."""

    def __init__(self):  # noqa: D107
        super().__init__()
        satisfies_version(ArgumentParserDecoratorExtensionPoint.EXTENSION_POINT_VERSION, '^1.0')

    def decorate_argument_parser(self, *, parser):  # noqa: D102
        return _BuildVerbDecorator(parser)


class _BuildVerbDecorator(ArgumentParserDecorator):
    """Catches the build verb's parser when colcon sets the verb's main on it."""

    def set_defaults(self, **kwargs):  # noqa: D102
        extension = kwargs.get('verb_extension')
        if getattr(extension, 'VERB_NAME', None) == 'build':
            self._parser.add_argument(
                '--mros-export', metavar='DIR',
                help='After the build, write the mROS headers (genmros) of every message '
                     'and service of the built packages and their dependencies to '
                     'DIR/include, and DIR/%s for a firmware build' % CMAKE_FILE)
            kwargs['main'] = _exporting(kwargs['main'])
        return self._parser.set_defaults(**kwargs)


def _exporting(build_main):
    """The build verb's main, checking DIR before and exporting after the build."""
    def main(*, context):
        export_dir = context.args.mros_export
        if export_dir:
            _fail_as_colcon_error(check_writable, os.path.abspath(export_dir))
        rc = build_main(context=context)
        if rc or not export_dir:
            return rc
        _fail_as_colcon_error(export_workspace, context.args, os.path.abspath(export_dir))
        return 0
    return main


def _fail_as_colcon_error(function, *arguments):
    # colcon reports a RuntimeError from a verb as one line and exits with 1.
    try:
        function(*arguments)
    except GenmrosError as error:
        raise RuntimeError('genmros: error: %s' % error)


def export_workspace(args, export_dir):
    """Export the packages colcon built (as selected by args) to export_dir.

    The built packages' types come from their sources, as catkin generates
    them (an install space keeps the files of a deleted .msg); their
    dependencies from the installed prefixes.
    """
    if len(args.base_paths) != 1:
        raise GenmrosError('--mros-export needs the packages under one base path, not %s'
                           % ' '.join(args.base_paths), export_dir)
    workspace = os.path.abspath(args.base_paths[0])
    require_ros_python()
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

    from colcon_mros.export import export  # needs genmsg: imported when the flag is used
    result = export(os.path.join(export_dir, 'include'), None, [workspace],
                    package_names=sorted(names), only='headers')
    exported = {message.package for message in result.messages}
    exported.update(service.package for service in result.services)
    for name in sorted(exported):
        _export_definitions(packages[name], os.path.join(export_dir, 'share', name))
    # Every type the export dir holds, not only this run's: a build of some
    # packages (--packages-select) adds to an export, never shrinks it.
    types = _exported_types(os.path.join(export_dir, 'share'))
    # COLCON_IGNORE: DIR/share/<pkg>/package.xml must not look like a second
    # copy of each package to colcon or catkin when DIR is in the workspace.
    write_files(export_dir, {CMAKE_FILE: _cmake_file(types), IGNORE_MARKER: ''})


def _export_definitions(package, share_dir):
    """Copy package.xml and the .msg/.srv files of package; drop removed ones."""
    files = {}
    for kind, paths in (('msg', package.message_files()), ('srv', package.service_files())):
        for path in paths:
            files[os.path.join(kind, os.path.basename(path))] = _read(path)
    # msg/ and srv/ sit beside package.xml in every installed prefix.
    manifest = os.path.join(os.path.dirname((package.msg_dirs + package.srv_dirs)[0]),
                            'package.xml')
    files['package.xml'] = _read(manifest)
    write_files(share_dir, files)
    for kind in DEFINITION_KINDS:
        directory = os.path.join(share_dir, kind)
        for name in os.listdir(directory) if os.path.isdir(directory) else ():
            if name.endswith('.' + kind) and os.path.join(kind, name) not in files:
                os.unlink(os.path.join(directory, name))


def _exported_types(share_dir):
    """pkg/Type of every definition under share_dir, services' halves included."""
    messages, services = set(), set()
    for package in sorted(os.listdir(share_dir)) if os.path.isdir(share_dir) else ():
        for kind, names in (('msg', messages), ('srv', services)):
            directory = os.path.join(share_dir, package, kind)
            for name in os.listdir(directory) if os.path.isdir(directory) else ():
                if name.endswith('.' + kind):
                    names.add('%s/%s' % (package, name[:-len(kind) - 1]))
    for service in services:
        messages.update((service + 'Request', service + 'Response'))
    return sorted(messages) + sorted(services)


def _read(path):
    try:
        with open(path, encoding='utf-8') as stream:
            return stream.read()
    except (OSError, UnicodeDecodeError) as error:
        raise GenmrosError('cannot read file: %s' % getattr(error, 'strerror', error), path)


def _cmake_file(types):
    return '''\
# Generated by genmros (colcon build --mros-export); do not edit.
# The mROS headers of a ROS workspace, for a firmware's CMakeLists.txt:
#   include(<this file>)
#   mros_import_messages(TARGET <firmware> EXPORT_DIR ${MROS_EXPORT_DIR}
#                        TYPES <the pkg/Type the firmware uses>)
set(MROS_EXPORT_DIR "${CMAKE_CURRENT_LIST_DIR}")
set(MROS_EXPORT_INCLUDE_DIR "${CMAKE_CURRENT_LIST_DIR}/include")
set(MROS_EXPORT_TYPES
%s)
if(NOT COMMAND mros_import_messages)
  include("%s")
endif()
''' % (''.join('  %s\n' % name for name in types), installed_file(CMAKE_MODULE))
