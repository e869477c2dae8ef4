# SPDX-License-Identifier: BSD-3-Clause
"""``genmros mros2-pc``'s build: an mros2 app and the user's mros2 for a PC.

Reads the library's sources and include directories from the checkout's
``CMakeLists.txt``, the app's sources (its ``Filelists.cmake`` as
mros2-posix writes one, else its C and C++ files) and endpoints (the
``create_publisher<T>("topic")`` and ``create_subscription<T>("topic")``
calls in them, unless given); runs the fit check and writes genmros'
headers and ``templates.hpp``; makes the one change the board's
``rtps/config.h`` needs to fit the mros2 (on a copy, printed); writes the
stand-ins' settings (``mros2_pc_settings.h``: the board's address, receive
limit and the settings that size each thread's stack); and runs make with
``mros2_pc.mk`` in three steps: the library with the stand-ins, the app,
the link.
"""

import dataclasses
import os
import re
import subprocess
import sys

from colcon_mros.core.cpp_literals import cpp_string_literal_lines
from colcon_mros.core.defaults import DEFAULT_STORAGE
from colcon_mros.core.output import write_files
from colcon_mros.core.settings import read_settings
from colcon_mros.errors import GenmrosError
from colcon_mros.library_tools.mros2.patches import check_root, mros2_patches
from colcon_mros.library_tools.pc_build import (SANITIZER_FLAGS, check_tools, flags_stamp,
                                                patched_copy, runner)
from colcon_mros.mros2.rules import PEER_MAX_MESSAGE

TARGET_DIR = os.path.dirname(os.path.abspath(__file__))
MAKEFILE = os.path.join(TARGET_DIR, 'mros2_pc.mk')
# The board's network: mros2-posix' address and netmask (its include/netif.h).
DEFAULT_BOARD_ADDRESS = '192.168.11.3'
BOARD_NETMASK = '255.255.255.0'
# The datagram mros2-posix' lwIP takes at most (MAX_RECV_PACKET_SIZE).
DEFAULT_RECEIVE_LIMIT = '4096'
# The tcpip thread's stack where no lwipopts.h is given: STM32CubeMX's lwIP
# default with CMSIS-RTOS2, whose sys_thread_new passes it on in bytes.
DEFAULT_TCPIP_STACK_SIZE = 1024
# What sizes each thread's stack: embeddedRTPS' threads by the name its
# sys_thread_new calls give, each a setting of rtps/config.h.
EMBEDDED_RTPS_THREADS = (('WriterThread', 'THREAD_POOL_WRITER_STACKSIZE'),
                         ('ReaderThread', 'THREAD_POOL_READER_STACKSIZE'),
                         ('SPDPThread', 'SPDP_WRITER_STACKSIZE'),
                         ('HBThread', 'HEARTBEAT_STACKSIZE'),
                         ('HBThreadPub', 'HEARTBEAT_STACKSIZE'),
                         ('HBThreadSub', 'HEARTBEAT_STACKSIZE'))
MROS2_THREAD = 'mROS2Thread'
TCPIP_THREAD = 'tcpip_thread'
# What a patched copy of the library holds.
LIBRARY_FILES = ('CMakeLists.txt', 'include', 'src', 'embeddedRTPS')
STEPS = (('library', 'mros2 of %(root)s and the PC target\'s stand-ins'),
         ('app', 'the app %(name)s'),
         ('program', 'link %(program)s'))
_SOURCE = re.compile(r'\$\{PROJECT_SOURCE_DIR\}/([^\s)]+)')
_ENDPOINT = re.compile(r'\bcreate_(publisher|subscription|service|client)\s*<\s*'
                       r'([A-Za-z_][\w:]*)\s*>\s*'
                       r'\(\s*"([^"]*)"\s*(?:,\s*((?:mros2::)?QoS\s*\([^()]*\)'
                       r'(?:\s*\.\s*\w+\s*\([^()]*\))*))?')
# A QoS as the patch reliable-where-asked spells it: QoS(depth), then calls in a chain.
_QOS_DEPTH = re.compile(r'QoS\s*\(\s*(\d+)\s*\)')
_QOS_CALL = re.compile(r'\.\s*(reliable|best_effort|keep_last)\s*\(\s*(\d*)\s*\)')
_UNDEFINED = re.compile(r"undefined reference to `([^']+)'")
# mros2 >= 0.5 defines the address embeddedRTPS announces (src/mros2.cpp).
_MROS2_ADDRESS = re.compile(r'^\s*std::array<uint8_t,\s*4>\s+IP_ADDRESS\s*;', re.M)
_CONFIG_ADDRESS = re.compile(r'^([ \t]*)const\s+std::array<uint8_t,\s*4>\s+IP_ADDRESS\s*=\s*'
                             r'\{([^}]*)\}\s*;[^\n]*', re.M)
_STACK_SIZE = re.compile(r'\.stack_size\s*=\s*(\d+)')


@dataclasses.dataclass
class Mros2PcBuild:
    """What one ``genmros mros2-pc`` is asked to build."""

    app_dir: str
    rtps_config: str
    mros2_root: str = None  # default: MROS2_ROOT
    receive_limit: str = DEFAULT_RECEIVE_LIMIT
    peer_max_message: int = PEER_MAX_MESSAGE  # the ROS side's largest datagram
    publish: tuple = ()  # default: the app's own create_publisher calls
    subscribe: tuple = ()
    serve: tuple = ()  # NAME:PKG/srv/TYPE; default: the app's own create_service calls
    call: tuple = ()
    workspaces: tuple = ()
    prefixes: tuple = None
    storage: str = DEFAULT_STORAGE
    option_files: tuple = ()
    target: str = 'arm'
    sanitize: bool = False
    hardened: bool = False  # the whole series; else the patches named
    patches: tuple = ()
    build_dir: str = None  # default: APP_DIR/build-mros2-pc-FLAVOUR
    app_defines: tuple = ()  # NAME or NAME=VALUE, for the app's sources
    extra_flags: tuple = ()  # for every compile and the link (--coverage, say)
    board_address: str = None  # default: the config's IP_ADDRESS, else mros2-posix'
    lwipopts: str = None
    fit_check: bool = True
    jobs: int = 1
    verbose: bool = False


@dataclasses.dataclass
class Mros2Program:
    """A built program: its path, how to run it, and the board's network."""

    path: str
    command: list
    board_address: str
    domain_id: int


def _read(path, role):
    try:
        with open(path, encoding='utf-8', errors='replace') as stream:
            return stream.read()
    except OSError as error:
        raise GenmrosError('cannot read %s: %s' % (role, error.strerror), path)


def _line_of(text, offset):
    return text.count('\n', 0, offset) + 1


def library_layout(root):
    """(sources, include directories) of the mros2 checkout root, as its
    CMakeLists.txt's target_sources and target_include_directories list them."""
    cmake = os.path.join(root, 'CMakeLists.txt')
    text = _read(cmake, "the mros2 checkout's CMakeLists.txt")
    lists = {}
    for command in ('target_sources', 'target_include_directories'):
        match = re.search(r'\b%s\s*\(\s*mros2\b([^)]*)\)' % command, text)
        if match is None:
            raise GenmrosError('no %s(mros2 ...): genmros mros2-pc reads the library\'s files '
                               'there' % command, cmake)
        lists[command] = [os.path.join(root, path) for path in _SOURCE.findall(match.group(1))]
    missing = [path for path in lists['target_sources'] if not os.path.isfile(path)]
    if missing:
        raise GenmrosError('the checkout lacks %s, which its CMakeLists.txt lists (is '
                           'embeddedRTPS checked out?)' % ', '.join(missing), root)
    includes = [path for path in lists['target_include_directories']
                if not path.endswith('mros2_msgs')]  # genmros' headers stand in for them
    return lists['target_sources'], includes


def app_sources(app_dir):
    """The app's sources: those its Filelists.cmake names (mros2-posix'),
    else its .c and .cpp files."""
    filelists = os.path.join(app_dir, 'Filelists.cmake')
    if os.path.isfile(filelists):
        names = re.findall(r'/([^/\s)]+\.(?:c|cc|cpp))\b', _read(filelists, "the app's list"))
    else:
        names = sorted(name for name in os.listdir(app_dir) if name.endswith(('.c', '.cpp')))
    if not names:
        raise GenmrosError('no C or C++ source here: not an mros2 app', app_dir)
    sources = [os.path.join(app_dir, name) for name in names]
    missing = [path for path in sources if not os.path.isfile(path)]
    if missing:
        raise GenmrosError('lists %s, which is not there' % ', '.join(missing), filelists)
    return sources


def _qos_suffix(qos):
    """The endpoint text's QoS for an app's QoS argument: ':reliable:DEPTH' where its calls
    end reliable, '' where best-effort (mros2's int, too)."""
    depth = _QOS_DEPTH.search(qos)
    depth = depth.group(1) if depth else ''
    reliable = False
    for call, argument in _QOS_CALL.findall(qos):
        if call == 'keep_last':
            depth = argument
        else:
            reliable = call == 'reliable'
    return ':reliable:%s' % depth if reliable and depth else ''


def app_endpoints(sources):
    """(publish, subscribe, serve, call): TOPIC:PKG/msg/TYPE[:reliable:DEPTH] texts from the
    app's create_publisher<T>("topic", qos) and create_subscription<T>("topic", qos) calls,
    NAME:PKG/srv/TYPE texts from its create_service<T>("name", ...) and
    create_client<T>("name") calls."""
    found = {'publisher': [], 'subscription': [], 'service': [], 'client': []}
    for path in sources:
        for kind, cpp_type, topic, qos in _ENDPOINT.findall(_read(path, 'an app source')):
            endpoint = '%s:%s%s' % (topic, cpp_type.lstrip(':').replace('::', '/'),
                                    _qos_suffix(qos))
            if endpoint not in found[kind]:
                found[kind].append(endpoint)
    return found['publisher'], found['subscription'], found['service'], found['client']


def _check_unique_names(group, sources):
    seen = {}
    for path in sources:
        name = os.path.splitext(os.path.basename(path))[0]
        if name in seen:
            raise GenmrosError('%s and %s share the name %s: the PC target needs the names of '
                               "the %s's sources to differ" % (seen[name], path, name, group))
        seen[name] = path


class BoardConfig:
    """The board's rtps/config.h as mros2 compiles it: the file, its
    settings, and the copy genmros writes where it must change it."""

    def __init__(self, path, mros2_root):
        self.path = os.path.abspath(path)
        self.text = _read(self.path, "the board's rtps/config.h (--rtps-config)")
        self.settings = read_settings([self.path], "the board's rtps/config.h (--rtps-config)")
        address = _CONFIG_ADDRESS.search(self.text)
        self.address = '.'.join(part.strip() for part in address.group(2).split(',')) \
            if address else None
        self.change = None
        mros2_cpp = os.path.join(mros2_root, 'src', 'mros2.cpp')
        defined = _MROS2_ADDRESS.search(_read(mros2_cpp, "mros2's src/mros2.cpp"))
        if defined and address:
            self.change = (
                '%s:%d: rtps::Config::IP_ADDRESS is defined by this mros2 too (%s:%d), which '
                'sets it at start-up: the copy declares it, extern std::array<uint8_t, 4> '
                'IP_ADDRESS;' % (self.path, _line_of(self.text, address.start()), mros2_cpp,
                                 _line_of(defined.string, defined.start())))
            self.text = self.text[:address.start()] + address.group(1) + \
                'extern std::array<uint8_t, 4> IP_ADDRESS;' + self.text[address.end():]
        self.sets_address = bool(defined)

    def directory(self, build_dir):
        """The include directory with rtps/config.h as mros2 compiles it."""
        if self.change is None:
            return os.path.dirname(os.path.dirname(self.path))
        directory = os.path.join(build_dir, 'config')
        write_files(directory, {os.path.join('rtps', 'config.h'): self.text})
        return directory

    def setting_text(self, name):
        setting = self.settings.get(name)
        if setting is None:
            return 'rtps::Config::%s' % name
        return 'rtps::Config::%s, %s' % (name, setting.where())


def _tcpip_stack(lwipopts):
    """(size, where it is set) of the tcpip thread's stack."""
    if lwipopts is None:
        return DEFAULT_TCPIP_STACK_SIZE, (
            "TCPIP_THREAD_STACKSIZE, genmros' default %d (--lwipopts gives the port's)"
            % DEFAULT_TCPIP_STACK_SIZE)
    settings = read_settings([lwipopts], "the port's lwipopts.h (--lwipopts)")
    setting = settings.get('TCPIP_THREAD_STACKSIZE')
    if setting is None:
        raise GenmrosError('sets no TCPIP_THREAD_STACKSIZE (--lwipopts)', lwipopts)
    return setting.value, 'TCPIP_THREAD_STACKSIZE, %s' % setting.where()


def _mros2_thread_setting(mros2_root):
    path = os.path.join(mros2_root, 'src', 'mros2.cpp')
    text = _read(path, "mros2's src/mros2.cpp")
    match = _STACK_SIZE.search(text)
    where = '%s:%d' % (path, _line_of(text, match.start())) if match else path
    return 'the stack_size mros2::init gives it, %s' % where


def settings_header(board_address, receive_limit, tcpip_stack, thread_settings, domain_id):
    """mros2_pc_settings.h: what the stand-ins take from genmros."""
    rows = ',\n'.join('  {%s, %s}' % (cpp_string_literal_lines(name)[0],
                                      ' '.join(cpp_string_literal_lines(setting)))
                      for name, setting in thread_settings)
    return ('// Written by genmros mros2-pc: the PC target\'s settings for this board.\n'
            '#ifndef MROS2_PC_SETTINGS_H\n#define MROS2_PC_SETTINGS_H\n\n'
            '#define MROS2_PC_BOARD_ADDRESS "%s"\n#define MROS2_PC_BOARD_NETMASK "%s"\n'
            '#define MROS2_PC_DOMAIN_ID %d\n'
            '#define MROS2_PC_RECEIVE_LIMIT %d\n#define MROS2_PC_TCPIP_STACK_SIZE %d\n'
            '// Which setting sizes each thread\'s stack.\n'
            '#define MROS2_PC_THREAD_SETTINGS \\\n%s\n\n#endif\n'
            % (board_address, BOARD_NETMASK, domain_id, receive_limit, tcpip_stack,
               rows.replace('\n', ' \\\n')))


def _flavour(request):
    patches = 'hardened' if request.hardened else '+'.join(request.patches)
    return '-'.join(part for part in (request.target, 'sanitize' if request.sanitize else '',
                                      patches) if part)


def _library_root(request, build_dir):
    """The mros2 the program is built from: the checkout, or a patched copy."""
    root = os.path.abspath(request.mros2_root or os.environ.get('MROS2_ROOT') or '')
    if not request.mros2_root and not os.environ.get('MROS2_ROOT'):
        raise GenmrosError('name the mros2 checkout: --mros2-root DIR or MROS2_ROOT')
    check_root(root)
    series = mros2_patches()
    if request.hardened:
        chosen = series
    else:
        names = [patch.name for patch in series]
        unknown = [name for name in request.patches if name not in names]
        if unknown:
            raise GenmrosError('no patch %s in the mros2 series (%s)'
                               % (', '.join(unknown), ', '.join(names)))
        chosen = [patch for patch in series if patch.name in request.patches]
    if not chosen:
        return root, root
    copy = patched_copy(root, LIBRARY_FILES, chosen, os.path.join(build_dir, 'mros2'))
    print('genmros: mros2 of %s with %s, on a copy in %s'
          % (root, ', '.join(patch.name for patch in chosen), copy), flush=True)
    return root, copy


def _run_steps(request, variables, words, app_dir):
    command = ['make', '--no-print-directory', '-f', MAKEFILE, '-j%d' % request.jobs] + \
        ([] if request.verbose else ['-s']) + \
        ['%s=%s' % item for item in sorted(variables.items())]
    for goal, line in STEPS:
        print('genmros: %s' % (line % words), flush=True)
        if goal != 'program':
            if subprocess.call(command + [goal]) != 0:
                raise GenmrosError("building %s for the PC failed (see the compiler's output "
                                   'above)' % words['name'], app_dir)
            continue
        linked = subprocess.run(command + [goal], stdout=subprocess.PIPE,
                                stderr=subprocess.STDOUT, text=True)
        sys.stdout.write(linked.stdout)
        if linked.returncode != 0:
            missing = sorted(set(_UNDEFINED.findall(linked.stdout)))
            if missing:
                raise GenmrosError(
                    'linking %s failed: %s called and defined neither by the app, nor by the '
                    "mros2 checkout, nor by the PC target's stand-ins (docs/mros2.md lists what "
                    'they define; mros2 v0.5.4 and v0.4.1 need nothing more)'
                    % (words['name'], ', '.join(missing)), app_dir)
            raise GenmrosError("linking %s failed (see the linker's output above)"
                               % words['name'], app_dir)


def build(request):
    """Builds a Mros2PcBuild's program in steps, one line each; returns a Mros2Program."""
    from colcon_mros.export.mros2_export import Board, export_firmware
    from colcon_mros.mros2.fit import receive_limit
    check_tools(request.target, request.sanitize)
    app_dir = os.path.abspath(request.app_dir)
    if not os.path.isdir(app_dir):
        raise GenmrosError('no such app directory', app_dir)
    name = os.path.basename(app_dir)
    build_dir = os.path.abspath(request.build_dir or os.path.join(
        app_dir, 'build-mros2-pc-' + _flavour(request)))
    user_root, root = _library_root(request, build_dir)
    library, include_dirs = library_layout(root)
    sources = app_sources(app_dir)
    _check_unique_names('library', library)
    _check_unique_names('app', sources)

    publish, subscribe, serve, call = (request.publish, request.subscribe, request.serve,
                                       request.call)
    if not (publish or subscribe or serve or call):
        publish, subscribe, serve, call = app_endpoints(sources)
        if not (publish or subscribe or serve or call):
            raise GenmrosError('no create_publisher<T>("topic"), create_subscription<T>('
                               '"topic"), create_service<T>("name") or create_client<T>("name") '
                               'call in the app: name its endpoints with --publish/--subscribe '
                               'TOPIC:PKG/msg/TYPE, --serve/--call NAME:PKG/srv/TYPE', app_dir)
        print('genmros: the app\'s endpoints: %s'
              % ', '.join(['publish %s' % e for e in publish] +
                          ['subscribe %s' % e for e in subscribe] +
                          ['serve %s' % e for e in serve] + ['call %s' % e for e in call]),
              flush=True)
    config = BoardConfig(request.rtps_config, root)
    limit = receive_limit(request.receive_limit)
    board = Board(config.path, request.receive_limit, root,
                  request.peer_max_message) if request.fit_check else None
    exported = export_firmware(os.path.join(build_dir, 'include'), request.workspaces,
                               request.prefixes, (), (), publish, subscribe, request.storage,
                               request.option_files, board, serve, call)
    # What might not fit, as genmros mros2-fit says it (the misfits stopped the build).
    for line in exported.fit.warnings if exported.fit else []:
        print('genmros: warning: %s' % line, file=sys.stderr, flush=True)
    if config.change:
        print('genmros: %s' % config.change, flush=True)

    board_address = request.board_address or config.address or DEFAULT_BOARD_ADDRESS
    if config.address and not config.sets_address and config.address != board_address:
        raise GenmrosError('rtps::Config::IP_ADDRESS is %s, which embeddedRTPS announces: the '
                           "board side's address must be it (--board-address %s)"
                           % (config.address, config.address), config.path)
    domain = config.settings.get('DOMAIN_ID')
    domain_id = domain.value if domain else 0
    tcpip_size, tcpip_where = _tcpip_stack(request.lwipopts)
    thread_settings = [(thread, config.setting_text(setting))
                       for thread, setting in EMBEDDED_RTPS_THREADS]
    thread_settings.append((MROS2_THREAD, _mros2_thread_setting(root)))
    thread_settings.append((TCPIP_THREAD, tcpip_where))
    write_files(os.path.join(build_dir, 'settings'), {'mros2_pc_settings.h': settings_header(
        board_address, limit.value, tcpip_size, thread_settings, domain_id)})

    program = os.path.join(build_dir, name)
    variables = {
        'MROS2_SOURCES': ' '.join(library), 'MROS2_INCLUDE_DIRS': ' '.join(include_dirs),
        'APP_SOURCES': ' '.join(sources), 'APP_DIR': app_dir,
        'CONFIG_DIR': config.directory(build_dir), 'TARGET': request.target,
        'BUILD': build_dir, 'PROGRAM': name,
        'SANITIZER_FLAGS': ' '.join(([SANITIZER_FLAGS] if request.sanitize else []) +
                                    list(request.extra_flags)),
        'STAND_IN_FLAGS': '-DMROS2_PC_SETS_RTPS_ADDRESS' if config.sets_address else '',
        'APP_FLAGS': ' '.join('-D' + define for define in request.app_defines),
    }
    variables['FLAGS_STAMP'] = flags_stamp(build_dir, {
        name: variables[name] for name in ('CONFIG_DIR', 'TARGET', 'SANITIZER_FLAGS',
                                           'STAND_IN_FLAGS', 'APP_FLAGS', 'MROS2_INCLUDE_DIRS')})
    words = {'root': user_root + (' (patched copy)' if root != user_root else ''),
             'name': name, 'program': program}
    _run_steps(request, variables, words, app_dir)
    return Mros2Program(program, runner(request.target) + [program], board_address, domain_id)
