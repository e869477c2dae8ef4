# SPDX-License-Identifier: BSD-3-Clause
"""rosidl_generator_mros2's entry point: what rosidl_generate_interfaces()
runs for the mros2 generator, as rosidl_generator_cpp runs generate_cpp.

rosidl_generator_mros2_generate_interfaces.cmake writes the arguments file
(``rosidl_write_generator_arguments()``): the package, its interfaces as
``idl_tuples`` (``<base>:<kind>/<Type>.idl``, rosidl_adapter's forms of its
``.msg`` and ``.srv`` files), the files the user wrote
(``ros_interface_files``: the target's sources), the ``.idl`` files of the
packages it depends on (``ros_interface_dependencies``: ``<pkg>:<path>``)
and the output directory. Exactly the listed interfaces get a header,
``<output_dir>/<pkg>/<kind>/<type>.hpp``, but for what mros2 cannot
carry, skipped with one line naming the type and the reason, so that
every interface package builds as it does with rosidl_generator_cpp: an
action (mros2 has none), a type of valid IDL mros2 cannot carry (a wchar,
a long double, an image too large:
:class:`~colcon_mros.ros2.model.UncarriableType`) and every type that
holds one. ``--header-list`` writes the headers it wrote, which the
CMake side installs as the package's ament index marker. genmros' own
errors name the ``.msg`` or ``.srv`` the user wrote, with its line. The
support headers they include are not written: the generator's install
holds them once
(``<prefix>/include/rosidl_generator_mros2``), and the CMake side installs
each package's headers under an include root of its own
(``<prefix>/include/<pkg>/mros2``, :data:`MROS2_INCLUDE_ROOT`).

With ``--dependency-file FILE --dependency-target OUTPUT`` it also writes
a make depfile (CMake's ``DEPFILE``): OUTPUT depends on the files the
headers are made from besides the interfaces (the modules it imported,
its templates and static headers), so that a new genmros regenerates them,
and no program runs at configure time to ask for that list.
"""

import argparse
import os
import sys

from colcon_mros.core import render as core_render
from colcon_mros.core.output import write_file, write_files
from colcon_mros.core.storage import HeapStorage
from colcon_mros.errors import GenmrosError
from colcon_mros.export.mros2_export import render_types
from colcon_mros.mros2 import render
from colcon_mros.mros2.cpp import header_path
from colcon_mros.ros2.environment import require_rosidl
from colcon_mros.ros2.interfaces import Package, interface_of_file
from colcon_mros.ros2.model import ModelBuilder, UncarriableType
from colcon_mros.ros2.rosidl import read_generator_arguments

PROGRAM = 'rosidl_generator_mros2'
# Below an install prefix, what rosidl_generator_mros2_generate_interfaces.cmake
# installs for a package ('%s': its name): its mros2 include root, and the
# ament index marker saying the generator ran for it.
MROS2_INCLUDE_ROOT = ('include', '%s', 'mros2')
MARKER_RESOURCE = 'rosidl_generator_mros2__packages'
# The include root an earlier colcon-mros shared between every package
# (include/mros2/<pkg>/...): what an install made then holds.
OLD_INCLUDE_ROOT = ('include', 'mros2')
# The generator's support headers, below its install prefix (setup.cfg).
SUPPORT_INCLUDE_DIR = ('include', PROGRAM)
GENERATED_KINDS = ('msg', 'srv')
# What rosidl_generate_interfaces() may pass that mros2 cannot carry.
SKIPPED_KINDS = {'action': 'mros2 has no actions'}


def _split_tuple(entry):
    """'<base>:<relative>' (or '<pkg>:<path>'), split at the last ':' as rosidl does."""
    first, _, second = entry.rpartition(':')
    return first, second


def _user_files(ros_interface_files):
    """{(kind, stem): path} of the .msg and .srv files the user wrote."""
    files = {}
    for path in ros_interface_files:
        stem, extension = os.path.splitext(os.path.basename(path))
        kind = os.path.basename(os.path.dirname(path))
        if extension == '.' + kind:
            files[(kind, stem)] = path
    return files


def _where_dependencies_come_from(package):
    """What rosidl passes of another package: the ones its call names."""
    return ('rosidl_generate_interfaces() passes only the packages it names: add %s to its '
            'DEPENDENCIES, with find_package(%s REQUIRED) before it' % (package, package))


def generate(arguments):
    """Write the headers of the interfaces an arguments file (as a dict)
    lists, but for the types mros2 cannot carry, and those that hold them;
    returns (the paths it changed, the headers relative to the output
    directory, the notices to print)."""
    name = arguments['package_name']
    user_files = _user_files(arguments.get('ros_interface_files', []))
    own, skipped = {}, []
    for entry in arguments.get('idl_tuples', []):
        base, relative = _split_tuple(entry)
        interface = interface_of_file(name, os.path.join(base, relative))
        if interface.kind in SKIPPED_KINDS:
            skipped.append(interface)
            continue
        if interface.kind not in GENERATED_KINDS:
            raise GenmrosError('an interface of kind %s, which mros2 does not know'
                               % interface.kind, interface.path)
        # genmros' errors name the file the user wrote, at its line.
        interface.path = user_files.get((interface.kind, interface.name), interface.path)
        own[(interface.kind, interface.name)] = interface
    dependencies = {}
    for entry in arguments.get('ros_interface_dependencies', []):
        package, path = _split_tuple(entry)
        interface = interface_of_file(package, path)
        dependencies.setdefault(package, {})[(interface.kind, interface.name)] = interface
    packages = {package: Package(package, None, interfaces)
                for package, interfaces in dependencies.items()}
    packages[name] = Package(name, None, own)
    builder = ModelBuilder(packages, HeapStorage(), _where_dependencies_come_from)
    notices = []
    for kind, reason in sorted(SKIPPED_KINDS.items()):
        names = ['%s/%s/%s' % (name, i.kind, i.name) for i in skipped if i.kind == kind]
        if names:
            notices.append('%s: skipped %s: %s' % (PROGRAM, ', '.join(names), reason))
    models = {'msg': [], 'srv': []}
    uncarried = []
    for kind, stem in sorted(own):
        full_name = '%s/%s/%s' % (name, kind, stem)
        try:
            models[kind].append(builder.message(full_name) if kind == 'msg'
                                else builder.service(full_name))
        except UncarriableType as error:
            uncarried.append(header_path(name, kind, stem))
            notices.append('%s: skipped %s: %s' % (PROGRAM, full_name, _why_uncarriable(
                full_name, error)))
    # The support headers are not the package's: the generator's install
    # holds them once (SUPPORT_INCLUDE_DIR), which the package's target names.
    files = render_types(models['msg'], models['srv'])
    # A header an earlier run wrote, before the type took what mros2 cannot carry.
    for relative in uncarried:
        path = os.path.join(arguments['output_dir'], relative)
        if os.path.exists(path):
            os.remove(path)
    return write_files(arguments['output_dir'], files), sorted(files), notices


def _why_uncarriable(full_name, error):
    """Why a type was skipped: what mros2 cannot carry in it, or in a type it holds."""
    if error.type_name in (full_name, full_name + '_Request', full_name + '_Response'):
        return 'mros2 cannot carry it: %s' % error
    return 'it holds %s, which mros2 cannot carry: %s' % (error.type_name, error)


def _read_arguments(path):
    try:
        return read_generator_arguments(path)
    except (OSError, ValueError) as error:
        raise GenmrosError('cannot read the generator arguments: %s'
                           % (getattr(error, 'strerror', None) or error), path)


def generator_files():
    """The files the headers come from besides the interfaces: the modules
    this one imports (the rosidl front end, the mros2 back end, the core)
    and the templates and static headers they render."""
    modules = {module.__file__ for name, module in sys.modules.items()
               if name.split('.')[0] == 'colcon_mros' and getattr(module, '__file__', None)}
    # This module too, when it runs as __main__.
    modules = sorted(modules | {os.path.abspath(__file__)})
    data = [os.path.join(directory, name)
            for directory in (render.TEMPLATE_DIR, render.SUPPORT_DIR, core_render.SUPPORT_DIR)
            for name in sorted(os.listdir(directory))]
    return modules + data


def _make_path(path):
    """A path as a make rule spells it: spaces escaped."""
    return path.replace(' ', '\\ ')


def write_dependency_file(path, target):
    """The depfile at path: target depends on generator_files()."""
    text = '%s: %s\n' % (_make_path(target), ' \\\n  '.join(
        _make_path(name) for name in generator_files()))
    write_file(path, text)


def main(argv=None):
    parser = argparse.ArgumentParser(
        prog=PROGRAM, description='Write the mros2 headers of the interfaces a rosidl '
                                  'arguments file lists (what rosidl_generate_interfaces() runs).')
    parser.add_argument('--generator-arguments-file', metavar='FILE', required=True,
                        help='the arguments file rosidl_write_generator_arguments() wrote')
    parser.add_argument('--header-list', metavar='FILE',
                        help='also write the headers, one a line, relative to the output '
                             'directory (the ament index marker the CMake side installs)')
    parser.add_argument('--dependency-file', metavar='FILE',
                        help="also write a make depfile: the rule's output depends on the "
                             "generator's own files")
    parser.add_argument('--dependency-target', metavar='OUTPUT',
                        help="the rule's output the depfile names (with --dependency-file)")
    options = parser.parse_args(argv)
    if bool(options.dependency_file) != bool(options.dependency_target):
        parser.error('--dependency-file and --dependency-target go together')
    try:
        require_rosidl()
        _, headers, notices = generate(_read_arguments(options.generator_arguments_file))
        if options.header_list:
            write_file(options.header_list, ''.join(header + '\n' for header in headers))
        if options.dependency_file:
            write_dependency_file(options.dependency_file, options.dependency_target)
    except GenmrosError as error:
        print('genmros: error: %s' % error, file=sys.stderr)
        return 1
    for notice in notices:
        print(notice)
    return 0


if __name__ == '__main__':
    sys.exit(main())
