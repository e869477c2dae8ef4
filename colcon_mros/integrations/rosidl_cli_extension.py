# SPDX-License-Identifier: BSD-3-Clause
"""``rosidl generate --type mros2``: the mros2 headers through rosidl's
command line, as ``--type cpp`` gives rosidl_generator_cpp's.

rosidl_cli (rosidl 3.x and 4.x) loads the type extensions of its entry
point group ``rosidl_cli.command.generate.type_extensions``; setup.cfg
registers this one as ``mros2``. It does what rosidl_generator_cpp's does:
``.msg`` and ``.srv`` files are translated to ``.idl`` first (rosidl_cli's
translate, with rosidl_adapter), the dependencies' ``.idl`` files are
found below the include paths, and the same generator as
rosidl_generate_interfaces()'s runs, with the same skips and notices
(:mod:`colcon_mros.integrations.rosidl_generator`).
"""

import pathlib

from rosidl_cli.command.generate.extensions import GenerateCommandExtension
from rosidl_cli.command.helpers import (dependencies_from_include_paths,
                                        idl_tuples_from_interface_files,
                                        interface_path_as_tuple)
from rosidl_cli.command.translate.api import translate

from colcon_mros.integrations.rosidl_generator import generate


class GenerateMros2(GenerateCommandExtension):
    """The mros2 type representation: a header per message and service."""

    def generate(self, package_name, interface_files, include_paths, output_path):
        idl_files = [path for path in interface_files if str(path).endswith('.idl')]
        other_files = [path for path in interface_files if not str(path).endswith('.idl')]
        if other_files:
            idl_files += translate(package_name=package_name, interface_files=other_files,
                                   include_paths=include_paths, output_format='idl',
                                   output_path=pathlib.Path(output_path) / 'tmp')
        # genmros' errors name the .msg or .srv the user wrote.
        user_files = [str(prefix / path)
                      for prefix, path in map(interface_path_as_tuple, other_files)]
        _, headers, notices = generate({
            'package_name': package_name,
            'output_dir': str(output_path),
            'idl_tuples': idl_tuples_from_interface_files(idl_files),
            'ros_interface_files': user_files,
            'ros_interface_dependencies': dependencies_from_include_paths(include_paths),
        })
        for notice in notices:
            print(notice)
        return [pathlib.Path(output_path) / header for header in headers]
