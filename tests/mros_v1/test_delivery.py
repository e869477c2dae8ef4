# SPDX-License-Identifier: BSD-3-Clause
"""mROS v1 delivery (mros_v1_delivery.h) keeps a large message it hands a
subscriber off the subscriber task's stack: the library's tasks have a few
KiB (MROS_TASK_STACK_SIZE, 2048 bytes in the samples), and a bounded
message holds its data itself. GCC's -fstack-usage of deliverFrame for a
bounded sensor_msgs/JointState of over 1 KB stays small, for the host and
for GR-PEACH's Cortex-A9 at mROS v1's -Os; a small message stays on the
stack, which costs no RAM of its own. The table of frames published on the
board exists only where the library passes no frame size."""

import os
import re
import subprocess

import pytest

from colcon_mros.mros_v1.rules import DELIVERY_ON_STACK_MAX
from support.checkout import run_genmros
from testing.ros_paths import prefix_arguments, ros1_prefixes

SOURCE = '''#include <message_headers.h>
#include <sensor_msgs/JointState.h>
#include <std_msgs/String.h>
static void received(void*) {}
void deliver(char* frame) {
  callCallback(sensor_msgs::JointState::MROS_TYPE_ID, received, frame);
  callCallback(std_msgs::String::MROS_TYPE_ID, received, frame);
}
'''
COMPILERS = {'host': ['g++', '-O2'],
             'cortex-a9': ['arm-none-eabi-g++', '-Os', '-mcpu=cortex-a9', '-marm',
                           '-mfloat-abi=hard', '-mfpu=vfpv3']}


@pytest.fixture(scope='module')
def bounded_types(tmp_path_factory):
    """An export of a bounded JointState (over 1 KB) and String (a few dozen bytes)."""
    root = tmp_path_factory.mktemp('v1_delivery')
    options = root / 'bounds.options'
    options.write_text('* max_size:32 max_count:16\n')
    include = str(root / 'include')
    run_genmros('mros-v1-export', '--type', 'sensor_msgs/JointState', '--type', 'std_msgs/String',
                '-o', include, *prefix_arguments(ros1_prefixes()),
                '--storage', 'bounded', '--options', str(options))
    return include


@pytest.mark.parametrize('cpu', [
    'host', pytest.param('cortex-a9', marks=pytest.mark.slow)])
def test_delivery_keeps_a_bounded_message_off_the_stack(bounded_types, tmp_path, cpu):
    source = tmp_path / 'deliver.cpp'
    source.write_text(SOURCE)
    subprocess.run(COMPILERS[cpu] + ['-std=gnu++98', '-fno-exceptions', '-fno-rtti',
                                     '-fstack-usage', '-c', '-I', bounded_types,
                                     str(source), '-o', str(tmp_path / 'deliver.o')],
                   check=True, cwd=str(tmp_path))
    with open(str(tmp_path / 'deliver.su')) as stream:
        usage = stream.read()
    frames = [int(match.group(1)) for match in
              re.finditer(r'deliverFrame[^\t]*\t(\d+)\t', usage)]
    callers = [int(match.group(1)) for match in re.finditer(r'deliver\(char\*\)\t(\d+)\t', usage)]
    assert _message_size(COMPILERS[cpu], bounded_types, tmp_path) > 1000
    # deliverFrame, inlined or not, and what calls it: far below the large
    # message; the small one, on the stack, within the bound and a frame's
    # bookkeeping.
    assert frames + callers, usage
    assert max(frames + callers) < DELIVERY_ON_STACK_MAX + 128 == 256, usage


# Publishes and delivers a bounded JointState (over 1 KB) and a bounded
# String (a few dozen bytes), as ros.cpp does.
BOTH_SIZES = '''#include <message_headers.h>
#include <sensor_msgs/JointState.h>
#include <std_msgs/String.h>
static void received(void*) {}
void publish(const sensor_msgs::JointState& joints, const std_msgs::String& text, char* block) {
  joints.memCopy(block);
  text.memCopy(block);
}
void deliver(char* frame, unsigned size) {
  callCallback(sensor_msgs::JointState::MROS_TYPE_ID, received, frame, size);
  callCallback(std_msgs::String::MROS_TYPE_ID, received, frame, size);
}
'''


def _static_symbols(include, tmp_path, *flags):
    """{demangled name: size} of the static data of BOTH_SIZES, compiled
    with flags."""
    source = tmp_path / 'both.cpp'
    source.write_text(BOTH_SIZES)
    subprocess.run(['g++', '-std=gnu++98', '-O2', '-Wall', '-Wextra', '-pedantic', '-Werror', '-c',
                    '-I', include] + list(flags) + [str(source), '-o', str(tmp_path / 'both.o')],
                   check=True)
    symbols = subprocess.run(['nm', '-C', '-S', str(tmp_path / 'both.o')], capture_output=True,
                             text=True, check=True).stdout
    return {match.group(3): int(match.group(1), 16)
            for match in re.finditer(r'^\S+ (\S+) ([BbDdu]) (.*)$', symbols, re.M)}


def test_only_a_large_message_takes_static_storage(bounded_types, tmp_path):
    static = _static_symbols(bounded_types, tmp_path)
    storage = {name: size for name, size in static.items() if 'DeliveryStorage' in name}
    assert list(storage) == [
        'mros::wire::DeliveryStorage<sensor_msgs::JointState, true>::place()::storage'], static
    assert list(storage.values())[0] > 1000 > DELIVERY_ON_STACK_MAX


def test_the_frame_table_exists_only_where_the_library_passes_no_frame_size(bounded_types,
                                                                            tmp_path):
    # mROS v1 as it is: memCopy notes each frame for on-board delivery.
    table = [name for name in _static_symbols(bounded_types, tmp_path) if 'OnBoardFrames' in name]
    assert table == ['mros::wire::OnBoardFrames::table()::slots']
    # genmros' patch set: ros.cpp defines the macro and passes each size.
    patched = _static_symbols(bounded_types, tmp_path, '-DMROS_LIBRARY_PASSES_FRAME_SIZE')
    assert [name for name in patched if 'OnBoardFrames' in name] == []
    # There the library's three-argument call, which needs the table, does not compile.
    source = tmp_path / 'unsized.cpp'
    source.write_text('#include <message_headers.h>\n#include <std_msgs/String.h>\n'
                      'static void received(void*) {}\n'
                      'void deliver(char* frame) { callCallback(std_msgs::String::MROS_TYPE_ID, '
                      'received, frame); }\n')
    refused = subprocess.run(['g++', '-std=gnu++98', '-fsyntax-only', '-I', bounded_types,
                              '-DMROS_LIBRARY_PASSES_FRAME_SIZE', str(source)],
                             capture_output=True, text=True)
    assert refused.returncode != 0 and 'callCallback' in refused.stderr, refused.stderr


def _message_size(compiler, include, tmp_path):
    """sizeof the bounded JointState for compiler's CPU, read from an object."""
    probe = tmp_path / 'size.cpp'
    probe.write_text('#include <sensor_msgs/JointState.h>\n'
                     'char size_probe[sizeof(sensor_msgs::JointState)];\n')
    subprocess.run(compiler + ['-std=gnu++98', '-c', '-I', include, str(probe), '-o',
                               str(tmp_path / 'size.o')], check=True)
    nm = 'arm-none-eabi-nm' if compiler[0].startswith('arm') else 'nm'
    symbols = subprocess.run([nm, '-S', str(tmp_path / 'size.o')], capture_output=True, text=True,
                             check=True).stdout
    return int(re.search(r'^\S+ (\S+) [BbCc] size_probe$', symbols, re.M).group(1), 16)


DELIVERY_PROGRAM = r'''#include <cstdio>
#include <string>
#include <message_headers.h>
#include <std_msgs/String.h>
static int delivered = 0;
static std::string text;
static void received(void* message) {
  ++delivered;
  text = static_cast<std_msgs::String*>(message)->data;
}
int main() {
  // "hello" as a frame: a length word the library left stale (0), then the
  // body: the string's length and its bytes.
  char frame[4 + 4 + 5] = {0, 0, 0, 0, 5, 0, 0, 0, 'h', 'e', 'l', 'l', 'o'};
  callCallback(std_msgs::String::MROS_TYPE_ID, received, frame, sizeof frame);
  std::printf("whole: %d %s\n", delivered, text.c_str());
  callCallback(std_msgs::String::MROS_TYPE_ID, received, frame, sizeof frame - 1);
  callCallback(std_msgs::String::MROS_TYPE_ID, received, frame, 3);
  std::printf("short: %d\n", delivered);
  callCallback(std_msgs::String::MROS_TYPE_ID, received, frame);
  std::printf("no size: %d\n", delivered);
  return 0;
}
'''


def test_delivery_reads_no_further_than_the_frame_size_the_library_gives(tmp_path):
    # genmros' patch set for the library passes the frame's size
    # (frame-size-to-delivery); without it, delivery believes the length
    # word of a frame it did not write (here a stale 0: nothing decodes).
    include = str(tmp_path / 'include')
    run_genmros('mros-v1-export', '--type', 'std_msgs/String', '-o', include,
                *prefix_arguments(ros1_prefixes()))
    with open(os.path.join(include, 'message_headers.h')) as stream:
        assert '#define MROS_CALL_CALLBACK_TAKES_FRAME_SIZE 1\n' in stream.read()
    source = tmp_path / 'deliver.cpp'
    source.write_text(DELIVERY_PROGRAM)
    program = str(tmp_path / 'deliver')
    subprocess.run(['g++', '-std=gnu++98', '-Wall', '-Wextra', '-Werror', '-I', include,
                    str(source), '-o', program], check=True)
    output = subprocess.run([program], capture_output=True, text=True, check=True).stdout
    assert output == 'whole: 1 hello\nshort: 1\nno size: 1\n'
