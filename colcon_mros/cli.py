"""The ``genmros`` command (also ``python3 -m colcon_mros``)."""

import argparse
import os
import sys

from colcon_mros import __version__
from colcon_mros.defaults import (DEFAULT_VARIABLE_SIZE_BUDGET, DEFINITION_TEXTS, EXPORT_PARTS,
                                  STORAGE_KINDS)
from colcon_mros.errors import GenmrosError
from colcon_mros.export_claims import ExportClaims
from colcon_mros.installed_files import CATKIN_MARKER, CMAKE_CONFIG, MAKE_FRAGMENT, installed_file
from colcon_mros.ros_environment import require_ros_python
from colcon_mros.workspace import parse_include_flags

DESCRIPTION = '''\
Generate mROS message headers from ROS 1 .msg and .srv files.

  genmros FILE.msg|FILE.srv -p PKG -o OUTDIR [-I PKG:DIR ...] [-e TEMPLATE_DIR]
          [--export-dir DIR]
      generator mode, with gencpp's arguments: the headers of one file
      (catkin runs it for every message of every package).

  genmros export [--workspace WS ...] [--package PKG ...] [--type PKG/TYPE ...] -o DIR
      the headers of the selected types and every type they contain, plus the
      per-firmware aggregates message_headers.h, message_class_specialization.h
      and msg_max_size.h for the selected types. Without --package or --type:
      every type in WS. (genmros export --help lists the options: storage,
      definition text, depfile.)

  genmros make-fragment
      prints the path of genmros.mk, the fragment an mROS v1 app's Makefile
      includes to generate its headers.

  genmros cmake-dir
      prints the directory of genmrosConfig.cmake: -Dgenmros_DIR=... lets
      find_package(genmros) work under a cross toolchain file.

  genmros catkin-prefix
      prints a catkin prefix that holds genmros' generator marker (and
      lets find_package(genmros) find this install): with it on
      CMAKE_PREFIX_PATH, catkin runs genmros (for installs that cannot
      write /etc/ros/genmsg: ROS Noetic, a user, a venv).

  genmros prune-export DIR
      removes from a catkin export dir (MROS_EXPORT_DIR) the headers and
      definitions no generated type needs any more (catkin runs it when a
      package loses a .msg or .srv file).
'''


def _generator_parser():
    parser = argparse.ArgumentParser(
        prog='genmros', description=DESCRIPTION,
        formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument('--version', action='version', version='genmros %s' % __version__)
    parser.add_argument('file', metavar='FILE', help='a .msg or .srv file')
    parser.add_argument('-p', dest='package', required=True, help='package of FILE')
    parser.add_argument('-o', dest='output_dir', required=True,
                        help='output directory, <include root>/<package>')
    parser.add_argument('-I', dest='include_paths', action='append', default=[],
                        metavar='PKG:DIR', help='msg directory of a package (repeatable)')
    parser.add_argument('-e', dest='template_dir', help='template directory to use instead of ours')
    parser.add_argument('--export-dir', metavar='DIR',
                        help='also write DIR/include/<pkg>/<Type>.h for the types of FILE and every '
                             'type they contain, and their definitions to DIR/share/<pkg>/ '
                             "(catkin's MROS_EXPORT_DIR)")
    return parser


def _export_parser():
    parser = argparse.ArgumentParser(
        prog='genmros export',
        description='Export the mROS headers of a workspace for a firmware build.')
    parser.add_argument('--workspace', dest='workspaces', action='append', default=[], metavar='WS',
                        help='catkin/colcon workspace or source tree, searched for packages '
                             '(repeatable)')
    parser.add_argument('--package', dest='packages', action='append', default=[],
                        metavar='PKG', help='export every type of PKG (repeatable)')
    parser.add_argument('--type', dest='types', action='append', default=[],
                        metavar='PKG/TYPE', help='export one message or service (repeatable)')
    parser.add_argument('-o', dest='output_dir', required=True, metavar='DIR',
                        help='include root to write to')
    parser.add_argument('--underlay', dest='prefixes', action='append', metavar='PREFIX',
                        help='installed prefix holding share/<pkg>/msg, instead of the ROS '
                             "environment (repeatable; default: rospkg's packages on "
                             'ROS_PACKAGE_PATH, then the spaces on CMAKE_PREFIX_PATH)')
    parser.add_argument('--variable-size-budget', type=int, metavar='BYTES',
                        default=DEFAULT_VARIABLE_SIZE_BUDGET,
                        help='PUB_MSG_MAX_SIZE share of a type without an upper size '
                             '(default: %(default)s)')
    parser.add_argument('--only', choices=EXPORT_PARTS[1:],
                        help='write only the headers, or only the per-firmware aggregates')
    parser.add_argument('-e', dest='template_dir', help='template directory to use instead of ours')
    parser.add_argument('--storage', choices=STORAGE_KINDS, default='heap',
                        help='strings and variable arrays as std::string/std::vector (heap, '
                             'default) or held in the message with maxima from options files '
                             '(bounded: no heap)')
    parser.add_argument('--options', dest='option_files', action='append', default=[],
                        metavar='FILE',
                        help="bounds for --storage bounded: lines 'pkg/Type.field max_size:N "
                             "max_count:N' or '* ...' (repeatable; each package's "
                             'msg/genmros.options is read too)')
    parser.add_argument('--definition-text', choices=DEFINITION_TEXTS, default='full',
                        help="the definition text each header carries: gencpp's (full, default; "
                             'what roscpp sends as message_definition) or the same declarations '
                             'without comments and blank lines (compact: less flash; the MD5 '
                             'sum and what ROS tools decode from the text are the same)')
    parser.add_argument('--depfile', metavar='FILE',
                        help='also write FILE, a make rule naming every .msg/.srv file and '
                             'options file the headers come from')
    return parser


def main(argv=None):
    argv = sys.argv[1:] if argv is None else argv
    try:
        if argv[:1] == ['export']:
            options = _export_parser().parse_args(argv[1:])
            require_ros_python()
            from colcon_mros.export import export  # needs genmsg and empy
            result = export(options.output_dir, options.prefixes,
                            options.workspaces, options.packages, options.types,
                            options.variable_size_budget, options.template_dir,
                            options.only or 'all', options.depfile, options.storage,
                            options.option_files, options.definition_text)
            print('genmros: exported %d message and %d service types to %s'
                  % (len(result.messages), len(result.services), options.output_dir))
        elif argv == ['make-fragment']:
            print(installed_file(MAKE_FRAGMENT))
        elif argv == ['cmake-dir']:
            print(os.path.dirname(installed_file(CMAKE_CONFIG)))
        elif argv == ['catkin-prefix']:
            print(os.path.dirname(installed_file(CATKIN_MARKER)))
        elif argv[:1] == ['prune-export'] and len(argv) == 2:
            if not os.path.isdir(argv[1]):
                raise GenmrosError('export dir is not a directory', argv[1])
            with ExportClaims(argv[1]) as claims:
                for relative in claims.prune():
                    print('genmros: removed %s' % os.path.join(argv[1], relative))
        else:
            options = _generator_parser().parse_args(argv)
            require_ros_python()
            from colcon_mros.generate import generate_file  # needs genmsg and empy
            generate_file(options.file, options.package, options.output_dir,
                          parse_include_flags(options.include_paths), options.template_dir,
                          options.export_dir)
    except GenmrosError as error:
        print('genmros: error: %s' % error, file=sys.stderr)
        return 1
    return 0
