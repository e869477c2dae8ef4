# SPDX-License-Identifier: BSD-3-Clause
"""genmros mros-v1-pc on bad input: one `genmros: error:` line naming the
file (and line) and the problem, exit 1, nothing built. The cases with an
app of the real checkout use the checkout MROS_V1_ROOT names and
write only to temporary directories."""

import os

import pytest

from support.checkout import run_genmros
from support.user_checkouts import MROS_V1_ROOT


def _error_line(*arguments):
    result = run_genmros('mros-v1-pc', '--build-only', *arguments, check=False)
    assert result.returncode == 1, result.stdout + result.stderr
    # The compiler's own lines (the library's warnings) may come before it.
    lines = [line for line in result.stderr.splitlines() if line.startswith('genmros:')]
    assert len(lines) == 1 and lines[0].startswith('genmros: error: '), result.stderr
    assert result.stderr.rstrip('\n').endswith(lines[0]), result.stderr
    return lines[0][len('genmros: error: '):]


def _app(root, cfg, source='', makefile='', header=''):
    app = os.path.join(str(root), 'mros_ws', 'app')
    os.makedirs(app)
    for name, text in (('app.cfg', cfg), ('app.cpp', source), ('Makefile', makefile),
                       ('app.h', header)):
        with open(os.path.join(app, name), 'w') as stream:
            stream.write(text)
    return app


def test_no_such_directory(tmp_path):
    missing = str(tmp_path / 'nowhere')
    assert _error_line(missing) == '%s: no such directory' % missing


def test_a_directory_without_app_cfg_is_not_an_app(tmp_path):
    assert _error_line(str(tmp_path)) == '%s: no app.cfg: not an mROS v1 app' % tmp_path


def test_an_app_outside_a_checkout_needs_mros_v1_root(tmp_path):
    app = _app(tmp_path, '')
    assert _error_line(app) == ('%s: no mROS v1 checkout here (no mros-lib/Makefile.m); give '
                                '--mros-v1-root' % os.path.normpath(os.path.join(app, '..', '..')))
    assert _error_line(app, '--mros-v1-root', str(tmp_path)) == (
        '%s: no mROS v1 checkout here (no mros-lib/Makefile.m)' % tmp_path)


@pytest.mark.needs_mros_v1
def test_a_task_the_app_does_not_define(tmp_path):
    # The library's own tasks are in the sample app's mros_config/; this
    # app's cfg names two tasks, and its app.cpp defines only the second:
    # the linker's complaint comes back as the cfg's line.
    sample_config = os.path.relpath(
        os.path.join(MROS_V1_ROOT, 'mros_ws', 'string_pubsub', 'mros_config'),
        os.path.join(str(tmp_path), 'mros_ws', 'app'))
    mros_cfg = os.path.join(MROS_V1_ROOT, 'mros-lib', 'mros.cfg')
    app = _app(tmp_path,
               'INCLUDE("%s");\n#include "mros_os_config.h"\n#include "app.h"\n'
               'CRE_TSK(USR_TASK1, { TA_NULL, 0, usr_task1, 8, 1024, NULL });\n'
               'CRE_TSK(USR_TASK2, { TA_NULL, 0, usr_task2, 8, 1024, NULL });\n' % mros_cfg,
               source='#include "app.h"\nvoid usr_task2() {\n}\n',
               header='#ifdef __cplusplus\nextern "C" {\n#endif\nvoid usr_task1();\n'
                      'void usr_task2();\n#ifdef __cplusplus\n}\n#endif\n',
               makefile='APPLDIR = app %s %s/os/target/os_asp\n'
                        'APPL_COBJS = mros_sys_config.o mros_usr_config.o mros_os_config.o\n'
                        % (sample_config, sample_config))
    assert _error_line(app, '--mros-v1-root', MROS_V1_ROOT, '--type', 'std_msgs/String') == (
        "%s:4: USR_TASK1 runs usr_task1(), which no source of the app defines (the linker "
        "found no definition)" % os.path.join(app, 'app.cfg'))


@pytest.mark.needs_mros_v1
def test_an_unsupported_static_api(tmp_path):
    app = _app(tmp_path, '\nCRE_MBX(BOX, { TA_NULL, 0, NULL });\n')
    problem = _error_line(app, '--mros-v1-root', MROS_V1_ROOT)
    assert problem.startswith('%s:2: CRE_MBX is not supported by the PC target'
                              % os.path.join(app, 'app.cfg'))
