# SPDX-License-Identifier: BSD-3-Clause
"""genmros headers on the CPUs mROS runs on, byte for byte against roscpp.

For every test_ws type and a representative set of Debian types, a program
for each target CPU fills random instances through genmros' classes (the
harness's seeded fill functions), serializes, deserializes and serializes
them again, checks the mROS v1 interface and that every proper prefix is
refused, and prints each wire image. The host computes roscpp's images of the
very same instances (same seeds, same fill functions, ros::serialization),
and the two must be equal byte for byte.

The CPUs, each emulated by QEMU from Debian:
- Cortex-M0 (BBC micro:bit, qemu-system-arm -M microbit; 16 KB of RAM, so
  compact instances) and Cortex-M4F (ARM MPS2 AN386): bare metal,
  arm-none-eabi-g++ with newlib, output over semihosting;
- Cortex-A9 with GR-PEACH's compiler line, arm-none-eabi-g++ with newlib,
  run by qemu-arm with semihosting;
- s390x, big-endian: the byte-by-byte wire path, run by qemu-s390x.
The M0 and A9 programs build at -std=gnu++98 (mROS v1's language mode), the
M4 and s390x ones at C++11.
"""

import os
import subprocess

import pytest

from support import cpp_harness
from support.checkout import TEST_WS, run_genmros
from testing.ros_paths import prefix_arguments, ros1_prefixes

pytestmark = [pytest.mark.needs_qemu, pytest.mark.slow]

DEBIAN_SET = ['sensor_msgs/Image', 'sensor_msgs/PointCloud2', 'sensor_msgs/JointState',
              'nav_msgs/Odometry', 'visualization_msgs/MarkerArray', 'std_msgs/Header',
              'std_msgs/Float64MultiArray']

CORTEX_M_LINK = ['--specs=rdimon.specs', '-nostartfiles',
                 '-Wl,--gc-sections', '-L' + cpp_harness.TARGETS_DIR]
CORTEX_M_STARTUP = os.path.join(cpp_harness.TARGETS_DIR, 'cortex_m_startup.c')
# No serial port or monitor: with -nographic QEMU multiplexes them with the
# semihosting output on stdio and drops output once the pipe is full.
BARE_METAL = ['-display', 'none', '-serial', 'none', '-monitor', 'none',
              '-semihosting-config', 'enable=on,target=native', '-kernel']


class Cpu:
    """How to build the check program for one CPU and run it under QEMU."""

    def __init__(self, compiler, flags, standard, run, instances, modes, link=(), startup=None):
        self.compiler = compiler
        self.startup = startup
        self.flags = flags
        self.standard = standard
        self.run = run
        self.instances = instances
        self.modes = modes
        self.link = list(link)


CPUS = {
    'cortex-m0': Cpu('arm-none-eabi-g++', ['-mcpu=cortex-m0', '-mthumb', '-Os'], 'gnu++98',
                     ['qemu-system-arm', '-M', 'microbit'] + BARE_METAL,
                     instances=40, modes=[cpp_harness.COMPACT],
                     link=CORTEX_M_LINK + ['-T', os.path.join(cpp_harness.TARGETS_DIR,
                                                              'microbit.ld')],
                     startup=CORTEX_M_STARTUP),
    'cortex-m4': Cpu('arm-none-eabi-g++', ['-mcpu=cortex-m4', '-mthumb', '-mfloat-abi=hard',
                                           '-mfpu=fpv4-sp-d16', '-O1'], 'c++11',
                     ['qemu-system-arm', '-M', 'mps2-an386'] + BARE_METAL,
                     instances=60,
                     modes=[cpp_harness.BINARY, cpp_harness.TEXT, cpp_harness.COMPACT],
                     link=CORTEX_M_LINK + ['-T', os.path.join(cpp_harness.TARGETS_DIR,
                                                              'mps2_an386.ld')],
                     startup=CORTEX_M_STARTUP),
    'cortex-a9': Cpu('arm-none-eabi-g++', ['-mcpu=cortex-a9', '-marm', '-mfpu=vfpv3',
                                           '-mfloat-abi=hard', '-mno-unaligned-access', '-O1'],
                     'gnu++98', ['qemu-arm', '-cpu', 'cortex-a9'], instances=60,
                     modes=[cpp_harness.BINARY, cpp_harness.TEXT, cpp_harness.COMPACT],
                     link=['--specs=rdimon.specs', '-Wl,--gc-sections']),
    's390x': Cpu('s390x-linux-gnu-g++', ['-O1'], 'c++11', ['qemu-s390x'], instances=60,
                 modes=[cpp_harness.BINARY, cpp_harness.TEXT, cpp_harness.COMPACT],
                 link=['-static']),
}
# Bounded storage on the smallest core, at mROS v1's language mode, and on
# the big-endian CPU: compact instances only, which fit the bounds.
BOUNDED_CPUS = {
    'cortex-m0': CPUS['cortex-m0'],
    's390x': Cpu('s390x-linux-gnu-g++', ['-O1'], 'gnu++98', ['qemu-s390x'], instances=60,
                 modes=[cpp_harness.COMPACT], link=['-static']),
}
# -Wno-psabi: GCC's note that std::vector iterators pass differently since GCC 7.1 (ARM).
FIRMWARE_FLAGS = ['-fno-exceptions', '-fno-rtti', '-Wno-psabi']
RUN_SECONDS = 120


@pytest.fixture(scope='module')
def target_sources(tmp_path_factory):
    """The type set's generated sources, genmros' and gencpp's headers, and
    the host program that prints roscpp's wire images."""
    root = tmp_path_factory.mktemp('target_cpus')
    search_path = cpp_harness.search_path()
    messages = ['%s/%s' % (package, os.path.basename(path)[:-4])
                for package, path in cpp_harness.test_ws_definitions('msg')]
    type_set = cpp_harness.TypeSet(search_path, messages + DEBIAN_SET,
                                   list(cpp_harness.test_ws_definitions('srv')))
    arguments = ['mros-v1-export', '--workspace', TEST_WS, *prefix_arguments(ros1_prefixes())]
    for package in cpp_harness.TEST_WS_PACKAGES:
        arguments += ['--package', package]
    for name in DEBIAN_SET:
        arguments += ['--type', name]
    exports = {'heap': str(root / 'genmros')}
    run_genmros(*arguments, '-o', exports['heap'])
    # Bounded storage with the bounds of compact instances (at most 4 elements
    # and 4 bytes), which they reach.
    exports['bounded'] = str(root / 'bounded')
    bounds = root / 'compact.options'
    bounds.write_text('* max_size:4 max_count:4\n')
    run_genmros(*arguments, '-o', exports['bounded'],
                '--storage', 'bounded', '--options', str(bounds))
    sources, expected = cpp_harness.expected_bytes_program(
        type_set, search_path, root, for_targets=True)
    return type_set, exports, sources, expected


def test_type_set_covers_the_types_named_for_the_targets(target_sources):
    type_set = target_sources[0]
    for name in DEBIAN_SET + ['mros_test/PersonalData', 'mros_test/ArrayTypes',
                              'mros_test/BuiltinTypes', 'mros_test/NestedTypes',
                              'mros_test/LookupPersonRequest', 'mros_test_base/Labeled',
                              'visualization_msgs/Marker', 'geometry_msgs/Pose']:
        assert name in type_set.messages


def _compile(command):
    result = subprocess.run(command, capture_output=True, text=True)
    assert result.returncode == 0, ' '.join(command) + '\n' + result.stderr[-6000:]


def _build(cpu, sources, export, directory):
    program = os.path.join(directory, 'check_' + cpu.standard)
    link = list(cpu.link)
    if cpu.startup:
        # Start-up code is C (it calls main); the C compiler of the same tool chain.
        startup = os.path.join(directory, 'startup.o')
        _compile([cpu.compiler[:-len('g++')] + 'gcc', '-std=c99', '-Wall', '-Wextra', '-Werror']
                 + cpu.flags + ['-c', cpu.startup, '-o', startup])
        link.append(startup)
    warnings = ['-Wall', '-Wextra', '-Werror'] + \
        (['-pedantic'] if cpu.standard != 'gnu++98' else [])
    command = ([cpu.compiler, '-std=' + cpu.standard] + cpu.flags + FIRMWARE_FLAGS + warnings +
               ['-DTARGET_INSTANCES=%du' % cpu.instances,
                '-DTARGET_MODES=%s' % ','.join(map(str, cpu.modes)),
                '-I', export, '-I', os.path.dirname(sources['target_side.cpp']),
                '-I', cpp_harness.TARGETS_DIR,
                '-I', cpp_harness.RANDOM_HEADER_DIR, sources['target_side.cpp'],
                os.path.join(cpp_harness.TARGETS_DIR, 'target_main.cpp')] + link + ['-o', program])
    _compile(command)
    return program


def _cases(output):
    return [line for line in output.splitlines() if line.startswith('case ')]


def _first_difference(expected, actual):
    """A readable account of the first case whose bytes differ."""
    for want, got in zip(expected, actual):
        if want != got:
            want_fields, got_fields = want.split(' '), got.split(' ')
            offset = 0
            while offset < min(len(want_fields[5]), len(got_fields[5])) and \
                    want_fields[5][offset] == got_fields[5][offset]:
                offset += 1
            return ('%s seed %s mode %s: roscpp %s bytes, target %s bytes, '
                    'first difference at byte %d'
                    % (want_fields[1], want_fields[2], want_fields[3], want_fields[4],
                       got_fields[4], offset // 2))
    return 'roscpp gave %d cases, the target %d' % (len(expected), len(actual))


@pytest.mark.parametrize('name, storage', [(name, 'heap') for name in sorted(CPUS)] + [
    (name, 'bounded') for name in sorted(BOUNDED_CPUS)])
def test_wire_images_equal_roscpp_on_the_cpu(target_sources, name, storage, tmp_path):
    type_set, exports, sources, expected_program = target_sources
    cpu = CPUS[name] if storage == 'heap' else BOUNDED_CPUS[name]
    program = _build(cpu, sources, exports[storage], str(tmp_path))
    run = subprocess.run(cpu.run + [program], capture_output=True, text=True, timeout=RUN_SECONDS)
    report = run.stdout.splitlines()
    assert run.returncode == 0, '\n'.join(
        [line for line in report if not line.startswith('case ')][-40:] + [run.stderr[-2000:]])
    assert not [line for line in report if line.startswith('FAIL ')]
    instances = cpu.instances * len(type_set.messages)
    assert report[-1].startswith('checked %d instances, ' %
                                 instances) and report[-1].endswith(': 0 failures')

    expected = subprocess.run([expected_program, str(cpu.instances)] + [str(m) for m in cpu.modes],
                              capture_output=True, text=True, check=True).stdout
    expected_cases, actual_cases = _cases(expected), _cases(run.stdout)
    assert len(expected_cases) == instances
    assert actual_cases == expected_cases, _first_difference(expected_cases, actual_cases)
