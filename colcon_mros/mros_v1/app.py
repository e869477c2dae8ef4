# SPDX-License-Identifier: BSD-3-Clause
"""An mROS v1 app as its own build describes it, and the headers that set
its library's settings.

An app is a directory of the checkout's ``mros_ws/`` with an ``app.cfg``
(its kernel objects), a ``Makefile`` (its sources, flags and the old
generator's JSON file of message types) and, optionally, its own
``mros_config/mros_usr_config.h``. The PC target builds it
(:mod:`colcon_mros.library_tools.mros_v1.pc_target.build`); the fit check
and report read its settings (:mod:`colcon_mros.library_tools.mros_v1.fit_flow`).
"""

import json
import os
import re
import subprocess
import tempfile

from colcon_mros.errors import GenmrosError
from colcon_mros.mros_v1.rules import LIBRARY_PASSES_FRAME_SIZE, SETTINGS_HEADERS

# `make -p` prints each variable after the line naming where it was set.
_ORIGIN = re.compile(r"^# makefile \(from '(.*)', line \d+\)$")
_ASSIGNMENT = re.compile(r'^([A-Za-z_][A-Za-z0-9_]*) :{0,2}= ?(.*)$')
_REFERENCE = re.compile(r'\$[({]([A-Za-z_][A-Za-z0-9_]*)[)}]')


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


def app_settings_headers(app):
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
                           % ('' if given else '; give --mros-v1-root'), where)
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


def passes_frame_size(mros_root):
    """Whether the library of the checkout mros_root passes delivery each
    frame's size: its ros.cpp defines LIBRARY_PASSES_FRAME_SIZE, as genmros'
    patch set has it."""
    try:
        with open(os.path.join(mros_root, 'mros-lib', 'mros-src', 'api', 'ros.cpp'),
                  encoding='utf-8', errors='replace') as stream:
            return re.search(r'^\s*#\s*define\s+%s\b' % LIBRARY_PASSES_FRAME_SIZE, stream.read(),
                             re.M) is not None
    except OSError:
        return False
