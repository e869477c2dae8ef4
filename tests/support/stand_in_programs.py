# SPDX-License-Identifier: BSD-3-Clause
"""Programs of the tests' own on the PC target's stand-ins (the ASP kernel,
task stacks, lwIP and mbed in colcon_mros/library_tools/mros_v1/pc_target), configured
from their own .cfg as an mROS v1 app is, with no mROS v1 library."""

import os
import subprocess

from colcon_mros.library_tools.mros_v1.pc_target.asp_cfg import read_config, write_kernel_config
from support.checkout import FIXTURES, REPO

PC_TARGET = os.path.join(REPO, 'colcon_mros', 'library_tools', 'mros_v1', 'pc_target')
# The arm target's line (mros_v1_pc.mk): GR-PEACH's CPU, linked statically
# for qemu-arm.
ARM = dict(prefix='arm-linux-gnueabihf-',
           flags=['-mcpu=cortex-a9', '-marm', '-mfpu=vfpv3', '-mfloat-abi=hard',
                  '-mno-unaligned-access'],
           link=['-static'])
NATIVE = dict(prefix='', flags=[], link=[])
# The ASP kernel's stand-in, below pc_target/.
KERNEL = ('asp/kernel.c', 'asp/kernel_scheduler.c', 'asp/kernel_tasks.c',
          'asp/kernel_semaphores.c', 'asp/kernel_timers.c', 'asp/syslog.c', 'asp/task_stacks.c')
SANITIZE = ['-fsanitize=address,undefined', '-fno-omit-frame-pointer', '-g']


def build(fixture, cfg, sources, build_dir, stand_ins=KERNEL,
          target=NATIVE, flags=('-O2',)):
    """tests/fixtures/<fixture>/<cfg> turned into the kernel's tables, and
    the stand-ins (paths below pc_target/) with the fixture's sources built
    into build_dir/program; returns its path."""
    fixture_dir = os.path.join(FIXTURES, fixture)
    cfg_dir = os.path.join(build_dir, 'cfg')
    write_kernel_config(read_config(os.path.join(fixture_dir, cfg), []), cfg_dir)
    includes = ['-I', cfg_dir, '-I', fixture_dir]
    for name in ('asp', 'mbed', 'lwip', 'config'):
        includes += ['-I', os.path.join(PC_TARGET, name)]
    common = target['flags'] + list(flags) + ['-Wall', '-Wextra', '-Werror', '-pthread']
    objects = []
    for source in ([os.path.join(PC_TARGET, path) for path in stand_ins]
                   + [os.path.join(cfg_dir, 'kernel_cfg.c')]
                   + [os.path.join(fixture_dir, name) for name in sources]):
        objects.append(os.path.join(build_dir, os.path.basename(source) + '.o'))
        compiler = ([target['prefix'] + 'g++', '-std=gnu++11'] if source.endswith('.cpp')
                    else [target['prefix'] + 'gcc'])
        subprocess.run(compiler + common + includes + ['-c', source, '-o', objects[-1]],
                       check=True)
    program = os.path.join(build_dir, 'program')
    subprocess.run([target['prefix'] + 'g++'] + common + target['link'] + objects
                   + ['-o', program], check=True)
    return program
