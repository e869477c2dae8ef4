"""The PC target's mbed stand-in (colcon_mros/mros_v1/pc_target/mbed), on its
own with the kernel: a program of ours (tests/fixtures/pc_target_mbed) built
natively under AddressSanitizer, whose Ticker and Timeout share the kernel's
timers as a board's share its hardware timer."""

import os
import subprocess

import pytest

from colcon_mros.mros_v1.pc_target.asp_cfg import read_config, write_kernel_config
from conftest import REPO

FIXTURE = os.path.join(REPO, 'tests', 'fixtures', 'pc_target_mbed')
PC_TARGET = os.path.join(REPO, 'colcon_mros', 'mros_v1', 'pc_target')
SANITIZE = ['-fsanitize=address,undefined', '-fno-omit-frame-pointer', '-g']


@pytest.fixture(scope='module')
def ticker_output(tmp_path_factory):
    build = str(tmp_path_factory.mktemp('ticker_test'))
    write_kernel_config(read_config(os.path.join(FIXTURE, 'ticker_test.cfg'), []),
                        os.path.join(build, 'cfg'))
    includes = ['-I', os.path.join(build, 'cfg'), '-I', FIXTURE]
    for name in ('asp', 'mbed', 'lwip', 'config'):
        includes += ['-I', os.path.join(PC_TARGET, name)]
    objects = []
    for source in (os.path.join(PC_TARGET, 'asp', 'kernel.c'),
                   os.path.join(PC_TARGET, 'asp', 'task_stacks.c'),
                   os.path.join(PC_TARGET, 'lwip', 'lwip.cpp'),
                   os.path.join(build, 'cfg', 'kernel_cfg.c')):
        objects.append(os.path.join(build, os.path.basename(source) + '.o'))
        compiler = ['g++', '-std=gnu++11'] if source.endswith('.cpp') else ['gcc']
        subprocess.run(compiler + ['-O1', '-Wall', '-Wextra', '-Werror', '-pthread', '-c']
                       + SANITIZE + includes + [source, '-o', objects[-1]], check=True)
    program = os.path.join(build, 'ticker_test')
    subprocess.run(['g++', '-O1', '-Wall', '-Wextra', '-Werror', '-pthread'] + SANITIZE + includes
                   + [os.path.join(PC_TARGET, 'mbed', 'mbed.cpp'),
                      os.path.join(FIXTURE, 'ticker_test.cpp')] + objects + ['-o', program],
                   check=True)
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
