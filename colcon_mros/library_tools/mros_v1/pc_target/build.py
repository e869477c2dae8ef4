# SPDX-License-Identifier: BSD-3-Clause
"""``genmros mros-v1-pc``: an unmodified mROS v1 app and library on a PC.

Asks make what the app's own ``Makefile`` sets, reads its ``app.cfg`` and
the old generator's JSON file of message types, writes the kernel
configuration for the PC target (:mod:`.asp_cfg`) and runs make with
``mros_v1_pc.mk`` beside this module, in three steps: the checkout's
``mros-lib`` with genmros' headers (through the make fragment) and the
PC target's ASP, lwIP and mbed stand-ins, the app, the link.
"""

import dataclasses
import os
import re
import subprocess
import sys

from colcon_mros.core.defaults import DEFAULT_DEFINITION_TEXT, DEFAULT_STORAGE
from colcon_mros.errors import GenmrosError
from colcon_mros.integrations.installed_files import MAKE_FRAGMENT, installed_file
from colcon_mros.library_tools.pc_build import (SANITIZER_FLAGS, check_tools, flags_stamp,
                                                patched_copy, runner)
from colcon_mros.library_tools.mros_v1.pc_target.asp_cfg import read_config, write_kernel_config
from colcon_mros.mros_v1.app import App, find_app

TARGET_DIR = os.path.dirname(os.path.abspath(__file__))
MAKEFILE = os.path.join(TARGET_DIR, 'mros_v1_pc.mk')
# The steps of a build: (make goal, what the step's line says).
STEPS = (('library', 'the mROS v1 library of %(root)s, the PC target and the message headers'),
         ('app', 'the app %(name)s'),
         ('program', 'link %(program)s'))
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


def hardened_library(mros_root, build_dir):
    """The root of a copy of mros_root's mros-lib in build_dir with the patch
    set applied (only changed files rewritten)."""
    from colcon_mros.library_tools.mros_v1.patches import LIBRARY_DIR, mros_v1_patches
    return patched_copy(mros_root, [LIBRARY_DIR], mros_v1_patches(),
                        os.path.join(build_dir, 'hardened'))


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
        from colcon_mros.ros1.environment import require_ros_python
        require_ros_python()
        from colcon_mros.library_tools.mros_v1.fit_flow import app_fit  # genmsg: the types' models
        fit, _ = app_fit(app, types, msg_paths, (), request.storage, request.option_files,
                         request.hardened)
        fit.refuse(request.fit_strict)
        for warning in fit.warnings:
            print('genmros: warning: %s' % warning)
    flavour = request.target + ('-sanitize' if request.sanitize else '') + \
        ('-hardened' if request.hardened else '')
    build_dir = os.path.abspath(request.build_dir or os.path.join(app.dir, 'build-pc-' + flavour))
    write_kernel_config(config, os.path.join(build_dir, 'cfg'))
    library_root = hardened_library(
        app.mros_root, build_dir) if request.hardened else app.mros_root
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
    variables['FLAGS_STAMP'] = flags_stamp(build_dir, {
        name: variables[name] for name in ('MROS_ROOT', 'APP_CXXFLAGS', 'BOARD_C_OPTIMIZATION',
                                           'BOARD_CXX_OPTIMIZATION', 'TARGET', 'SANITIZER_FLAGS',
                                           'FIT_CHECK_FLAGS')})
    command = ['make', '--no-print-directory', '-f', MAKEFILE, '-j%d' % request.jobs] + \
        ([] if request.verbose else ['-s']) + ['%s=%s' %
                                               item for item in sorted(variables.items())]
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
