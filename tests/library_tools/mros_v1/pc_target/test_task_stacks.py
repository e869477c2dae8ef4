# SPDX-License-Identifier: BSD-3-Clause
"""The board's task stacks on the PC target (asp/task_stacks.c), with the real
mROS v1 library: an app (tests/fixtures/mros_v1_pc_app/stack_use.cpp) whose
1 KiB user task keeps either a bounded mros_test/ArrayTypes (1.8 KB) or a
600-byte buffer in a local variable. On the arm target the first stops the
program with one line naming the setting; the stack report shows the
second against the task's size. The native target keeps host stacks."""

import os
import re
import signal

import pytest

from colcon_mros.mros_v1.app import App
from testing.ros_graph import DELIVERY_TIMEOUT, Board, RosGraph
from support.user_checkouts import MROS_V1_ROOT
from support.pc_target_apps import APP_FIXTURE, build_app

pytestmark = [pytest.mark.needs_mros_v1, pytest.mark.needs_qemu, pytest.mark.slow]

OS_CONFIG = os.path.join('mros_config', 'os', 'target', 'os_asp', 'mros_os_config.h')
# The app keeps the type and never sends it: the fit check's settings for
# sending it do not matter here.
HEADER_FLAGS = ('--storage', 'bounded',
                '--options', os.path.join(APP_FIXTURE, 'stack_use.options'),
                '--no-fit-check')
OVERFLOW = re.compile(r'^mROS PC target: task (\w+) overflowed its stack of (\d+) bytes '
                      r'\((\w+) at ([^:]+):(\d+); CRE_TSK at ([^:]+):(\d+)\); it needs at least '
                      r'(\d+) bytes$')


def _defined_size(name):
    """The value custom_pubsub's mros_os_config.h gives name (a product of
    numbers there), and its line."""
    with open(os.path.join(MROS_V1_ROOT, 'mros_ws', 'custom_pubsub', OS_CONFIG)) as stream:
        for number, line in enumerate(stream, 1):
            match = re.match(r'#define %s\s+([\d\s*]+?)\s*(//.*)?$' % name, line)
            if match:
                size = 1
                for factor in match.group(1).split('*'):
                    size *= int(factor)
                return size, number
    raise AssertionError('%s is not in %s' % (name, OS_CONFIG))


def _cfg_line(task):
    with open(os.path.join(APP_FIXTURE, 'app.cfg')) as stream:
        return next(number for number, line in enumerate(stream, 1)
                    if 'CRE_TSK(%s,' % task in line)


@pytest.fixture(scope='module')
def arm_program(tmp_path_factory):
    return build_app(MROS_V1_ROOT, str(tmp_path_factory.mktemp('stack_use_arm')), 'stack_use.cpp',
                     types=('mros_test/ArrayTypes',), header_flags=HEADER_FLAGS)


def test_a_task_that_overruns_its_board_stack_stops_with_one_line(arm_program, tmp_path):
    with RosGraph() as graph:
        board = Board(graph, arm_program, str(tmp_path), inputs={'P6_0': 1})
        kept = board.process.wait_for(r'keeping a message of (\d+) bytes',
                                      timeout=DELIVERY_TIMEOUT)[0]
        assert board.process.popen.wait(timeout=DELIVERY_TIMEOUT) == 70
    lines = board.process.lines()
    overflows = [OVERFLOW.match(line) for line in lines if 'overflowed' in line]
    assert len(overflows) == 1 and overflows[0], board.process.output()
    task, size, setting, header, header_line, cfg, cfg_line, needed = overflows[0].groups()
    assert (task, setting, cfg) == ('USR_TASK1', 'MROS_USR1_STACK_SIZE', 'app.cfg')
    assert (int(size), int(header_line)) == _defined_size(setting)
    assert header == OS_CONFIG and int(cfg_line) == _cfg_line('USR_TASK1')
    # At least the message, which lies deeper than the task's stack reaches.
    assert int(needed) >= int(kept.group(1)) > int(size)
    assert not any('kept a message' in line for line in lines), board.process.output()


def test_the_native_target_keeps_host_stacks_and_runs_on(tmp_path):
    program = build_app(MROS_V1_ROOT, str(tmp_path / 'native'), 'stack_use.cpp', target='native',
                        types=('mros_test/ArrayTypes',), header_flags=HEADER_FLAGS)
    with RosGraph() as graph:
        board = Board(graph, program, str(tmp_path), runner=[], inputs={'P6_0': 1})
        board.process.wait_for('kept a message with 1 ints', timeout=DELIVERY_TIMEOUT)
        assert board.process.alive()
    assert 'overflowed' not in board.process.output()


def test_the_stack_report_shows_each_task_against_its_size(arm_program, tmp_path):
    with RosGraph() as graph:
        board = Board(graph, arm_program, str(tmp_path), inputs={'P6_0': 0})
        board.process.wait_for('kept a buffer of 600.0 bytes', timeout=DELIVERY_TIMEOUT)
        board.process.wait_for('task 2 ran', timeout=DELIVERY_TIMEOUT)
        os.kill(board.process.popen.pid, signal.SIGUSR1)
        heading = board.process.wait_for('task stacks, peak use', timeout=DELIVERY_TIMEOUT)
        assert heading and board.process.alive()
        status = board.process.stop(signal.SIGINT)
    on_request, at_exit = board.stack_reports()
    assert status == -signal.SIGINT, board.process.output()
    library_size, _ = _defined_size('MROS_TASK_STACK_SIZE')
    user_size, _ = _defined_size('MROS_USR1_STACK_SIZE')
    sizes = {task: size for task, (_, size) in on_request.items()}
    assert sizes == {'MAIN_TASK': library_size, 'PUB_TASK': library_size,
                     'SUB_TASK': library_size, 'XML_SLV_TASK': library_size,
                     'XML_MAS_TASK': library_size, 'USR_TASK1': user_size,
                     'USR_TASK2': user_size}, board.process.output()
    # The buffer, the kernel's 64 bytes of context and a few frames; not the
    # host's snprintf and vsnprintf, which alone take more than the 1 KiB.
    assert 600 + 64 < on_request['USR_TASK1'][0] < user_size
    assert set(at_exit) == set(on_request)
    for task, (peak, size) in at_exit.items():
        # Every task ran, and has at least the kernel's context on its stack.
        assert 64 <= on_request[task][0] <= peak <= size, (task, board.process.output())


@pytest.mark.parametrize('sample', ['custom_pubsub', 'string_pubsub'])
def test_the_library_and_app_build_as_the_apps_makefile_builds_them_for_the_board(sample):
    # The samples' Makefiles set DEBUG = true and OMIT_OPTIMIZATION = true:
    # Makefile.asp then gives C -O0 alone, Makefile.mbd gives C++ -DDEBUG -O0.
    app = App(os.path.join(MROS_V1_ROOT, 'mros_ws', sample), MROS_V1_ROOT)
    with open(os.path.join(app.dir, 'Makefile')) as stream:
        text = stream.read()
    assert re.search(r'^DEBUG = true$', text, re.M)
    assert re.search(r'^OMIT_OPTIMIZATION = true$', text, re.M)
    assert (app.c_optimization, app.cxx_optimization) == ('-O0', '-DDEBUG -O0')
    # The test apps' Makefile sets neither.
    fixture = App(APP_FIXTURE, MROS_V1_ROOT)
    assert (fixture.c_optimization, fixture.cxx_optimization) == ('-O2', '-DNDEBUG -Os')
