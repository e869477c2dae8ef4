# SPDX-License-Identifier: BSD-3-Clause
"""The PC target's task stacks (colcon_mros/library_tools/mros_v1/pc_target/asp/task_stacks.c),
on their own with the kernel: a program of ours (tests/fixtures/pc_target_stacks)
configured from its own .cfg, built for 32-bit ARM as the arm target builds an
app and run under qemu-arm. Each task runs on the size its CRE_TSK gives, above
a guard: a task that overruns it stops the program with one line naming the
setting, its header line and the CRE_TSK; the report on SIGUSR1 and at SIGINT
gives every task its size and its peak use."""

import os
import re
import signal

import pytest

from support import stand_in_programs
from testing.ros_graph import Process

pytestmark = [pytest.mark.needs_qemu, pytest.mark.slow]

FIXTURE = os.path.join(stand_in_programs.FIXTURES, 'pc_target_stacks')
OVERFLOW = re.compile(r'^mROS PC target: task (\w+) overflowed its stack of (\d+) bytes '
                      r'\((\w+) at ([^:]+):(\d+); CRE_TSK at ([^:]+):(\d+)\); it needs at least '
                      r'(\d+) bytes$')
REPORT_HEADING = 'mROS PC target: task stacks'
REPORT_LINE = re.compile(r'^  (\w+) +(\d+|-) of +(\d+) bytes')
KERNEL_CONTEXT_BYTES = 64


def _line_of(path, pattern):
    with open(path) as stream:
        return next(number for number, line in enumerate(stream, 1) if re.search(pattern, line))


@pytest.fixture(scope='module')
def program(tmp_path_factory):
    return stand_in_programs.build('pc_target_stacks', 'stack_test.cfg', ['stack_test.c'],
                                   str(tmp_path_factory.mktemp('stack_test')),
                                   target=stand_in_programs.ARM)


def _start(program, buffer_bytes):
    return Process('stack_test', ['qemu-arm', program],
                   dict(os.environ, STACK_TEST_BYTES=str(buffer_bytes)))


def _reports(lines):
    """Each report in lines: {task: (peak or None, size)}."""
    reports = []
    for line in lines:
        if line.startswith(REPORT_HEADING):
            reports.append({})
        elif reports and REPORT_LINE.match(line):
            task, peak, size = REPORT_LINE.match(line).groups()
            reports[-1][task] = (None if peak == '-' else int(peak), int(size))
    return reports


def test_a_task_that_overruns_its_stack_stops_with_the_setting_to_change(program):
    process = _start(program, 2000)
    try:
        assert process.popen.wait(timeout=60) == 70
    finally:
        process.stop()
    lines = process.lines()
    overflows = [OVERFLOW.match(line) for line in lines if 'overflowed' in line]
    assert len(overflows) == 1 and overflows[0], process.output()
    task, size, setting, header, header_line, cfg, cfg_line, needed = overflows[0].groups()
    assert (task, int(size), setting) == ('SMALL_TASK', 1024, 'SMALL_STACK_SIZE')
    assert (header, int(header_line)) == (
        'stack_test.h', _line_of(os.path.join(FIXTURE, 'stack_test.h'), 'define SMALL_STACK_SIZE'))
    assert (cfg, int(cfg_line)) == (
        'stack_test.cfg',
        _line_of(os.path.join(FIXTURE, 'stack_test.cfg'), r'CRE_TSK\(SMALL_TASK'))
    assert int(needed) >= 2000 + KERNEL_CONTEXT_BYTES
    assert not any('kept a buffer' in line for line in lines), process.output()


def test_the_report_gives_each_task_its_size_and_peak(program):
    process = _start(program, 600)
    try:
        process.wait_for('kept a buffer of 600 bytes', timeout=60)
        os.kill(process.popen.pid, signal.SIGUSR1)
        process.wait_for(REPORT_HEADING, timeout=60)
        process.wait_for(r'^  SMALL_TASK ', timeout=60)
        assert process.alive()
        status = process.stop(signal.SIGINT)
    finally:
        process.stop()
    assert status == -signal.SIGINT, process.output()
    on_request, at_exit = _reports(process.lines())
    assert {task: size for task, (_, size) in on_request.items()} == {
        'MAIN_TASK': 2048, 'SMALL_TASK': 1024}, process.output()
    # The buffer and the kernel's context, and not syslog's formatting,
    # which runs on the host stack.
    assert 600 + KERNEL_CONTEXT_BYTES < on_request['SMALL_TASK'][0] < 1024
    for task, (peak, size) in at_exit.items():
        assert KERNEL_CONTEXT_BYTES <= on_request[task][0] <= peak <= size, process.output()
