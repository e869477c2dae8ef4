"""``genmros mros-v1-pc``: an unmodified mROS v1 app and library on a PC.

Reads what the app's own build reads (its ``Makefile``, ``app.cfg`` and
the old generator's JSON file of message types), checks it, writes the
kernel configuration for the PC target (:mod:`colcon_mros.asp_cfg`) and
runs make with ``pc_target/mros_v1_pc.mk``, which builds the checkout's
``mros-lib`` and the app against genmros' headers (through the make
fragment) and the PC target's ASP, lwIP and mbed.
"""

import glob
import json
import os
import re
import shutil
import subprocess
import sys

from colcon_mros.asp_cfg import IDENTIFIER, read_config, write_kernel_config
from colcon_mros.errors import GenmrosError
from colcon_mros.installed_files import MAKE_FRAGMENT, PC_TARGET_MAKEFILE, installed_file

# The cross compiler of the arm target and what runs its programs.
ARM_COMPILER = 'arm-linux-gnueabihf-g++'
ARM_RUNNER = 'qemu-arm'
# The Makefile variables of an mROS v1 app this reads (mros_ws/<app>/Makefile).
_MAKE_VARIABLE = re.compile(r'^\s*([A-Z_]+)\s*[:+]?=[ \t]*(.*?)\s*$', re.M)


class App:
    """An mROS v1 app as its Makefile, JSON file and app.cfg describe it."""

    def __init__(self, app_dir, mros_root):
        self.dir = os.path.abspath(app_dir)
        self.mros_root = os.path.abspath(mros_root)
        self.cfg = os.path.join(self.dir, 'app.cfg')
        variables = _make_variables(os.path.join(self.dir, 'Makefile'))
        self.name = variables.get('APPNAME') or os.path.basename(self.dir)
        main_source = variables.get('APPLNAME', 'app')
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
        self.json_file = variables.get('MSG_SETTING_JSON')

    def message_types(self):
        """(types, package paths) from the old generator's JSON file."""
        candidates = [self.json_file] if self.json_file else []
        candidates += ['app.json', 'msg_app.json']
        for name in candidates:
            path = os.path.join(self.dir, name)
            if os.path.isfile(path):
                return _types_of_json(path, self.dir)
        return [], []

    def sources(self):
        found = []
        for directory in self.source_dirs:
            for pattern in ('*.c', '*.cpp'):
                found.extend(sorted(glob.glob(os.path.join(directory, pattern))))
        return found


def _make_variables(makefile):
    try:
        with open(makefile, encoding='utf-8', errors='replace') as stream:
            text = stream.read()
    except OSError:
        return {}
    variables = {}
    for name, value in _MAKE_VARIABLE.findall(text):
        value = value.replace('$(%s)' % name, '').strip()
        variables[name] = (variables.get(name, '') + ' ' + value).strip() \
            if name.startswith('APPL_') else value
    return variables


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


def check_tasks(app, config):
    """Every task and cyclic handler app.cfg names has a definition among the
    app's sources (the library's tasks are in its mros_config/)."""
    text = ''
    for source in app.sources():
        with open(source, encoding='utf-8', errors='replace') as stream:
            text += stream.read()
    for kernel_object in config.objects:
        function = kernel_object.fields.get('task') or kernel_object.fields.get('handler')
        if function is None or not IDENTIFIER.match(function):
            continue
        if not re.search(r'\b%s\s*\([^;{)]*\)\s*\{' % re.escape(function), text):
            raise GenmrosError('%s runs %s(), which no source of the app defines (%s)'
                               % (kernel_object.name, function,
                                  ' '.join(os.path.relpath(directory, app.dir)
                                           for directory in app.source_dirs)),
                               kernel_object.path, kernel_object.line)


def check_tools(target):
    compiler = ARM_COMPILER if target == 'arm' else 'g++'
    if shutil.which(compiler) is None:
        raise GenmrosError('%s not found: install %s' % (
            compiler, 'g++-arm-linux-gnueabihf (or use --target native)' if target == 'arm'
            else 'g++'))
    if shutil.which('make') is None:
        raise GenmrosError('make not found: install make')


def runner(target):
    """The command that runs a program built for target on this PC."""
    return [ARM_RUNNER] if target == 'arm' else []


def build(options):
    """Builds the app; returns the program's path."""
    app_dir = os.path.abspath(options.app_dir)
    if not os.path.isdir(app_dir):
        raise GenmrosError('no such directory', options.app_dir)
    if not os.path.isfile(os.path.join(app_dir, 'app.cfg')):
        raise GenmrosError('no app.cfg: not an mROS v1 app', options.app_dir)
    app = App(app_dir, find_mros_root(app_dir, options.mros_root))
    check_tools(options.target)
    makefile = installed_file(PC_TARGET_MAKEFILE)
    pc_target = os.path.dirname(makefile)
    # The library's mros.cfg is on the search path, as in ASP's own build.
    config = read_config(app.cfg, [os.path.join(app.mros_root, 'mros-lib'),
                                   os.path.join(pc_target, 'cfg', 'asp')])
    check_tasks(app, config)
    types, paths = app.message_types()
    types = options.types or types
    if not types:
        raise GenmrosError('no message types: the app has no app.json/msg_app.json; give --type',
                           app.dir)
    build_dir = os.path.abspath(options.build_dir or
                                os.path.join(app.dir, 'build-pc-%s' % options.target))
    write_kernel_config(config, os.path.join(build_dir, 'cfg'))
    genmros = '%s -m colcon_mros' % sys.executable
    variables = {
        'MROS_ROOT': app.mros_root, 'APP_NAME': app.name, 'APP_DIRS': ' '.join(app.source_dirs),
        'APP_OBJS': ' '.join(app.objects), 'APP_CXXFLAGS': ' '.join(app.cxx_flags),
        'TARGET': options.target, 'BUILD': build_dir,
        'MROS_MSG_TYPES': ' '.join(types),
        'MROS_MSG_PATHS': ' '.join(options.msg_paths or paths),
        'MROS_MSG_DEFINITION_TEXT': options.definition_text,
        'MROS_MSG_FLAGS': ' '.join(['--storage', options.storage] + [
            '--options %s' % os.path.abspath(path) for path in options.option_files]),
        'GENMROS': 'env PYTHONPATH=%s %s' % (os.path.dirname(os.path.dirname(
            os.path.abspath(__file__))), genmros),
        'GENMROS_MK': installed_file(MAKE_FRAGMENT),
    }
    command = ['make', '--no-print-directory', '-f', makefile,
               '-j%d' % options.jobs] + ['%s=%s' % item for item in sorted(variables.items())]
    if subprocess.call(command) != 0:
        raise GenmrosError('building %s for the PC failed (see make\'s output above)' % app.name,
                           app.dir)
    return os.path.join(build_dir, app.name)


def run_program(program, target):
    """Replaces this process with the program (ROS_MASTER_URI etc. as set)."""
    command = runner(target) + [program]
    os.execvp(command[0], command)
