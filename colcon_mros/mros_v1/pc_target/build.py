"""``genmros mros-v1-pc``: an unmodified mROS v1 app and library on a PC.

Asks make what the app's own ``Makefile`` sets, reads its ``app.cfg`` and
the old generator's JSON file of message types, writes the kernel
configuration for the PC target (:mod:`.asp_cfg`) and runs make with
``mros_v1_pc.mk`` beside this module, in three steps: the checkout's
``mros-lib`` with genmros' headers (through the make fragment) and the
PC target's ASP, lwIP and mbed stand-ins, the app, the link.
"""

import dataclasses
import filecmp
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile

from colcon_mros.errors import GenmrosError
from colcon_mros.generator.defaults import DEFAULT_DEFINITION_TEXT, DEFAULT_STORAGE
from colcon_mros.integrations.installed_files import MAKE_FRAGMENT, installed_file
from colcon_mros.mros_v1.pc_target.asp_cfg import read_config, write_kernel_config
from colcon_mros.mros_v1.rules import SETTINGS_HEADERS

TARGET_DIR = os.path.dirname(os.path.abspath(__file__))
MAKEFILE = os.path.join(TARGET_DIR, 'mros_v1_pc.mk')
# The cross compiler of the arm target and what runs its programs.
ARM_COMPILER = 'arm-linux-gnueabihf-g++'
ARM_RUNNER = 'qemu-arm'
# What --sanitize adds to every compile and the link (native target only).
SANITIZER_FLAGS = '-fsanitize=address,undefined -fno-omit-frame-pointer'
# The steps of a build: (make goal, what the step's line says).
STEPS = (('library', 'the mROS v1 library of %(root)s, the PC target and the message headers'),
         ('app', 'the app %(name)s'),
         ('program', 'link %(program)s'))
# `make -p` prints each variable after the line naming where it was set.
_ORIGIN = re.compile(r"^# makefile \(from '(.*)', line \d+\)$")
_ASSIGNMENT = re.compile(r'^([A-Za-z_][A-Za-z0-9_]*) :{0,2}= ?(.*)$')
_REFERENCE = re.compile(r'\$[({]([A-Za-z_][A-Za-z0-9_]*)[)}]')
_UNDEFINED = re.compile(r"undefined reference to `([A-Za-z_]\w*)'")


@dataclasses.dataclass
class PcBuild:
    """What one ``genmros mros-v1-pc`` is asked for: the app, where it runs
    (target 'arm' or 'native'), the headers' form, and the fit check."""

    app_dir: str
    mros_root: str = None  # default: the checkout the app is in
    target: str = 'arm'
    build_dir: str = None  # default: APP_DIR/build-pc-TARGET
    types: tuple = ()  # default: the app's app.json
    msg_paths: tuple = ()
    storage: str = DEFAULT_STORAGE
    option_files: tuple = ()
    definition_text: str = DEFAULT_DEFINITION_TEXT
    jobs: int = 1
    fit_check: bool = True
    fit_strict: bool = False
    sanitize: bool = False
    hardened: bool = False  # the library with the patch set applied, on a copy
    verbose: bool = False


class App:
    """An mROS v1 app as its Makefile, JSON file and app.cfg describe it."""

    def __init__(self, app_dir, mros_root):
        self.dir = os.path.abspath(app_dir)
        self.mros_root = os.path.abspath(mros_root)
        self.cfg = os.path.join(self.dir, 'app.cfg')
        variables = app_variables(os.path.join(self.dir, 'Makefile'))
        self.name = variables.get('APPNAME') or os.path.basename(self.dir)
        main_source = variables.get('APPLNAME') or 'app'
        # APPLDIR is relative to the app's directory, where its make runs;
        # the sample apps also name a directory that is not there.
        self.source_dirs = [self.dir]
        for name in variables.get('APPLDIR', '').split():
            directory = os.path.normpath(os.path.join(self.dir, name))
            if os.path.isdir(directory) and directory not in self.source_dirs:
                self.source_dirs.append(directory)
        self.objects = ['%s.o' % main_source] + variables.get('APPL_COBJS', '').split() + \
            variables.get('APPL_CXXOBJS', '').split()
        self.cxx_flags = [flag for flag in variables.get('APPL_CXXFLAGS', '').split()
                          if flag.startswith('-')]
        self.c_optimization, self.cxx_optimization = board_optimization(variables)
        self.json_file = variables.get('MSG_SETTING_JSON')

    def message_types(self, types=(), msg_paths=()):
        """(types, package paths) of the app: those given, else those of the
        old generator's JSON file."""
        candidates = [self.json_file] if self.json_file else []
        candidates += ['app.json', 'msg_app.json']
        json_types, json_paths = [], []
        for name in candidates:
            path = os.path.join(self.dir, name)
            if os.path.isfile(path):
                json_types, json_paths = _types_of_json(path, self.dir)
                break
        types = list(types) or json_types
        if not types:
            raise GenmrosError('no message types: the app has no app.json/msg_app.json; give '
                               '--type', self.dir)
        return types, list(msg_paths) or json_paths


def app_variables(makefile, given=()):
    """The variables an app's Makefile sets, as make reads them.

    make runs in an empty directory, so the board's makefiles the app's
    Makefile includes by relative paths (ASP, mbed, mROS) are not there: the
    values are the app's own, references expanded. given: NAME=value
    settings for make's command line."""
    if not os.path.isfile(makefile):
        return {}
    makefile = os.path.abspath(makefile)
    with tempfile.TemporaryDirectory(prefix='genmros-make-') as scratch:
        directory = os.path.join(scratch, 'mros_ws', 'app')
        os.makedirs(directory)
        database = subprocess.run(['make', '-pn', '-f', makefile] + list(given), cwd=directory,
                                  stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True,
                                  env=dict(os.environ, LC_ALL='C')).stdout
    values = {}
    from_app = False
    for line in database.splitlines():
        origin = _ORIGIN.match(line)
        if origin:
            from_app = origin.group(1) == makefile
            continue
        assignment = _ASSIGNMENT.match(line) if from_app else None
        if assignment:
            values[assignment.group(1)] = assignment.group(2)
        from_app = False

    def expand(value, seen):
        return _REFERENCE.sub(lambda reference: expand(values.get(reference.group(1), ''),
                                                       seen | {reference.group(1)})
                              if reference.group(1) not in seen else '', value)
    return {name: expand(value, {name}).strip() for name, value in values.items()}


def board_optimization(variables):
    """(C flags, C++ flags) of optimization that an app's own build gives
    its code and the library's on the board, from its Makefile's variables:
    for C, Makefile.asp's COPTS (-O0, then -O2 unless OMIT_OPTIMIZATION is
    set); for C++, Makefile.mbd's flags, which come after those
    (-DDEBUG -O0 where DEBUG = true, else -DNDEBUG -Os). The samples set
    both: their board build is unoptimized."""
    c_flags = '-O0' if variables.get('OMIT_OPTIMIZATION') else '-O2'
    cxx_flags = '-DDEBUG -O0' if variables.get('DEBUG') == 'true' else '-DNDEBUG -Os'
    return c_flags, cxx_flags


def library_settings(app):
    """The headers that set the library's settings, as the build includes
    them: the app's mros_usr_config.h (its mros_config/, else the library's
    default) and the library's mros_packet_config.h (of its ROS_VERSION)."""
    library = os.path.join(app.mros_root, 'mros-lib')
    variables = app_variables(os.path.join(library, 'Makefile.m'), ['MROS_DIR=' + library])
    include_dirs = [flag[2:] for flag in variables.get('MROS_INCLUDE_PATHS', '').split()
                    if flag.startswith('-I')]
    found = []
    for name in SETTINGS_HEADERS:
        paths = [os.path.join(directory, name) for directory in app.source_dirs + include_dirs]
        paths = [path for path in paths if os.path.isfile(path)]
        if not paths:
            raise GenmrosError('the library and the app have no %s (give --no-fit-check to build '
                               'without the fit check)' % name, app.mros_root)
        found.append(paths[0])
    return found


def _types_of_json(path, app_dir):
    try:
        with open(path, encoding='utf-8') as stream:
            settings = json.load(stream)
        headers = settings.get('including_msgs', [])
        catkin_ws = settings.get('catkin_ws_dir')
    except (OSError, ValueError, AttributeError) as error:
        raise GenmrosError('not the JSON file of mROS v1\'s message generator: %s' % error, path)
    types = [re.sub(r'\.h\Z', '', header) for header in headers]
    paths = []
    if catkin_ws:
        workspace = os.path.normpath(os.path.join(app_dir, catkin_ws))
        if os.path.isdir(workspace):
            paths.append(workspace)
    return types, paths


def find_mros_root(app_dir, given):
    """The mROS v1 checkout: given, else the one the app sits in (mros_ws/<app>)."""
    candidate = given or os.path.join(app_dir, os.pardir, os.pardir)
    if not os.path.isfile(os.path.join(candidate, 'mros-lib', 'Makefile.m')):
        where = given or os.path.normpath(candidate)
        raise GenmrosError('no mROS v1 checkout here (no mros-lib/Makefile.m)%s'
                           % ('' if given else '; give --mros-root'), where)
    return os.path.abspath(candidate)


def find_app(app_dir, mros_root=None):
    """(app dir, mROS v1 checkout) of the app in app_dir (with its app.cfg),
    in the checkout mros_root (default: the one it sits in)."""
    if not os.path.isdir(app_dir):
        raise GenmrosError('no such directory', app_dir)
    if not os.path.isfile(os.path.join(app_dir, 'app.cfg')):
        raise GenmrosError('no app.cfg: not an mROS v1 app', app_dir)
    app_dir = os.path.abspath(app_dir)
    return app_dir, find_mros_root(app_dir, mros_root)


def hardened_library(mros_root, build_dir):
    """The root of a copy of mros_root's mros-lib in build_dir with the patch
    set applied; a file whose text is the same as at the last build keeps
    its time, so that make rebuilds only what changed."""
    from colcon_mros.mros_v1.patches.patch_set import LIBRARY_DIR, apply_patches
    root = os.path.join(build_dir, 'hardened')
    os.makedirs(build_dir, exist_ok=True)
    with tempfile.TemporaryDirectory(prefix='genmros-hardened-', dir=build_dir) as scratch:
        shutil.copytree(os.path.join(mros_root, LIBRARY_DIR), os.path.join(scratch, LIBRARY_DIR))
        apply_patches(scratch)
        for directory, _, names in os.walk(os.path.join(scratch, LIBRARY_DIR)):
            target = os.path.join(root, os.path.relpath(directory, scratch))
            os.makedirs(target, exist_ok=True)
            for name in names:
                source, copy = os.path.join(directory, name), os.path.join(target, name)
                if not os.path.isfile(copy) or not filecmp.cmp(source, copy, shallow=False):
                    shutil.copy2(source, copy)
    return root


def check_tools(target, sanitize):
    if sanitize and target != 'native':
        raise GenmrosError('--sanitize needs --target native (qemu-arm runs no sanitizer)')
    compiler = ARM_COMPILER if target == 'arm' else 'g++'
    if shutil.which(compiler) is None:
        raise GenmrosError('%s not found: install %s' % (
            compiler, 'g++-arm-linux-gnueabihf (or use --target native)'
            if target == 'arm' else 'g++'))
    if shutil.which('make') is None:
        raise GenmrosError('make not found: install make')


def runner(target):
    """The command that runs a program built for target on this PC."""
    return [ARM_RUNNER] if target == 'arm' else []


def _unresolved_task(config, linker_output):
    """The GenmrosError for a task or handler app.cfg names that no object
    file defines, from the linker's complaint; None if it is not that."""
    missing = set(_UNDEFINED.findall(linker_output))
    for kernel_object in config.objects:
        function = kernel_object.fields.get('task') or kernel_object.fields.get('handler')
        if function in missing:
            return GenmrosError('%s runs %s(), which no source of the app defines (the linker '
                                'found no definition)' % (kernel_object.name, function),
                                kernel_object.path, kernel_object.line)
    return None


def app_fit(app, types, msg_paths, settings_files, storage_kind, option_files):
    """The Fit of an App's types (those given, else its app.json's) to its
    settings (those given, else the headers its build includes), and the
    settings headers read: the one fit flow of genmros mros-v1-pc and
    genmros mros-v1-fit."""
    # genmsg: the types' models
    from colcon_mros.export.firmware_export import firmware_messages
    from colcon_mros.mros_v1.fit import Fit
    from colcon_mros.mros_v1.settings import read_settings
    types, msg_paths = app.message_types(types, msg_paths)
    settings_files = list(settings_files) or library_settings(app)
    messages = firmware_messages(types, msg_paths, storage_kind, option_files)
    return Fit(messages, read_settings(settings_files)), settings_files


def build(request):
    """Builds a PcBuild's app in steps, one line each; returns the program's path."""
    app_dir, mros_root = find_app(request.app_dir, request.mros_root)
    check_tools(request.target, request.sanitize)  # make reads the app's Makefile next
    app = App(app_dir, mros_root)
    # The library's mros.cfg is on the search path, as in ASP's own build.
    config = read_config(app.cfg, [os.path.join(app.mros_root, 'mros-lib'),
                                   os.path.join(TARGET_DIR, 'cfg', 'asp')])
    types, msg_paths = app.message_types(request.types, request.msg_paths)
    if request.fit_check:
        from colcon_mros.generator.ros_environment import require_ros_python
        require_ros_python()
        fit, _ = app_fit(app, types, msg_paths, (), request.storage, request.option_files)
        fit.refuse(request.fit_strict)
        for warning in fit.warnings:
            print('genmros: warning: %s' % warning)
    flavour = request.target + ('-sanitize' if request.sanitize else '') + \
        ('-hardened' if request.hardened else '')
    build_dir = os.path.abspath(request.build_dir or os.path.join(app.dir, 'build-pc-' + flavour))
    write_kernel_config(config, os.path.join(build_dir, 'cfg'))
    library_root = hardened_library(app.mros_root, build_dir) if request.hardened else app.mros_root
    variables = {
        'MROS_ROOT': library_root, 'APP_NAME': app.name, 'APP_DIRS': ' '.join(app.source_dirs),
        'APP_OBJS': ' '.join(app.objects), 'APP_CXXFLAGS': ' '.join(app.cxx_flags),
        'BOARD_C_OPTIMIZATION': app.c_optimization,
        'BOARD_CXX_OPTIMIZATION': app.cxx_optimization,
        'TARGET': request.target, 'BUILD': build_dir,
        'SANITIZER_FLAGS': SANITIZER_FLAGS if request.sanitize else '',
        'MROS_MSG_TYPES': ' '.join(types),
        'MROS_MSG_PATHS': ' '.join(msg_paths),
        'MROS_MSG_DEFINITION_TEXT': request.definition_text,
        'MROS_MSG_FLAGS': ' '.join(['--storage', request.storage] + [
            '--options %s' % os.path.abspath(path) for path in request.option_files]),
        'FIT_CHECK_FLAGS': '-DMROS_SKIP_FIT_CHECK' if not request.fit_check else '',
        'GENMROS': 'env PYTHONPATH=%s %s -m colcon_mros' % (
            os.path.dirname(os.path.dirname(os.path.dirname(TARGET_DIR))), sys.executable),
        'GENMROS_MK': installed_file(MAKE_FRAGMENT),
    }
    command = ['make', '--no-print-directory', '-f', MAKEFILE, '-j%d' % request.jobs] + \
        ([] if request.verbose else ['-s']) + ['%s=%s' % item for item in sorted(variables.items())]
    program = os.path.join(build_dir, app.name)
    words = {'root': app.mros_root + (' (hardened)' if request.hardened else ''),
             'name': app.name, 'program': program}
    for goal, line in STEPS:
        print('genmros: %s' % (line % words), flush=True)
        if goal != 'program':
            if subprocess.call(command + [goal]) != 0:
                raise GenmrosError('building %s for the PC failed (see the compiler\'s output '
                                   'above)' % app.name, app.dir)
            continue
        linked = subprocess.run(command + [goal], stdout=subprocess.PIPE,
                                stderr=subprocess.STDOUT, text=True)
        if linked.returncode != 0:
            error = _unresolved_task(config, linked.stdout)
            if error is None:
                sys.stdout.write(linked.stdout)
                error = GenmrosError('linking %s failed (see the linker\'s output above)'
                                     % app.name, app.dir)
            raise error
        sys.stdout.write(linked.stdout)
    return program


def run_program(program, target):
    """Replaces this process with the program (ROS_MASTER_URI etc. as set)."""
    command = runner(target) + [program]
    os.execvp(command[0], command)
