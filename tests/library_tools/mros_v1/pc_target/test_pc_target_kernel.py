# SPDX-License-Identifier: BSD-3-Clause
"""The PC target's TOPPERS/ASP scheduling
(colcon_mros/library_tools/mros_v1/pc_target/asp/kernel*.c), on its own: a
program of ours (tests/fixtures/pc_target_kernel) configured from its own
.cfg by colcon_mros.library_tools.mros_v1.pc_target.asp_cfg, as an mROS v1
app is (tests/support/stand_in_programs.py), runs scenarios whose
traces show ASP's rules: highest priority first and FIFO within one, a
task whose priority is set going behind its equals, activation and wake-up
requests queued up to 1, time-outs, delays and cyclic handlers on time, and
one task at a time (the mROS v1 library's only mutual exclusion).
"""

import re
import subprocess

import pytest

from support import stand_in_programs

E_OK, E_QOVR, E_TMOUT = 0, -43, -50
# Timing on a loaded 2-core machine: late by up to this much, never early.
LATENESS_MS = 60


@pytest.fixture(scope='module')
def trace(tmp_path_factory):
    program = stand_in_programs.build('pc_target_kernel', 'kernel_test.cfg', ['kernel_test.c'],
                                      str(tmp_path_factory.mktemp('kernel_test')))
    result = subprocess.run([program], capture_output=True, text=True, timeout=60)
    assert result.returncode == 0, result.stdout + result.stderr
    assert result.stdout.rstrip().endswith('done'), result.stdout
    return result.stdout.splitlines()


def _events(trace, scenario):
    return [line.split(': ', 1)[1] for line in trace if line.startswith(scenario + ': ')]


def _value(trace, scenario, label):
    for event in _events(trace, scenario):
        if event.startswith(label):
            return int(re.search(r'(-?\d+)\Z', event).group(1))
    raise AssertionError('no %r in %s' % (label, trace))


def test_initialization_routines_run_before_the_first_task(trace):
    assert trace[0] == 'init: before the first task'


def test_highest_priority_first_then_fifo_within_a_priority(trace):
    assert _events(trace, 'order') == [
        'X activated C, B, A',
        'A runs at priority 3',
        'C runs at priority 4',
        'B runs at priority 4',
    ]


def test_setting_a_priority_puts_the_task_behind_its_equals(trace):
    assert _events(trace, 'yield') == [
        'B before chg_pri', 'C before chg_pri', 'B after chg_pri', 'C after chg_pri']


def test_activation_requests_queue_up_to_one(trace):
    assert _value(trace, 'activation', 'X first act_tsk') == E_OK
    assert _value(trace, 'activation', 'X second act_tsk') == E_OK
    assert _value(trace, 'activation', 'X third act_tsk') == E_QOVR
    assert _events(trace, 'activation').count('B activated') == 2


def test_wakeup_requests_queue_up_to_one(trace):
    assert _value(trace, 'wakeup', 'X wup_tsk on itself') == E_OK
    assert _value(trace, 'wakeup', 'X second wup_tsk') == E_QOVR
    assert _value(trace, 'wakeup', 'X slp_tsk') == E_OK
    assert _value(trace, 'wakeup', 'X tslp_tsk(100)') == E_TMOUT
    assert 100 <= _value(trace, 'wakeup', 'X waited ms') <= 100 + LATENESS_MS


def test_delays_and_timeouts_last_as_long_as_asked(trace):
    assert 50 <= _value(trace, 'delay', 'X dly_tsk(50) took ms') <= 50 + LATENESS_MS
    assert _value(trace, 'delay', 'X twai_sem(30) on an empty semaphore') == E_TMOUT


def test_cyclic_handler_runs_at_its_period(trace):
    assert 20 <= _value(trace, 'cyclic', 'X ticks in 500 ms at 20 ms') <= 26


def test_one_task_runs_at_a_time(trace):
    # Two tasks each make 200 read-modify-write increments with 200 us
    # between read and write and no lock: none is lost.
    assert _value(trace, 'exclusion', 'X counter after 2 x 200 increments') == 400
    assert 'S stops' in _events(trace, 'exclusion')
