# SPDX-License-Identifier: BSD-3-Clause
"""colcon_mros.library_tools.mros_v1.pc_target.asp_cfg: the PC target's
TOPPERS/ASP configurator, on app.cfg files of its own and on the real mROS v1
kernel configuration when a checkout is given (MROS_V1_ROOT)."""

import os

import pytest

from support.checkout import REPO
from support.user_checkouts import MROS_V1_ROOT
from colcon_mros.errors import GenmrosError
from colcon_mros.library_tools.mros_v1.pc_target.asp_cfg import read_config, write_kernel_config

PC_CFG = os.path.join(REPO, 'colcon_mros', 'library_tools', 'mros_v1', 'pc_target', 'cfg', 'asp')


def _write(directory, name, text):
    path = os.path.join(str(directory), name)
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, 'w') as stream:
        stream.write(text)
    return path


def test_objects_are_numbered_in_order_of_creation_across_includes(tmp_path):
    _write(tmp_path, 'lib/base.cfg', 'CRE_TSK(FIRST, { TA_ACT, 0, first, 5, 1024, NULL });\n'
                                     'CRE_SEM(READY, { TA_NULL, 0, 1 });\n')
    cfg = _write(tmp_path, 'app/app.cfg', '/* an app */\nINCLUDE("../lib/base.cfg");\n'
                                          '#include "app.h"\n'
                                          '// two more\nCRE_TSK(SECOND, { TA_NULL, 7, second,\n'
                                          '  PRI(1, 2), 2 * 1024, NULL });\n'
                                          'CRE_CYC(TICK, { TA_STA, 0, tick, 100, 0 });\n'
                                          'DEF_KMM({ 1024, NULL });\n')
    _write(tmp_path, 'app/app.h', '')
    config = read_config(cfg, [])
    assert [(o.api, o.name) for o in config.objects] == [
        ('CRE_TSK', 'FIRST'), ('CRE_SEM', 'READY'), ('CRE_TSK', 'SECOND'), ('CRE_CYC', 'TICK')]
    assert config.objects[2].fields['priority'] == 'PRI(1, 2)'
    assert config.objects[2].fields['stack_size'] == '2 * 1024'
    assert config.objects[2].line == 5
    write_kernel_config(config, str(tmp_path / 'out'))
    header = (tmp_path / 'out' / 'kernel_cfg.h').read_text()
    assert '#define FIRST 1\n#define SECOND 2\n' in header
    assert '#define TNUM_SEMID 1\n#define READY 1\n' in header
    source = (tmp_path / 'out' / 'kernel_cfg.c').read_text()
    assert '#include "%s"' % os.path.join(str(tmp_path), 'app', 'app.h') in source
    assert ('{"SECOND", TA_NULL, (intptr_t)(7), (TASK)(second), PRI(1, 2), 2 * 1024, '
            '"CRE_TSK at app.cfg:5"},') in source
    # Outside the app's directory: the whole path.
    assert '"CRE_TSK at %s:1"},' % os.path.join(str(tmp_path), 'lib', 'base.cfg') in source


def test_a_stack_size_names_the_header_line_that_defines_it(tmp_path):
    # What the overflow line of the PC target's task stacks quotes.
    _write(tmp_path, 'app/config/sizes.h', '#ifndef SIZES\n#define SIZES\n'
                                           '#define USER_STACK (1024 * 1)\n#endif\n')
    cfg = _write(tmp_path, 'app/app.cfg',
                 '#include "config/sizes.h"\n'
                 'CRE_TSK(USER, { TA_NULL, 0, user, 5, USER_STACK, NULL });\n'
                 'CRE_TSK(OTHER, { TA_NULL, 0, other, 5, ELSEWHERE, NULL });\n')
    config = read_config(cfg, [])
    user, other = config.objects
    assert config.stack_origin(user) == 'USER_STACK at config/sizes.h:3; CRE_TSK at app.cfg:2'
    assert config.stack_origin(other) == 'ELSEWHERE; CRE_TSK at app.cfg:3'


@pytest.mark.parametrize('text, line, problem', [
    ('CRE_DTQ(QUEUE, { TA_NULL, 4, NULL });', 2, 'CRE_DTQ is not supported by the PC target'),
    ('CRE_TSK(T, { TA_NULL, 0, t, 5 });', 2, 'CRE_TSK: 4 fields in { ... }, expected 6'),
    ('CRE_TSK(T, { TA_NULL, 0, t, 5, 1, NULL });\nCRE_TSK(T, { TA_NULL, 0, t, 5, 1, NULL });',
     3, 'T is created twice (first at '),
    ('INCLUDE("missing.cfg");', 2, 'INCLUDE: missing.cfg not found'),
    ('#ifdef BOARD\nCRE_SEM(S, { TA_NULL, 0, 1 });\n#endif', 2, '#ifdef: the PC target'),
    ('CRE_SEM(S, { TA_NULL, 0, 1 };', 2, 'static API call without its closing ")"'),
    ('CRE_SEM(S, { TA_NULL, 0, 1 );', 2, 'unbalanced brackets'),
    ('stray text', 2, "expected a static API call, found 'stray text'"),
])
def test_bad_cfg_stops_with_file_line_and_problem(tmp_path, text, line, problem):
    cfg = _write(tmp_path, 'app.cfg', '\n' + text + '\n')
    with pytest.raises(GenmrosError) as error:
        read_config(cfg, [])
    assert str(error.value).startswith('%s:%d: ' % (cfg, line)), str(error.value)
    assert problem in str(error.value)


@pytest.mark.needs_mros_v1
def test_the_real_mros_cfg_and_a_sample_apps_cfg(tmp_path):
    app_cfg = os.path.join(MROS_V1_ROOT, 'mros_ws', 'string_pubsub', 'app.cfg')
    config = read_config(app_cfg, [PC_CFG])
    assert [o.name for o in config.of_api('CRE_TSK')] == [
        'MAIN_TASK', 'PUB_TASK', 'SUB_TASK', 'XML_SLV_TASK', 'XML_MAS_TASK', 'USR_TASK1',
        'USR_TASK2']
    # The board's EthernetInterface.cfg, as the PC target has it.
    assert [o.name for o in config.of_api('CRE_SEM')] == ['TCPIP_INITED', 'NETIF_LINKED',
                                                          'NETIF_UP']
    assert [o.fields['handler'] for o in config.of_api('CRE_CYC')] == ['cyclic_handler']
