# SPDX-License-Identifier: BSD-3-Clause
"""The PC target's mbed stand-in (colcon_mros/library_tools/mros_v1/pc_target/mbed), on its
own with the kernel: programs of ours (tests/fixtures/pc_target_mbed) built
natively under AddressSanitizer: Ticker and Timeout share the kernel's timers
as a board's share its hardware timer, and the pins are the files a test or a
user reads and edits (an output's changes logged, an input's value read, an
InterruptIn's rise handler run when the inputs file says the pin went up)."""

import os
import subprocess

import pytest

from support import stand_in_programs
from testing.ros_graph import Process

STAND_INS = stand_in_programs.KERNEL + ('lwip/lwip.cpp', 'mbed/mbed.cpp')


@pytest.fixture(scope='module')
def ticker_output(tmp_path_factory):
    program = stand_in_programs.build(
        'pc_target_mbed', 'ticker_test.cfg', ['ticker_test.cpp'],
        str(tmp_path_factory.mktemp('ticker_test')),
        stand_ins=STAND_INS, flags=['-O1'] + stand_in_programs.SANITIZE)
    return subprocess.run([program], capture_output=True, text=True, timeout=60)


def test_a_timeout_s_stale_detach_leaves_the_ticker_that_took_its_timer(ticker_output):
    assert ticker_output.stdout.splitlines()[:3] == [
        'timeout fired: 1',
        'ticker ticks after the timeout\'s detach: yes',
        'ticker stopped by its own detach: yes'], ticker_output.stdout + ticker_output.stderr


def test_attaching_again_and_again_holds_no_memory(ticker_output):
    assert ticker_output.stdout.splitlines()[-1] == 'done', ticker_output.stderr
    assert 'LeakSanitizer' not in ticker_output.stderr, ticker_output.stderr[-3000:]
    assert ticker_output.returncode == 0, ticker_output.stderr[-3000:]


def test_pins_are_the_output_log_and_the_inputs_file(tmp_path):
    program = stand_in_programs.build(
        'pc_target_mbed', 'pins_test.cfg', ['pins_test.cpp'], str(tmp_path),
        stand_ins=STAND_INS, flags=['-O1'] + stand_in_programs.SANITIZE)
    inputs, outputs = tmp_path / 'inputs', tmp_path / 'outputs'
    inputs.write_text('P6_0 0\n')
    process = Process('pins_test', [program], dict(os.environ, MROS_PC_INPUTS=str(inputs),
                                                   MROS_PC_OUTPUT_LOG=str(outputs)))
    try:
        process.wait_for('waiting for a rise', timeout=30)
        inputs.write_text('P6_0 1\n')
        assert process.popen.wait(timeout=30) == 0, process.output()
    finally:
        process.stop()
    assert process.lines() == ['button before: 0', 'waiting for a rise', 'rises: 1',
                               'button after: 1', 'done'], process.output()
    # LED1 is P6_13; every change, in order.
    assert outputs.read_text().splitlines() == ['P6_13 1', 'P6_13 0', 'P6_13 1']
