# SPDX-License-Identifier: BSD-3-Clause
"""The generated headers and templates.hpp compile against mros2's runtime
calls, in the order src/mros2.cpp (v0.5.4) makes them, -Wall -Wextra clean
for the host and the boards' CPUs; on the host the stand-in runtime's
publish sends what Fast-CDR writes, header and padding included, through
its 100-byte buffer and its 64-byte fragments alike.

The stand-in (testing/mros2_runtime) declares what mros2.h declares
and defines the four templates as mros2.cpp does, with its buffers; the
network is left out.
"""

import os
import re
import subprocess

import pytest

from support.checkout import REPO, run_genmros
from testing import fastcdr
from testing.ros_paths import prefix_arguments, ros2_prefixes

RUNTIME = os.path.join(REPO, 'testing', 'mros2_runtime')
FLAGS = ['-std=c++14', '-Wall', '-Wextra', '-Werror']
TARGETS = {
    'host': ['g++'],
    'cortex-m4': ['arm-none-eabi-g++', '-mcpu=cortex-m4', '-mthumb', '-mfloat-abi=hard',
                  '-mfpu=fpv4-sp-d16', '-fno-exceptions', '-fno-rtti'],
    'cortex-m0': ['arm-none-eabi-g++', '-mcpu=cortex-m0', '-mthumb', '-fno-exceptions',
                  '-fno-rtti'],
}
PUBLISH = ['test_interface_files/msg/Nested', 'test_interface_files/msg/Strings',
           'test_interface_files/msg/MultiNested', 'test_interface_files/msg/WStrings']
SUBSCRIBE = ['test_interface_files/msg/Arrays', 'test_interface_files/msg/BasicTypes']

MAIN = r'''
#include <stdio.h>
#include "mros2.h"
#include "test_interface_files/msg/basic_types.hpp"
#include "test_interface_files/msg/nested.hpp"
#include "test_interface_files/msg/strings.hpp"

static int received;
// As mros2 calls a callback: through void (*)(intptr_t).
static void on_basic(intptr_t msg) {
  received = reinterpret_cast<test_interface_files::msg::BasicTypes*>(msg)->int32_value;
}

static void print_sent() {
  for (uint32_t i = 0; i < g_sent_size; ++i) printf("%%02x", g_sent[i]);
  printf("\n");
}

int main() {
  mros2::Node node;
  mros2::Publisher pub = node.create_publisher<test_interface_files::msg::Strings>("chatter", 10);
  printf("%%s %%s\n", pub.topic_name.c_str(), g_type_name);
  test_interface_files::msg::Strings strings;
  strings.string_value = "%(long_text)s";
  pub.publish(strings);
  print_sent();
  pub.publish(strings);
  print_sent();
  test_interface_files::msg::Nested nested;
  nested.basic_types_value.float64_value = 2.5;
  nested.basic_types_value.uint8_value = 7;
  pub.publish(nested);
  print_sent();
  static const uint8_t sample[] = {%(basic_sample)s};
  rtps::ReaderCacheChange change(sample, sizeof sample);
  mros2::SubscribeDataType data = {on_basic, 0};
  mros2::Subscriber::callback_handler<test_interface_files::msg::BasicTypes>(&data, change);
  printf("%%d\n", received);
  return 0;
}
'''


@pytest.fixture(scope='module')
def export(tmp_path_factory):
    root = str(tmp_path_factory.mktemp('mros2_runtime_export'))
    arguments = ['mros2-export', *prefix_arguments(ros2_prefixes()), '-o', root]
    for name in PUBLISH:
        arguments += ['--publish', name]
    for name in SUBSCRIBE:
        arguments += ['--subscribe', name]
    run_genmros(*arguments)
    return root


@pytest.mark.parametrize('target', ['host', pytest.param('cortex-m4', marks=pytest.mark.slow),
                                    pytest.param('cortex-m0', marks=pytest.mark.slow)])
def test_the_runtime_calls_compile_warning_free(export, tmp_path, target):
    command = TARGETS[target] + FLAGS + ['-I', export, '-I', RUNTIME, '-c',
                                         os.path.join(RUNTIME, 'mros2_runtime_check.cpp'),
                                         '-o', str(tmp_path / 'check.o')]
    result = subprocess.run(command, capture_output=True, text=True)
    assert result.returncode == 0 and result.stderr == '', result.stderr[-4000:]


def test_a_type_name_too_long_for_embedded_rtps_stops_the_build(export, tmp_path):
    """mros2-posix's rtps/config.h keeps type names in 40 bytes, NUL
    included; every listed name is longer and is named with what it needs."""
    def compile_with(length):
        return subprocess.run(['g++'] + FLAGS + [
            '-DSTAND_IN_MAX_TYPENAME_LENGTH=%d' % length, '-I', export, '-I', RUNTIME, '-c',
            os.path.join(RUNTIME, 'mros2_runtime_check.cpp'), '-o', str(tmp_path / 'check.o')],
            capture_output=True, text=True)
    dds_names = ['%s::msg::dds_::%s_' % (n.split('/')[0], n.split('/')[2])
                 for n in PUBLISH + SUBSCRIBE]
    result = compile_with(40)
    assert result.returncode != 0
    for dds_name in dds_names:
        assert ('%s: its DDS type name and its NUL needs rtps::Config::MAX_TYPENAME_LENGTH >= %d '
                '(rtps/config.h)' % (dds_name, len(dds_name) + 1)) in result.stderr
    assert compile_with(max(len(name) for name in dds_names) + 1).returncode == 0


def test_a_subscribed_message_too_large_for_the_reader_stack_stops_the_build(export, tmp_path):
    """mros2's callback_handler holds the message on the reader thread's
    stack: templates.hpp holds sizeof(T) and the margin (512 unless the
    firmware defines it) against THREAD_POOL_READER_STACKSIZE, for the
    subscribed types only (the published MultiNested holds three Arrays)."""
    def compile_with(stack, margin=None):
        defines = ['-DSTAND_IN_THREAD_POOL_READER_STACKSIZE=%d' % stack]
        if margin is not None:
            defines.append('-DMROS2_READER_STACK_MARGIN=%d' % margin)
        return subprocess.run(['g++'] + FLAGS + defines + [
            '-I', export, '-I', RUNTIME, '-c', os.path.join(RUNTIME, 'mros2_runtime_check.cpp'),
            '-o', str(tmp_path / 'check.o')], capture_output=True, text=True)
    result = compile_with(600)
    assert result.returncode != 0
    reasons = re.findall(r'static assertion failed: (.*)', result.stderr)
    assert reasons == [
        "test_interface_files::msg::%s: mros2's callback_handler holding the message on the "
        "reader thread's stack, with MROS2_READER_STACK_MARGIN bytes for the frames below it "
        'needs rtps::Config::THREAD_POOL_READER_STACKSIZE >= sizeof(test_interface_files::msg::%s)'
        ' + MROS2_READER_STACK_MARGIN (rtps/config.h)' % (name, name)
        for name in ('Arrays',)], result.stderr[-3000:]  # BasicTypes fits in 600
    # g++ says what sizeof(Arrays) + the margin came to; exactly that much builds.
    needed = int(re.search(r'\((\d+) <= 600\)', result.stderr).group(1))
    assert compile_with(needed).returncode == 0
    assert compile_with(needed, margin=513).returncode != 0


def test_the_runtime_sends_what_fastcdr_writes(export, tmp_path):
    program = fastcdr.build(str(tmp_path / 'fastcdr'))
    long_text = 'x' * 150  # over mros2's 100-byte buffer: fragments
    basic = [('bool', True), ('octet', 1), ('uint8', 2), ('float32', 0.5), ('float64', 1.25),
             ('int8', -3), ('uint8', 4), ('int16', -5), ('uint16', 6), ('int32', -123456),
             ('uint32', 8), ('int64', -9), ('uint64', 10)]
    sample = fastcdr.encode(program, basic)
    source = tmp_path / 'main.cpp'
    source.write_text(MAIN % {'long_text': long_text,
                              'basic_sample': ', '.join(str(b) for b in sample)})
    binary = str(tmp_path / 'main')
    result = subprocess.run(['g++'] + FLAGS + ['-I', export, '-I', RUNTIME, str(source),
                                               os.path.join(RUNTIME, 'mros2_runtime_check.cpp'),
                                               '-o', binary], capture_output=True, text=True)
    assert result.returncode == 0, result.stderr[-4000:]
    lines = subprocess.run([binary], capture_output=True, text=True, check=True).stdout.split()
    assert lines[:2] == ['rt/chatter', 'test_interface_files::msg::dds_::Strings_']
    strings = [('string', long_text.encode())] + [('string', text) for text in (
        b'Hello world!', b"Hello'world!", b'Hello"world!', b"Hello'world!", b'Hello"world!')]
    strings += [('string', b'')] + [('string', text) for text in (
        b'Hello world!', b"Hello'world!", b'Hello"world!', b"Hello'world!", b'Hello"world!')]
    expected = fastcdr.encode(program, strings)
    expected += bytes(-len(expected) % 4)
    assert bytes.fromhex(lines[2]) == expected      # in 64-byte fragments
    assert bytes.fromhex(lines[3]) == expected      # and again
    nested = [(kind, {'float64': 2.5}.get(kind, 7 if n == 6 else 0)) for n, (kind, _)
              in enumerate(basic)]
    nested[0] = ('bool', False)
    nested_bytes = fastcdr.encode(program, nested)
    assert bytes.fromhex(lines[4]) == nested_bytes + bytes(-len(nested_bytes) % 4)
    assert lines[5] == '-123456'


def test_a_bad_count_through_the_unsized_receive_grows_nothing(export, tmp_path):
    """mros2's callback_handler calls copyFromBuf without a size; a sample
    whose sequence count says 2**31 elements must not make the vector try to
    hold them (it would take 16 GB and stop the board)."""
    source = tmp_path / 'bad_count.cpp'
    source.write_text(
        '#include <stdio.h>\n#include "test_interface_files/msg/unbounded_sequences.hpp"\n'
        'int main() {\n'
        '  static uint8_t sample[1 << 17];\n'
        '  sample[0] = 0; sample[1] = 0; sample[2] = 0; sample[3] = 0x80;  // bool_values: 2**31\n'
        '  test_interface_files::msg::UnboundedSequences message;\n'
        '  message.copyFromBuf(sample);\n'
        '  printf("%zu\\n", message.bool_values.size());\n'
        '  return 0;\n}\n')
    binary = str(tmp_path / 'bad_count')
    subprocess.run(['g++'] + FLAGS + ['-I', export, str(source), '-o', binary], check=True)
    result = subprocess.run(['sh', '-c', 'ulimit -v 1000000 && %s' % binary], capture_output=True,
                            text=True)
    assert result.returncode == 0, result.stderr
    assert result.stdout.strip() == '0'
