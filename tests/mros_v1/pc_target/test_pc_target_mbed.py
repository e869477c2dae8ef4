"""The PC target's mbed stand-in (colcon_mros/mros_v1/pc_target/mbed), on its
own with the kernel: a program of ours (tests/fixtures/pc_target_mbed) built
natively under AddressSanitizer, whose Ticker and Timeout share the kernel's
timers as a board's share its hardware timer."""

import subprocess

import pytest

import stand_in_programs

STAND_INS = ('asp/kernel.c', 'asp/task_stacks.c', 'lwip/lwip.cpp', 'mbed/mbed.cpp')


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
