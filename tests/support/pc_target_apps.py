# SPDX-License-Identifier: BSD-3-Clause
"""Apps on the real mROS v1 library, built by genmros mros-v1-pc from this
checkout: the checkout's sample apps, and test apps of
tests/fixtures/mros_v1_pc_app's Makefile and app.cfg with one of its sources
as app.cpp."""

import os
import re
import shutil
import subprocess
import sys

from support.checkout import FIXTURES, REPO, TEST_WS

APP_FIXTURE = os.path.join(FIXTURES, 'mros_v1_pc_app')


def build_app(mros_root, build_root, source, target='arm', types=('mros_test/PersonalData',),
              header_flags=()):
    """source (a name in tests/fixtures/mros_v1_pc_app, or a path) as the
    app's app.cpp beside that dir's Makefile and app.cfg, with custom_pubsub's
    mros_config/ and app.h linked in (the library's tasks and memory pools and
    the user tasks' declarations, as a new app takes them from a sample),
    built for target with the
    headers of types (header_flags: more options of mros-v1-pc, such as
    --storage); returns the program."""
    app = os.path.join(build_root, 'app')
    os.makedirs(app, exist_ok=True)
    links = {name: os.path.join(APP_FIXTURE, name) for name in ('Makefile', 'app.cfg')}
    links['app.cpp'] = os.path.join(APP_FIXTURE, source)
    for name in ('mros_config', 'app.h'):
        links[name] = os.path.join(mros_root, 'mros_ws', 'custom_pubsub', name)
    for name, origin in links.items():
        if not os.path.lexists(os.path.join(app, name)):
            os.symlink(origin, os.path.join(app, name))
    output = os.path.join(build_root, 'build')
    type_args = [argument for name in types for argument in ('--type', name)]
    _mros_v1_pc(app, output, ['--mros-v1-root', mros_root, '--workspace',
                              os.path.join(TEST_WS, 'src'), '--target', target]
                + type_args + list(header_flags))
    return os.path.join(output, 'test_app')


def build_sample(mros_root, app, output, *flags):
    """The checkout's sample app mros_ws/<app> built into output with flags
    (--target, --sanitize, --hardened, ...); returns (the program, what
    genmros and the compilers printed)."""
    printed = _mros_v1_pc(os.path.join(mros_root, 'mros_ws', app), output, flags)
    return os.path.join(output, app), printed


def _mros_v1_pc(app_dir, output, flags):
    """genmros mros-v1-pc of this checkout; what it printed, or RuntimeError."""
    result = subprocess.run(
        [sys.executable, '-m', 'colcon_mros', 'mros-v1-pc', app_dir, '-o', output, '-j2',
         '--build-only']
        + list(flags), cwd=REPO, capture_output=True, text=True)
    if result.returncode != 0:
        raise RuntimeError('genmros mros-v1-pc failed:\n' + result.stdout[-3000:]
                           + result.stderr[-3000:])
    return result.stdout + result.stderr


def library_copy(mros_root, destination, settings):
    """A copy of the library (mros-lib, and custom_pubsub's mros_config and
    app.h, which the test apps take) at destination with settings changed:
    {(path relative to the checkout, macro name): value}, each a #define
    there. Returns destination."""
    shutil.copytree(os.path.join(mros_root, 'mros-lib'), os.path.join(destination, 'mros-lib'))
    sample = os.path.join('mros_ws', 'custom_pubsub')
    shutil.copytree(os.path.join(mros_root, sample, 'mros_config'),
                    os.path.join(destination, sample, 'mros_config'))
    shutil.copy(os.path.join(mros_root, sample, 'app.h'), os.path.join(destination, sample))
    for (relative, name), value in settings.items():
        path = os.path.join(destination, relative)
        with open(path) as stream:
            text, count = re.subn(r'(#define %s\s+)\d+' % name, r'\g<1>%d' % value, stream.read())
        if count != 1:
            raise ValueError('%s defines %s %d times' % (path, name, count))
        with open(path, 'w') as stream:
            stream.write(text)
    return destination
