# SPDX-License-Identifier: BSD-3-Clause
"""The ``genmros`` command (also ``python3 -m colcon_mros``).

One argparse subcommand per job, each with ``--help``, and a function that
turns its options into the explicit arguments of the module that does the
job. Every command line names its subcommand (catkin's runs ``genmros
generate``). Each subcommand imports what it needs when it runs: ROS'
Python packages only where they are needed.
"""

import argparse
import os
import sys
import textwrap

from colcon_mros import __version__
from colcon_mros.core.defaults import (DEFAULT_DEFINITION_TEXT, DEFAULT_STORAGE,
                                       DEFINITION_TEXTS, EXPORT_PARTS, STORAGE_KINDS)
from colcon_mros.core.wording import counted
from colcon_mros.errors import GenmrosError
from colcon_mros.mros_v1.defaults import DEFAULT_VARIABLE_SIZE_BUDGET, PC_TARGETS

DESCRIPTION = '''\
Generate mROS message headers: from ROS 1 .msg and .srv files for mROS v1,
and from ROS 2 interface files (.msg, .srv, .idl, read with rosidl) for
mros2. Definitions come from source trees (--workspace WS) and installed
prefixes (--prefix PREFIX); without --prefix, from the ROS environment.

  genmros mros-v1-export [--workspace WS ...] [--type PKG/TYPE ...] -o DIR
  genmros mros2-export [--workspace WS ...] [--publish [TOPIC:]PKG/msg/TYPE ...]
                       [--subscribe [TOPIC:]PKG/msg/TYPE ...] -o DIR

The names this release replaced (export, prune-export, --mros-root, ...)
still work until the next release, each saying its new name on stderr.'''
# The user's subcommands in the top-level help, by what they serve. The
# plumbing the builds run (catkin: generate, catkin-export-dir) answers
# --help of its own but is not listed.
SUBCOMMAND_GROUPS = (
    ('mROS v1 (ROS 1)', ('mros-v1-export', 'mros-v1-fit', 'mros-v1-pc', 'mros-v1-harden',
                         'mros-v1-prune-export')),
    ('mros2 (ROS 2)', ('mros2-export', 'mros2-fit', 'mros2-pc', 'mros2-pc-ros', 'mros2-harden',
                       'mros2-peer-profile', 'mros2-mend-wheels')),
    ('paths for builds', ('cmake-dir', 'make-fragment', 'catkin-prefix')),
)


class _Subcommands:
    """argparse's subparsers, keeping each subcommand's one-line summary for
    the grouped top-level help instead of argparse's flat list."""

    def __init__(self, action):
        self.action = action
        self.summaries = {}

    def add_parser(self, name, help, **keywords):
        self.summaries[name] = help
        return self.action.add_parser(name, **keywords)

    def listing(self):
        """The groups of SUBCOMMAND_GROUPS, one line per subcommand."""
        width = max(len(name) for _, names in SUBCOMMAND_GROUPS for name in names)
        lines = []
        for title, names in SUBCOMMAND_GROUPS:
            lines.append('%s:' % title)
            lines += [textwrap.fill(self.summaries[name], 79, initial_indent='  %-*s  ' % (
                width, name), subsequent_indent=' ' * (width + 4)) for name in names]
        return '\n'.join(lines)


# The spellings this release replaced, hidden from --help and kept until the
# next one, so that scripts and builds have a release to move: each does
# what its new spelling does and says that spelling on stderr.
RENAMED_SUBCOMMANDS = {'export': 'mros-v1-export', 'prune-export': 'mros-v1-prune-export'}


def _say_renamed(old, new):
    print("genmros: '%s' is now %s; the old name goes in the next release" % (old, new),
          file=sys.stderr)


class _OldSpelling(argparse.Action):
    """An old spelling of an option (or of a positional argument, then named
    by old): it stores its value where the new spelling does (appends with
    append; stores const with nargs=0) and says new, once a run."""

    def __init__(self, option_strings, dest, new, old=None, append=False, **keywords):
        # Absent, it leaves the new spelling's default alone.
        keywords.setdefault('default', argparse.SUPPRESS)
        super().__init__(option_strings, dest, help=argparse.SUPPRESS, **keywords)
        self.new, self.old, self.append, self.said = new, old, append, False

    def __call__(self, parser, namespace, values, option_string=None):
        if not self.said:
            _say_renamed(self.old or option_string, self.new)
            self.said = True
        if self.append:
            values = list(getattr(namespace, self.dest, None) or []) + [values]
        elif self.nargs == 0:
            values = self.const
        setattr(namespace, self.dest, values)


# Options more than one subcommand takes, each defined once.

def _add_output(parser, what, **keywords):
    """-o/--output: on every subcommand, the thing it writes."""
    parser.add_argument('-o', '--output', help=what, **keywords)


def _add_template_dir(parser):
    parser.add_argument('-e', dest='template_dir',
                        help='template directory to use instead of ours')


def _add_cmake_module(parser):
    parser.add_argument('--cmake-module', metavar='FILE',
                        help="the mros_generate.cmake an export dir's mros_export.cmake includes "
                             "(default: this install's)")


def _add_types(parser, default):
    parser.add_argument('--type', dest='types', action='append', default=[], metavar='PKG/TYPE',
                        help='a message or service type, or one half of a service '
                             '(PKG/SrvRequest) (repeatable; default: %s)' % default)


def _add_definition_places(parser, prefix_default, workspace_help='a source tree'):
    """Where definitions are, with one name for each kind of place on every
    subcommand: --workspace (a source tree) and --prefix (an installed
    prefix). The names they had are hidden aliases: --underlay (a prefix)
    and --msg-path (either, told apart by its share/), an old spelling."""
    parser.add_argument('--workspace', dest='workspaces', action='append', default=[],
                        metavar='WS', help='%s, searched for package.xml (repeatable)'
                                           % workspace_help)
    parser.add_argument('--prefix', dest='prefixes', action='append', metavar='PREFIX',
                        help='an installed prefix (share/<pkg>/msg), or an export dir '
                             '(repeatable; default: %s)' % prefix_default)
    parser.add_argument('--underlay', dest='prefixes', action='append', help=argparse.SUPPRESS)
    parser.add_argument('--msg-path', dest='msg_paths', action=_OldSpelling, append=True,
                        default=[], new="'--workspace' (a source tree) or '--prefix' (an "
                                        'installed prefix, with share/)')


def _add_source_export_dir(parser, use):
    parser.add_argument('--export-dir', metavar='DIR',
                        help="an export dir (catkin's MROS_EXPORT_DIR, colcon's --mros-export) "
                             'the types come from%s' % use)


def _add_settings(parser, default):
    parser.add_argument('--mros-v1-settings', dest='library_settings', action='append',
                        default=[], metavar='FILE',
                        help="an mROS v1 settings header to check the types against: the app's "
                             "mros_usr_config.h and the library's mros_packet_config.h, the one "
                             'the build includes first (repeatable; %s)' % default)


def _add_fit_strict(parser):
    parser.add_argument('--fit-strict', action='store_true',
                        help="refuse too, instead of warning, what only might not fit the "
                             "library's settings: a frame without a largest size (heap "
                             'storage), a connection header that fits only short names')


def _add_storage(parser, what, options_note):
    """Heap or bounded storage, and the options files that bound it."""
    parser.add_argument('--storage', choices=STORAGE_KINDS, default=DEFAULT_STORAGE,
                        help='%s as std::string/std::vector (heap, default) or held in the '
                             'message with maxima from options files (bounded: no heap)' % what)
    parser.add_argument('--options', dest='option_files', action='append', default=[],
                        metavar='FILE',
                        help="bounds for --storage bounded: lines 'pkg/Type.field max_size:N "
                             "max_count:N' or '* ...' (repeatable%s)" % options_note)


def _add_header_form(parser):
    """What the headers hold: storage, bounds, definition text."""
    _add_storage(parser, 'strings and variable arrays',
                 "; each package's msg/genmros.options is read too")
    parser.add_argument('--definition-text', choices=DEFINITION_TEXTS,
                        default=DEFAULT_DEFINITION_TEXT,
                        help="the definition text each header carries: gencpp's (full, default; "
                             'what roscpp sends as message_definition) or the same declarations '
                             'without comments and blank lines (compact: less flash; the MD5 '
                             'sum and what ROS tools decode from the text are the same)')


def _add_app(parser, types_default="the app's app.json"):
    """Where an mROS v1 app, its library and its types are."""
    parser.add_argument('--mros-v1-root', metavar='DIR',
                        help='the mROS v1 checkout (default: the one APP_DIR is in, ../..)')
    parser.add_argument('--mros-root', dest='mros_v1_root', action=_OldSpelling,
                        new="'--mros-v1-root'")
    _add_types(parser, types_default)
    _add_definition_places(parser, "app.json's catkin_ws_dir, else the ROS environment",
                           "a source tree (default: app.json's catkin_ws_dir)")


# The subcommands.

def _add_generate(subparsers):
    parser = subparsers.add_parser(
        'generate', help='the headers of .msg and .srv files (generator mode)',
        description="The headers of .msg and .srv files of one package, with gencpp's "
                    'arguments: what catkin runs once per package.')
    parser.add_argument('files', nargs='+', metavar='FILE', help='a .msg or .srv file')
    parser.add_argument('-p', dest='package', required=True, help='package of the files')
    _add_output(parser, "the package's header directory the headers are written to, "
                        '<include root>/<package>', dest='output_dir', required=True,
                metavar='DIR')
    parser.add_argument('-I', dest='include_paths', action='append', default=[],
                        metavar='PKG:DIR', help='msg directory of a package (repeatable)')
    _add_template_dir(parser)
    parser.add_argument('--add-to-export-dir', dest='export_dir', metavar='DIR',
                        help='also put the headers of the types of FILE and of every type they '
                             "contain, and their definitions, into the export dir DIR (catkin's "
                             'MROS_EXPORT_DIR)')
    # Its name until 0.1.0, where --export-dir elsewhere names a dir to read.
    parser.add_argument('--export-dir', dest='export_dir', help=argparse.SUPPRESS)
    _add_cmake_module(parser)
    parser.add_argument('--record', dest='records', action='append', default=[], metavar='FILE',
                        help="the run's record (repeatable): only the files whose definitions "
                             'changed since the last run recorded there are generated again '
                             '(catkin gives one per package, and one in the export dir)')
    parser.add_argument('--all-of-package', action='store_true',
                        help='FILE... are all the definitions the package has: the headers (and '
                             'export dir claims) of any other, removed from the package, go')
    parser.set_defaults(run=_generate)


def _add_mros_v1_export(subparsers):
    parser = subparsers.add_parser(
        'mros-v1-export', help='the headers and aggregates one firmware needs',
        description='The headers of the selected types and every type they contain, plus the '
                    'per-firmware aggregates message_headers.h, message_class_specialization.h '
                    'and msg_max_size.h for the selected types. Without --package or --type: '
                    'every type in the workspaces.')
    _add_definition_places(parser, "the ROS environment: rospkg's packages on ROS_PACKAGE_PATH, "
                                   'then the spaces on CMAKE_PREFIX_PATH',
                           'a catkin/colcon workspace or source tree')
    parser.add_argument('--package', dest='packages', action='append', default=[],
                        metavar='PKG', help='export every type of PKG (repeatable)')
    _add_types(parser, 'every type of --package, else of --workspace')
    _add_output(parser, 'the include root the headers are written to', dest='output_dir',
                required=True, metavar='DIR')
    _add_source_export_dir(parser, ': an underlay whose headers serve where they have the form '
                                   'asked for (heap storage, full text), so that only the '
                                   'aggregates are written')
    parser.add_argument('--variable-size-budget', type=int, metavar='BYTES',
                        default=DEFAULT_VARIABLE_SIZE_BUDGET,
                        help='PUB_MSG_MAX_SIZE share of a type without an upper size '
                             '(default: %(default)s)')
    parser.add_argument('--only', choices=EXPORT_PARTS[1:],
                        help='write only the headers, or only the per-firmware aggregates')
    _add_template_dir(parser)
    _add_header_form(parser)
    parser.add_argument('--record', metavar='FILE',
                        help="keep the run's record in FILE, and do nothing when it says that "
                             'nothing the output comes from changed; FILE is also a make rule '
                             'naming every .msg/.srv and options file the headers come from')
    _add_settings(parser, 'each setting too small for a type is one error line with the value '
                          'it needs')
    _add_fit_strict(parser)
    parser.add_argument('--quiet', action='store_true',
                        help='say nothing when the run record says the headers are up to date '
                             '(the make fragment runs genmros on every make)')
    parser.set_defaults(run=_mros_v1_export)


def _add_printers(subparsers):
    for name, help_text, run in (
            ('make-fragment', "print the path of genmros.mk, the fragment an mROS v1 app's "
                              'Makefile includes to generate its headers', _make_fragment),
            ('cmake-dir', 'print the directory of genmrosConfig.cmake: -Dgenmros_DIR=... lets '
                          'find_package(genmros) work under a cross toolchain file', _cmake_dir),
            ('catkin-prefix', "print a catkin prefix that holds genmros' generator marker (and "
                              'leads find_package(genmros) to this install): with it on '
                              'CMAKE_PREFIX_PATH, catkin runs genmros (for installs that cannot '
                              'write /etc/ros/genmsg: ROS Noetic, a user, a venv)',
             _catkin_prefix)):
        parser = subparsers.add_parser(name, help=help_text, description=help_text)
        parser.set_defaults(run=run)


def _add_export_dir_commands(subparsers):
    parser = subparsers.add_parser(
        'mros-v1-prune-export', help='remove from an export dir what no definition needs any more',
        description='Remove from an export dir (MROS_EXPORT_DIR) the headers and definitions no '
                    'generated type needs any more.')
    parser.add_argument('export_dir', metavar='DIR')
    parser.set_defaults(run=_mros_v1_prune_export)
    parser = subparsers.add_parser(
        'catkin-export-dir', help="catkin's configure step with MROS_EXPORT_DIR "
                                  '(genmros-extras.cmake)',
        description="What catkin's configure step asks once when MROS_EXPORT_DIR is set: the "
                    'export dir is checked and prepared, and a CMake file says where the '
                    "packages' run records in it go.")
    parser.add_argument('export_dir', metavar='DIR', help='the export dir to prepare')
    parser.add_argument('--cmake-file', required=True, metavar='FILE')
    _add_cmake_module(parser)
    parser.set_defaults(run=_catkin_export_dir)


def _add_mros_v1_pc(subparsers):
    parser = subparsers.add_parser(
        'mros-v1-pc', help='build and run an unmodified mROS v1 app and library on this PC',
        description='Build an mROS v1 app (mros_ws/<app>) with the mROS v1 library of its '
                    'checkout, unchanged, and genmros\' headers, and run it on this PC against a '
                    'ROS master: the PC target stands in for TOPPERS/ASP (with its scheduling), '
                    'lwIP and mbed. The message types come from the app\'s app.json (the old '
                    'generator\'s file) unless --type is given. The node finds the master in '
                    'ROS_MASTER_URI and its address in ROS_IP/ROS_HOSTNAME.')
    parser.add_argument('app_dir', metavar='APP_DIR', help="the app's directory (with app.cfg)")
    parser.add_argument('--target', choices=PC_TARGETS, default='arm',
                        help='arm: 32-bit ARM Linux, the board\'s instruction set, a static '
                             'program run with qemu-arm, each task on its app.cfg stack size '
                             '(default); native: this PC, 1 MiB task stacks')
    _add_output(parser, 'the build directory (default: APP_DIR/build-pc-TARGET)',
                dest='build_dir', metavar='DIR')
    _add_app(parser)
    _add_header_form(parser)
    parser.add_argument('-j', dest='jobs', type=int, default=os.cpu_count() or 1,
                        help='parallel make jobs (default: the number of CPUs)')
    parser.add_argument('--no-fit-check', action='store_true',
                        help="build even where the app's types do not fit the library's "
                             "settings (the check in genmros' make step and in ros.cpp); the "
                             'program will then overrun what the check names')
    _add_fit_strict(parser)
    parser.add_argument('--sanitize', action='store_true',
                        help='build library, stand-ins and app with AddressSanitizer and '
                             'UndefinedBehaviorSanitizer (with --target native), so that an '
                             'overrun shows on the PC before the board')
    parser.add_argument('--hardened', action='store_true',
                        help="build the library with genmros' patch set for it applied, on a "
                             'copy in the build directory (genmros mros-v1-harden applies it to '
                             'a checkout); default: the library as it is')
    parser.add_argument('-v', '--verbose', action='store_true',
                        help='show every compiler command (default: one line per step; '
                             'compiler errors are always shown in full)')
    _add_build_only(parser, 'under qemu-arm for arm, against the master of ROS_MASTER_URI')
    parser.add_argument('--run', dest='build_only', action=_OldSpelling, nargs=0, const=False,
                        new="the default ('--build-only' builds without running)")
    parser.set_defaults(run=_mros_v1_pc)


def _add_mros_v1_fit(subparsers):
    parser = subparsers.add_parser(
        'mros-v1-fit', help="an mROS v1 app's message types against its library's settings",
        description="One table row per message type of an mROS v1 app (or of an export dir): "
                    'its definition text, the connection headers ROS nodes send for it, its '
                    "largest frame, and for each of the library's settings (header buffers, "
                    "type name field, memory pools) 'ok' or the value it needs; then the "
                    "library's tables and the lines a build would stop with. Exits 1 if a "
                    'build would stop.')
    parser.add_argument('app_dir', metavar='APP_DIR', nargs='?',
                        help="the app's directory (mros_ws/<app>)")
    _add_source_export_dir(parser, ', reported instead of an app')
    _add_settings(parser, "default for an app: the app's mros_usr_config.h and the library's "
                          'mros_packet_config.h')
    _add_app(parser, "the app's app.json, or every type of --export-dir")
    _add_header_form(parser)
    parser.set_defaults(run=_mros_v1_fit)


def _add_build_only(parser, where):
    parser.add_argument('--build-only', action='store_true',
                        help='build the program, and do not run it (default: build it, then run '
                             'it %s)' % where)


def _add_harden_arguments(parser, subcommand, option, what):
    """The checkout a harden subcommand patches (option, or the one argument
    of the old spelling), and what it does to it."""
    dest = option[2:].replace('-', '_')
    root = parser.add_mutually_exclusive_group(required=True)
    root.add_argument(option, dest=dest, metavar='DIR', help=what)
    root.add_argument(dest, nargs='?', action=_OldSpelling, old='%s DIR' % subcommand,
                      new="'%s %s DIR'" % (subcommand, option))
    # argparse shows a group with a hidden member as optional.
    parser.usage = '%%(prog)s [-h] %s DIR [--check | --revert]' % option
    action = parser.add_mutually_exclusive_group()
    action.add_argument('--check', action='store_true',
                        help='say which patches are applied; exit 0 if all are, 1 if not')
    action.add_argument('--revert', action='store_true', help='take the patches out')


def _add_mros_v1_harden(subparsers):
    parser = subparsers.add_parser(
        'mros-v1-harden', help="apply genmros' patch set to an mROS v1 checkout's library",
        description="Apply genmros' patch set for the mROS v1 library (fixes, each named for "
                    'what it fixes) to the mros-lib/ of a checkout, for the board\'s own build. '
                    'Only mros-lib/ is changed, and only where every file is as the patches '
                    'expect; a patch already applied is left as it is.')
    _add_harden_arguments(parser, 'mros-v1-harden', '--mros-v1-root', 'the mROS v1 checkout')
    parser.set_defaults(run=_mros_v1_harden)


def _add_mros2_harden(subparsers):
    parser = subparsers.add_parser(
        'mros2-harden', help="apply genmros' patch set to an mros2 checkout",
        description="Apply genmros' patch set for mros2 (made for v0.5.4: one writer per "
                    'publisher; the checked receive, which drops and counts a sample that does '
                    "not decode, with genmros' message headers; embeddedRTPS discovering Fast "
                    'DDS 3) to a checkout. Only include/, src/ and embeddedRTPS/ are changed, '
                    'and only where every file is as the patches expect; a patch already '
                    'applied is left as it is.')
    _add_harden_arguments(parser, 'mros2-harden', '--mros2-root', 'the mros2 checkout')
    parser.set_defaults(run=_mros2_harden)


def _add_mros2_sources(parser):
    _add_definition_places(parser, 'AMENT_PREFIX_PATH; an installed ROS 2 prefix has the ament '
                                   "index, an export dir's is its mros2/",
                           'a ROS 2 workspace or source tree')


def _add_mros2_endpoints(parser, instantiated):
    topic_help = ('a topic and message type the firmware %s' + instantiated +
                  '; a type alone skips the topic rules of the fit check; :reliable, one the '
                  'app makes with mros2::QoS(DEPTH).reliable() (DEPTH 10 unless given; the '
                  'mros2 patch reliable-where-asked) (repeatable)')
    service_help = ('a service the firmware %s' + instantiated + ', with '
                    'mros2::Node::create_%s (the mros2 patch services-both-ways): its request '
                    'and reply writer and reader count as reliable endpoints on rq/NAMERequest '
                    'and rr/NAMEReply (repeatable)')
    topic, service = '[TOPIC:]PKG/msg/TYPE[:reliable[:DEPTH]]', '[NAME:]PKG/srv/TYPE'
    for flag, metavar, text in (('--publish', topic, topic_help % 'publishes'),
                                ('--subscribe', topic, topic_help % 'subscribes to'),
                                ('--serve', service, service_help % ('serves', 'service')),
                                ('--call', service, service_help % ('calls', 'client'))):
        parser.add_argument(flag, dest=flag[2:], action='append', default=[], metavar=metavar,
                            help=text)


def _add_mros2_board(parser, required):
    parser.add_argument('--rtps-config', required=required, metavar='FILE',
                        help="the board's rtps/config.h, the one the firmware compiles with"
                             + ('' if required else ': check the endpoints against it first'))
    parser.add_argument('--receive-limit', metavar='BYTES|FILE:NAME',
                        help="the largest datagram the board's network stack takes: bytes, or "
                             "the setting NAME in FILE (a #define or a constant); checked "
                             'against the largest sample of each subscribed type')
    parser.add_argument('--mros2-root', metavar='DIR',
                        help="the firmware's mros2 checkout: whether its Publisher has a writer "
                             'of its own and whether it takes samples in fragments')
    _add_peer_max_message(parser)


def _add_peer_max_message(parser):
    from colcon_mros.mros2.rules import PEER_MAX_MESSAGE
    parser.add_argument('--peer-max-message', metavar='BYTES', type=int,
                        default=PEER_MAX_MESSAGE,
                        help="the largest datagram the ROS side sends: its transport's "
                             'maxMessageSize (default %d, Fast DDS\' UDP default); a larger '
                             'sample comes in fragments of up to that' % PEER_MAX_MESSAGE)


def _add_mros2_storage(parser):
    _add_storage(parser, 'unbounded strings and sequences (string<=N and T[<=N] are always '
                         'bounded)', "; each package's msg/genmros.options is read too")


def _add_mros2_export(subparsers):
    parser = subparsers.add_parser(
        'mros2-export', help='the headers one mros2 firmware needs, and its '
                             'templates.hpp',
        description='mros2 (ROS 2): the headers of the selected ROS 2 types and every type they '
                    'contain, read with rosidl from a workspace and the installed ROS 2 packages; '
                    "with --publish/--subscribe also mros2's templates.hpp for those types, with "
                    "the fit check's static_asserts; with --rtps-config the fit check runs first "
                    '(genmros mros2-fit) and a misfit writes nothing.')
    _add_mros2_sources(parser)
    parser.add_argument('--package', dest='packages', action='append', default=[],
                        metavar='PKG', help='export every type of PKG (repeatable)')
    parser.add_argument('--type', dest='types', action='append', default=[],
                        metavar='PKG/msg/TYPE',
                        help='a message (PKG/msg/TYPE or PKG/TYPE), a service (PKG/srv/NAME) or '
                             'one half of one (repeatable)')
    _add_mros2_endpoints(parser, ': exported, and instantiated in templates.hpp')
    _add_output(parser, 'the include root the headers (and templates.hpp) are written to',
                dest='output_dir', required=True, metavar='DIR')
    _add_mros2_board(parser, required=False)
    _add_mros2_storage(parser)
    parser.set_defaults(run=_mros2_export)


def _add_mros2_fit(subparsers):
    parser = subparsers.add_parser(
        'mros2-fit', help="a firmware's endpoints against its board's settings",
        description="mros2 (ROS 2): a firmware's endpoints against its board's rtps/config.h "
                    "(type and topic name lengths, the participant's writers and readers), "
                    "its network stack's receive limit (each subscribed type's largest sample) "
                    "and its mros2 (more than one publisher). One line per problem, naming the "
                    'setting, its file and line and the value it needs. Exits 1 if a build '
                    'would stop.')
    _add_mros2_sources(parser)
    _add_mros2_endpoints(parser, '')
    _add_mros2_board(parser, required=True)
    _add_mros2_storage(parser)
    parser.set_defaults(run=_mros2_fit)


def _add_mros2_pc(subparsers):
    from colcon_mros.library_tools.mros2.pc_target.build import DEFAULT_RECEIVE_LIMIT
    parser = subparsers.add_parser(
        'mros2-pc', help='build and run an unmodified mros2 app and mros2 on this PC',
        description="Build an mros2 app with the user's mros2 (and its embeddedRTPS), "
                    "unchanged, genmros' headers and templates.hpp (after the fit check), and "
                    "stand-ins for the board's CMSIS-RTOS2 and lwIP, then run it on a network "
                    'of its own: the board side has the board\'s address, the ROS side the '
                    'peer\'s, in one user namespace with two network namespaces (no root). '
                    '`genmros mros2-pc-ros -- CMD` runs a ROS 2 command on its ROS side.',
        usage='genmros mros2-pc APP_DIR --rtps-config FILE [options]')
    parser.add_argument('app_dir', metavar='APP_DIR',
                        help="the app's directory (its Filelists.cmake, else its .c/.cpp files)")
    # The old spelling of mros2-pc-ros: APP_DIR 'ros', then -- CMD.
    parser.add_argument('command', nargs='*', help=argparse.SUPPRESS)
    parser.add_argument('--rtps-config', metavar='FILE',
                        help="the board's rtps/config.h, the one the firmware compiles with")
    parser.add_argument('--receive-limit', metavar='BYTES|FILE:NAME',
                        default=DEFAULT_RECEIVE_LIMIT,
                        help="the largest datagram the board's network stack takes; a larger "
                             "one is cut to it (default %s, mros2-posix' lwIP)"
                             % DEFAULT_RECEIVE_LIMIT)
    parser.add_argument('--mros2-root', metavar='DIR',
                        help='the mros2 checkout, with its embeddedRTPS (default: MROS2_ROOT)')
    _add_peer_max_message(parser)
    parser.add_argument('--lwipopts', metavar='FILE',
                        help="the port's lwipopts.h: the tcpip thread's stack size "
                             '(TCPIP_THREAD_STACKSIZE; default 1024 bytes)')
    parser.add_argument('--board-address', metavar='ADDRESS',
                        help="the board's IPv4 address, on a /24 (default: the config's "
                             "IP_ADDRESS, else mros2-posix' 192.168.11.3)")
    _add_mros2_sources(parser)
    _add_mros2_endpoints(parser, " (default: the app's create_publisher and "
                                 'create_subscription calls)')
    _add_mros2_storage(parser)
    parser.add_argument('--target', choices=PC_TARGETS, default='arm',
                        help="arm: 32-bit ARM Linux, the board's data layout, a static program "
                             'run with qemu-arm, each thread on its board stack size (default); '
                             'native: this PC, host stacks')
    parser.add_argument('--sanitize', action='store_true',
                        help='build with AddressSanitizer and UndefinedBehaviorSanitizer '
                             '(with --target native)')
    patches = parser.add_mutually_exclusive_group()
    patches.add_argument('--hardened', action='store_true',
                         help="build a copy of mros2 with genmros' whole patch series applied "
                              '(genmros mros2-harden); the checkout stays as it is')
    patches.add_argument('--patch', dest='patches', action='append', default=[],
                         metavar='NAME',
                         help='apply only this patch of the series to the copy (repeatable), '
                              'e.g. accept-fast-dds-3-discovery')
    _add_output(parser, 'the build directory (default: APP_DIR/build-mros2-pc-FLAVOUR)',
                dest='build_dir', metavar='DIR')
    parser.add_argument('-j', dest='jobs', type=int, default=os.cpu_count() or 1,
                        help='parallel make jobs (default: the number of CPUs)')
    parser.add_argument('--no-fit-check', action='store_true',
                        help="build even where the endpoints do not fit the board's settings")
    parser.add_argument('-D', dest='app_defines', action='append', default=[],
                        metavar='NAME[=VALUE]',
                        help="a preprocessor definition for the app's sources (repeatable), as "
                             "an app's Filelists.cmake options give them")
    _add_build_only(parser, "on the board's side of its network")
    parser.add_argument('-v', '--verbose', action='store_true',
                        help='show every compiler command')
    parser.set_defaults(run=_mros2_pc)


def _add_mros2_pc_ros(subparsers):
    parser = subparsers.add_parser(
        'mros2-pc-ros', help='run a ROS 2 command on the ROS side of the mros2-pc board that '
                             'runs',
        description="mros2 (ROS 2): run a ROS 2 command on the ROS side of the network of the "
                    'board that genmros mros2-pc runs (for this user), with its ROS_DOMAIN_ID, '
                    'and stop it if the board stops first.',
        usage='genmros mros2-pc-ros [-h] -- CMD [ARG ...]')
    parser.add_argument('command', nargs='*', metavar='CMD',
                        help='the command and its arguments, after --')
    parser.set_defaults(run=_mros2_pc_ros)


def _add_mros2_peer_profile(subparsers):
    from colcon_mros.mros2.rules import PEER_RECEIVE_BUFFER
    parser = subparsers.add_parser(
        'mros2-peer-profile', help="the Fast DDS profile of ROS 2 nodes that talk to a board",
        description="mros2 (ROS 2): write the Fast DDS profile that keeps a ROS 2 node's "
                    "datagrams within an mros2 board's receive limit: a larger sample goes "
                    'out in fragments, which mros2 takes with the patch '
                    'data-frag-for-best-effort-readers. Give it to the nodes with '
                    'FASTDDS_DEFAULT_PROFILES_FILE (Fast DDS 3) or '
                    'FASTRTPS_DEFAULT_PROFILES_FILE (Fast DDS 2), and the same number to the '
                    'fit check (mros2-fit and mros2-export --peer-max-message).')
    largest = parser.add_mutually_exclusive_group(required=True)
    largest.add_argument('--peer-max-message', metavar='BYTES', type=int,
                         help="the largest datagram the nodes send: the board's receive limit")
    largest.add_argument('--max-message', dest='peer_max_message', type=int,
                         action=_OldSpelling, new="'--peer-max-message'")
    parser.add_argument('--receive-buffer', metavar='BYTES', type=int,
                        default=PEER_RECEIVE_BUFFER,
                        help="the nodes' socket receive buffer (default %d: a board's large "
                             'sample comes in fragments of 64 bytes)' % PEER_RECEIVE_BUFFER)
    _add_output(parser, 'the profile file to write (default: standard output)',
                metavar='FILE')
    parser.set_defaults(run=_mros2_peer_profile)


def _add_mros2_mend_wheels(subparsers):
    parser = subparsers.add_parser(
        'mros2-mend-wheels', help="make a venv of ROS 2's wheels fit for CMake builds",
        description="mros2 (ROS 2): point the CMake files of ROS 2's wheels in a venv (PyPI's "
                    "ros-*, on Debian 12) at the venv's own Python and NumPy include "
                    "directories: as built, they name the wheels' builder's "
                    '(/opt/python/cp311-cp311/...), and an interface package of yours that '
                    "builds Python code against the venv stops at CMake's configure. Run it "
                    'again after pip installs more wheels; files already mended are left as '
                    'they are.')
    parser.add_argument('venv', metavar='VENV', help='the venv that holds the wheels')
    parser.set_defaults(run=_mros2_mend_wheels)


SUBCOMMANDS = (_add_generate, _add_mros_v1_export, _add_printers, _add_export_dir_commands,
               _add_mros_v1_pc, _add_mros_v1_fit, _add_mros_v1_harden, _add_mros2_export,
               _add_mros2_fit, _add_mros2_pc, _add_mros2_pc_ros, _add_mros2_harden,
               _add_mros2_peer_profile, _add_mros2_mend_wheels)


def build_parser():
    """genmros' argument parser, and its subcommands' parsers by name."""
    parser = argparse.ArgumentParser(prog='genmros',
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument('--version', action='version', version='genmros %s' % __version__)
    subparsers = _Subcommands(parser.add_subparsers(dest='subcommand', metavar='SUBCOMMAND'))
    for add in SUBCOMMANDS:
        add(subparsers)
    parser.description = DESCRIPTION
    parser.epilog = subparsers.listing() + '\n\nEvery subcommand has --help.'
    return parser, subparsers.action.choices


# What each subcommand runs.

def _generate(options):
    from colcon_mros.ros1.environment import require_ros_python
    require_ros_python()
    from colcon_mros.integrations.catkin_generator import generate_files  # needs genmsg and empy
    from colcon_mros.ros1.workspace import parse_include_flags
    generate_files(options.files, options.package, options.output_dir,
                   parse_include_flags(options.include_paths), options.template_dir,
                   options.export_dir, options.records, options.cmake_module,
                   options.all_of_package)


def _mros2_board(options):
    from colcon_mros.export.mros2_export import Board
    return Board(options.rtps_config, options.receive_limit, options.mros2_root,
                 options.peer_max_message)


def _definition_places(options):
    """(workspaces, prefixes or None) of --workspace, --prefix and the
    old --msg-path, which takes either."""
    from colcon_mros.ros1.workspace import split_msg_paths
    prefixes, workspaces = split_msg_paths(options.msg_paths)
    prefixes = (options.prefixes or []) + prefixes
    return options.workspaces + workspaces, prefixes or None


def _mros2_export(options):
    from colcon_mros.ros2.environment import require_rosidl
    require_rosidl()
    from colcon_mros.export.mros2_export import export_firmware
    options.workspaces, options.prefixes = _definition_places(options)
    result = export_firmware(options.output_dir, options.workspaces, options.prefixes,
                             options.packages, options.types, options.publish, options.subscribe,
                             options.storage, options.option_files, _mros2_board(options),
                             options.serve, options.call)
    for line in result.fit.warnings if result.fit else []:
        print('genmros: warning: %s' % line, file=sys.stderr)
    for line in result.notes:
        print('genmros: note: %s' % line, file=sys.stderr)
    print('genmros: %s, %s in %s (%s changed, %d removed)'
          % (counted(len(result.messages), 'mros2 message type'),
             counted(len(result.services), 'service'), options.output_dir,
             counted(len(result.changed), 'file'), len(result.removed)))


def _mros2_fit(options):
    from colcon_mros.ros2.environment import require_rosidl
    require_rosidl()
    from colcon_mros.export.mros2_export import firmware_fit
    if not (options.publish or options.subscribe or options.serve or options.call):
        raise GenmrosError('name the endpoints: --publish/--subscribe [TOPIC:]PKG/msg/TYPE, '
                           '--serve/--call [NAME:]PKG/srv/TYPE')
    options.workspaces, options.prefixes = _definition_places(options)
    fit = firmware_fit(_mros2_board(options), options.workspaces, options.prefixes,
                       options.publish, options.subscribe, options.storage, options.option_files,
                       options.serve, options.call)
    sys.stdout.write(fit.report())
    return 1 if fit.misfits else 0


def _mros2_peer_profile(options):
    from colcon_mros.core.output import write_file
    from colcon_mros.mros2.render import peer_profile
    from colcon_mros.mros2.rules import discovery_problem
    problem = discovery_problem('--peer-max-message', options.peer_max_message)
    if problem:
        raise GenmrosError(problem)
    profile = peer_profile(options.peer_max_message, options.receive_buffer)
    if options.output is None:
        sys.stdout.write(profile)
        return 0
    write_file(options.output, profile)
    print('genmros: wrote %s' % options.output)
    return 0


def _mros2_mend_wheels(options):
    from colcon_mros.ros2.wheels import mend_wheels
    mended = mend_wheels(options.venv)
    print('genmros: mended %d CMake file(s) of %s' % (len(mended), options.venv))
    return 0


def _mros_v1_export(options):
    from colcon_mros.ros1.environment import require_ros_python
    require_ros_python()
    from colcon_mros.export.firmware_export import ExportRequest, export  # needs genmsg and empy
    workspaces, prefixes = _definition_places(options)
    result = export(ExportRequest(
        output_dir=options.output_dir, prefixes=prefixes, workspaces=workspaces,
        package_names=options.packages, type_names=options.types,
        variable_budget=options.variable_size_budget, template_dir=options.template_dir,
        only=options.only or EXPORT_PARTS[0], record=options.record,
        storage_kind=options.storage, option_files=options.option_files,
        definition_text=options.definition_text, export_dir=options.export_dir,
        library_settings=options.library_settings, fit_strict=options.fit_strict))
    for warning in result.warnings:
        print('genmros: warning: %s' % warning, file=sys.stderr)
    if result.up_to_date:
        if not options.quiet:
            print('genmros: the headers in %s are up to date' % options.output_dir)
    else:
        print('genmros: exported %s and %s to %s'
              % (counted(len(result.messages), 'message type'),
                 counted(len(result.services), 'service type'), options.output_dir))


def _make_fragment(options):
    from colcon_mros.integrations.installed_files import MAKE_FRAGMENT, installed_file
    print(installed_file(MAKE_FRAGMENT))


def _cmake_dir(options):
    from colcon_mros.integrations.installed_files import CMAKE_CONFIG, installed_file
    print(os.path.dirname(installed_file(CMAKE_CONFIG)))


def _catkin_prefix(options):
    from colcon_mros.integrations.installed_files import CATKIN_MARKER, installed_file
    print(os.path.dirname(installed_file(CATKIN_MARKER)))


def _mros_v1_prune_export(options):
    from colcon_mros.export.export_dir import ExportDir
    from colcon_mros.integrations.installed_files import CMAKE_MODULE, installed_file
    if not os.path.isdir(options.export_dir):
        raise GenmrosError('export dir is not a directory', options.export_dir)
    for relative in ExportDir(options.export_dir).prune(installed_file(CMAKE_MODULE)):
        print('genmros: removed %s' % os.path.join(options.export_dir, relative))


def _catkin_export_dir(options):
    from colcon_mros.integrations.catkin_export_dir import configure_export_dir
    configure_export_dir(options.export_dir, options.cmake_file, options.cmake_module)


def _package_paths(options):
    """--workspace, --prefix and --msg-path as the one list of package paths
    an mROS v1 app's build takes (its make fragment's MROS_MSG_PATHS)."""
    for prefix in options.prefixes or []:
        if not os.path.isdir(os.path.join(prefix, 'share')):
            raise GenmrosError('not an installed prefix (no share/): give a source tree with '
                               '--workspace', prefix)
    return options.workspaces + (options.prefixes or []) + options.msg_paths


def _mros_v1_pc(options):
    from colcon_mros.library_tools.mros_v1.pc_target import build
    program = build.build(build.PcBuild(
        app_dir=options.app_dir, mros_root=options.mros_v1_root, target=options.target,
        build_dir=options.build_dir, types=options.types, msg_paths=_package_paths(options),
        storage=options.storage, option_files=options.option_files,
        definition_text=options.definition_text, jobs=options.jobs,
        fit_check=not options.no_fit_check, fit_strict=options.fit_strict,
        sanitize=options.sanitize, hardened=options.hardened, verbose=options.verbose))
    print('genmros: built %s\n  run it with ROS_MASTER_URI and ROS_IP set: %s'
          % (program, ' '.join(build.runner(options.target) + [program])))
    if not options.build_only:
        sys.stdout.flush()
        build.run_program(program, options.target)


def _mros_v1_fit(options):
    from colcon_mros.ros1.environment import require_ros_python
    require_ros_python()
    from colcon_mros.library_tools.mros_v1 import report
    from colcon_mros.library_tools.mros_v1.fit_flow import app_fit, export_dir_fit  # needs genmsg
    from colcon_mros.mros_v1.app import App, find_app
    form = (options.storage, options.option_files)
    if options.export_dir:
        fit, settings = export_dir_fit(options.export_dir, options.types,
                                       options.library_settings, *form)
    elif options.app_dir:
        fit, settings = app_fit(App(*find_app(options.app_dir, options.mros_v1_root)),
                                options.types, _package_paths(options), options.library_settings,
                                *form)
    else:
        raise GenmrosError('give an app directory, or --export-dir')
    text, stops = report.report(fit, settings)
    sys.stdout.write(text)
    return 1 if stops else 0


def _harden(root, patches, options):
    """Apply, check (--check) or take out (--revert) a patch series on root."""
    from colcon_mros.library_tools.patch_series import apply_patches, patch_states
    if options.check:
        states = patch_states(root, patches)
        for patch, applied in states:
            print('%-13s %s: %s' % ('applied' if applied else 'not applied', patch.name,
                                    patch.description))
        return 0 if all(applied for _, applied in states) else 1
    done = apply_patches(root, patches, revert=options.revert)
    verb = 'took out' if options.revert else 'applied'
    print('genmros: %s %s' % (verb, ', '.join(done)) if done else
          'genmros: nothing to do: the patches are %s' % ('out' if options.revert else 'in'))
    return 0


def _mros_v1_harden(options):
    from colcon_mros.library_tools.mros_v1.patches import check_root, mros_v1_patches
    return _harden(check_root(options.mros_v1_root), mros_v1_patches(), options)


def _mros2_pc_ros(options):
    from colcon_mros.library_tools.mros2.pc_target import network
    if not options.command:
        raise GenmrosError('give the command to run on the ROS side: genmros mros2-pc-ros -- CMD')
    return network.run_ros_side(options.command)


def _mros2_pc(options):
    if options.app_dir == 'ros':
        _say_renamed('mros2-pc ros', "'mros2-pc-ros'")
        return _mros2_pc_ros(options)
    if options.command:
        raise GenmrosError('unexpected %s after APP_DIR' % ' '.join(options.command))
    if not options.rtps_config:
        raise GenmrosError("give the board's rtps/config.h: --rtps-config FILE")
    from colcon_mros.library_tools.mros2.pc_target.build import Mros2PcBuild, build
    from colcon_mros.ros2.environment import require_rosidl
    require_rosidl()
    workspaces, prefixes = _definition_places(options)
    program = build(Mros2PcBuild(
        app_dir=options.app_dir, rtps_config=options.rtps_config,
        mros2_root=options.mros2_root, receive_limit=options.receive_limit,
        peer_max_message=options.peer_max_message, publish=options.publish,
        subscribe=options.subscribe, serve=options.serve, call=options.call,
        workspaces=workspaces,
        prefixes=prefixes, storage=options.storage, option_files=options.option_files,
        target=options.target, sanitize=options.sanitize, hardened=options.hardened,
        patches=tuple(options.patches), build_dir=options.build_dir,
        app_defines=tuple(options.app_defines),
        board_address=options.board_address, lwipopts=options.lwipopts,
        fit_check=not options.no_fit_check, jobs=options.jobs, verbose=options.verbose))
    if options.build_only:
        print('genmros: built %s' % program.path)
        return 0
    from colcon_mros.library_tools.mros2.pc_target import network
    return network.run_board(program)


def _mros2_harden(options):
    from colcon_mros.library_tools.mros2.patches import check_root, mros2_patches
    return _harden(check_root(options.mros2_root), mros2_patches(), options)


def main(argv=None):
    argv = sys.argv[1:] if argv is None else list(argv)
    genmros, subcommands = build_parser()
    if argv and argv[0] in RENAMED_SUBCOMMANDS:
        _say_renamed(argv[0], "'%s'" % RENAMED_SUBCOMMANDS[argv[0]])
        argv[0] = RENAMED_SUBCOMMANDS[argv[0]]
    if argv and not argv[0].startswith('-') and argv[0] not in subcommands:
        genmros.print_usage(sys.stderr)
        print("genmros: error: unknown subcommand '%s' (the subcommands: %s)"
              % (argv[0], ', '.join(name for _, names in SUBCOMMAND_GROUPS for name in names)),
              file=sys.stderr)
        return 2
    options, unknown = genmros.parse_known_args(argv)
    if unknown and options.subcommand is not None:
        # The subcommand's usage, not the top level's: it has the options.
        subcommands[options.subcommand].error('unrecognized arguments: %s' % ' '.join(unknown))
    if unknown:
        genmros.error('unrecognized arguments: %s' % ' '.join(unknown))
    if options.subcommand is None:
        genmros.print_usage(sys.stderr)
        print('genmros: error: give a subcommand (genmros --help lists them)', file=sys.stderr)
        return 2
    try:
        return options.run(options) or 0
    except GenmrosError as error:
        for line in str(error).splitlines():
            print('genmros: error: %s' % line, file=sys.stderr)
        return 1
