# SPDX-License-Identifier: BSD-3-Clause
"""The PC target's lwIP stand-in (colcon_mros/library_tools/mros_v1/pc_target/lwip), on its
own with the kernel: a program of ours (tests/fixtures/pc_target_lwip),
written against lwIP's socket API as mROS v1's network layer is and built
natively under AddressSanitizer and UndefinedBehaviorSanitizer. A task that
waits in a socket call gives up the CPU, as an ASP task does while lwIP's
tcpip thread serves it: the tasks below it run, connect and exchange bytes;
lwip_select keeps its time-out, SO_RCVTIMEO is an int of milliseconds as in
lwIP 1.4; lwIP's FD_ZERO compiles where a variable is
named fd_set, as in mROS v1."""

import re
import subprocess

import pytest

from support import stand_in_programs

STAND_INS = stand_in_programs.KERNEL + ('lwip/lwip.cpp',)
# Timing on a loaded 2-core machine: late by up to this much, never early.
LATENESS_MS = 200


@pytest.fixture(scope='module')
def lines(tmp_path_factory):
    program = stand_in_programs.build(
        'pc_target_lwip', 'socket_test.cfg', ['socket_test.c'],
        str(tmp_path_factory.mktemp('socket_test')), stand_ins=STAND_INS,
        flags=['-O1'] + stand_in_programs.SANITIZE)
    result = subprocess.run([program], capture_output=True, text=True, timeout=60)
    assert result.returncode == 0 and 'Sanitizer' not in result.stderr, \
        result.stdout + result.stderr[-3000:]
    return result.stdout.splitlines()


def _value(lines, prefix):
    line = next(line for line in lines if line.startswith(prefix))
    return int(re.search(r'(-?\d+)\D*$', line).group(1))


def test_a_task_waiting_in_accept_lets_the_tasks_below_it_connect(lines):
    assert 'server: accepted a connection (1)' in lines
    assert _value(lines, 'server: received') == 4
    assert "client: received 'pong' (4 bytes)" in lines
    assert lines[-1] == 'done'


def test_select_keeps_its_time_out_and_reports_a_ready_socket(lines):
    assert _value(lines, 'client: select on an idle socket gave') == 0
    assert 100 <= _value(lines, 'client: after') <= 100 + LATENESS_MS
    assert _value(lines, 'client: select on the connection gave') == 1


def test_the_lowest_task_runs_while_the_others_wait_in_socket_calls(lines):
    assert _value(lines, 'watcher: ran') >= 50


def test_a_receive_time_out_is_taken_in_milliseconds_as_lwip_1_4_takes_it(lines):
    # mbed 2's lwIP takes SO_RCVTIMEO as an int of milliseconds (genmros'
    # receive-time-out patch sets it so); the host takes a timeval.
    assert _value(lines, 'client: recv with SO_RCVTIMEO timed out') == 1
    assert 150 <= _value(lines, 'client: recv returned after') <= 150 + LATENESS_MS
