# SPDX-License-Identifier: BSD-3-Clause
"""The warning matrix of the mros2 headers: every message type of
test_ws_ros2 and of ROS 2's test interface files (Debian's
ros2-test-interface-files), and the float64[64] the warning was first
found with, published in fragments by a caller written as mros2's
``Publisher::publish`` is (an array ``uint8_t frag_buf[N]``, the first
fragment after the 4-byte encapsulation header), in one translation unit, compiled with every
warning flag of :data:`WARNING_FLAGS` by {g++, arm-none-eabi-g++, clang++}
x {-O0 .. -Os} x {C++11 .. C++20}. The fragments of FLATTENED_SIZE bytes
are sent with every call inlined (GCC's flatten), so that the compiler
holds every copy of every walk against frag_buf, not only those it
happens to inline.

A program built for the host also checks the bytes: each type, decoded
from one patterned sample, goes out in fragments of N = 16, 64 and 100
bytes, and what the fragments carry, put back together, must be what
copyToBuf writes. tests/mros2/test_warning_matrix.py compiles and runs a
part of the matrix, bench/mros2/warning_matrix.py all of it.

- :func:`export_headers`: the types' headers, exported with genmros;
- :func:`message_types`: the types an export holds (header, C++ name);
- :func:`write_program`: the caller's source for those types;
- :func:`compile_command`, :func:`build`: one configuration's build, and
  the warnings it gave;
- :func:`run`: a host program's byte check.
"""

import collections
import glob
import os
import re
import subprocess
import sys

from testing import ros_paths
from testing.interface_packages import write_interface_package

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
TEST_WS_ROS2 = os.path.join(REPO, 'test_ws_ros2')
# test_ws_ros2's packages, and ROS 2's test interface files, installed as
# the package test_interface_files (Debian: under /usr).
PACKAGES = ('mros2_base_msgs', 'mros2_test_msgs', 'test_interface_files')
# And the type the warning was first found with: a fixed array larger than
# every fragment buffer, whose one copy the compiler held against the
# buffer; in a package of its own, written beside the export.
FIRST_FINDING_PACKAGE = 'warning_matrix_msgs'
FIRST_FINDING_MESSAGES = {'WideArray': 'float64[64] values\n'}

COMPILERS = {
    'g++': ['g++'],
    # A board's CPU (mros2's STM32 boards are Cortex-M): compiled, not linked.
    'arm-none-eabi-g++': ['arm-none-eabi-g++', '-mcpu=cortex-m4', '-mthumb'],
    'clang++': ['clang++'],
}
COMPILE_ONLY = ('arm-none-eabi-g++',)
LEVELS = ('-O0', '-O1', '-O2', '-O3', '-Os')
STANDARDS = ('c++11', 'c++14', 'c++17', 'c++20')
WARNING_FLAGS = ['-Wall', '-Wextra', '-Wpedantic', '-Wconversion', '-Wsign-conversion',
                 '-Werror']
# The sizes of the caller's fragment buffer: smaller than most images, the
# 64 bytes of mros2's frag_buf, and the 100 of its whole-message buf.
FRAGMENT_BUFFER_SIZES = (16, 64, 100)
# The size whose fragments are also sent flattened (see PROGRAM): the
# smallest, which most copies are over.
FLATTENED_SIZE = 16

Configuration = collections.namedtuple('Configuration', 'compiler level standard')
Build = collections.namedtuple('Build', 'configuration output warnings errors stderr')

# A diagnostic of a -W flag, a warning or (with -Werror) an error: its flag.
_WARNING = re.compile(
    r'^\S+:\d+:\d+: (?:warning|error): .*\[(?:-Werror,)?-W(?:error=)?([\w+=-]+)\]$', re.M)
# Every error, and those that are warnings -Werror made errors.
_ERROR = re.compile(r'^\S+:\d+:\d+: (?:fatal )?error: ', re.M)
_WERROR = re.compile(r'^\S+:\d+:\d+: error: .*\[-Werror[=,]-?W?[\w+=-]+\]$', re.M)


def every_configuration():
    """The whole matrix, compiler by compiler, then level, then standard."""
    return [Configuration(compiler, level, standard) for compiler in COMPILERS
            for level in LEVELS for standard in STANDARDS]


def export_headers(include_dir):
    """The headers of every message type and service half of PACKAGES and
    FIRST_FINDING_PACKAGE, written into include_dir with genmros' mros2 back end, as
    users run it (the issue's package in a workspace beside include_dir)."""
    issue_workspace = write_interface_package(
        include_dir.rstrip(os.sep) + '-workspace', FIRST_FINDING_PACKAGE, FIRST_FINDING_MESSAGES,
        'The message of testing/mros2_warning_matrix.py.')
    result = subprocess.run(
        [sys.executable, '-m', 'colcon_mros', 'mros2-export', '--workspace', TEST_WS_ROS2,
         '--workspace', issue_workspace, '-o', include_dir]
        + ros_paths.prefix_arguments(ros_paths.ros2_prefixes())
        + ['--package=%s' % p for p in PACKAGES + (FIRST_FINDING_PACKAGE,)],
        capture_output=True, text=True, cwd=REPO)
    if result.returncode != 0:
        raise RuntimeError('genmros mros2-export failed:\n%s' % result.stderr[-4000:])
    return include_dir


def message_types(include_dir):
    """(header, C++ name) of every message class of the export in
    include_dir, a service's request and response included: each
    pkg/msg/name.hpp declares its classes in namespace pkg::msg."""
    types = []
    for path in sorted(glob.glob(os.path.join(include_dir, '*', '*', '*.hpp'))):
        header = os.path.relpath(path, include_dir)
        namespace = '::'.join(header.split(os.sep)[:2])
        with open(path) as stream:
            classes = re.findall(r'^class (\w+) : public mros2_wire::Message<\1>$',
                                 stream.read(), re.M)
        types += [(header, '%s::%s' % (namespace, name)) for name in classes]
    return types


# The types whose fragments are sent as the compiler inlines the calls, not
# flattened: MultiNested's walk flattened (three levels of arrays and
# sequences of Arrays, BoundedSequences and UnboundedSequences, each
# flattened on its own) takes g++ -O1 a minute.
AS_COMPILED = ('test_interface_files::msg::MultiNested',)

# The caller. publish_in_fragments is mros2's Publisher::publish (v0.5.4)
# for a message over its buffer, with frag_buf a local array of N bytes: the
# compiler sees the object copyToFragBuf writes into, and warns where a copy
# could pass its end.
PROGRAM = r'''// SPDX-License-Identifier: BSD-3-Clause
// Written by testing/mros2_warning_matrix.py: every type of the export
// published in fragments as mros2's Publisher::publish sends it, the bytes
// checked against copyToBuf's.
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include <vector>

%(includes)s

namespace {

typedef std::vector<uint8_t> Bytes;

// A received sample every type decodes from: each 32-bit word 1, 2 or 3,
// so that every sequence and string holds one to three elements, within
// every bound of the types, and every number is set.
Bytes patterned_sample() {
  Bytes sample(1 << 16);
  for (size_t i = 0; i < sample.size(); ++i)
    sample[i] = static_cast<uint8_t>(i %% 4 == 0 ? 1 + i / 4 %% 3 : 0);
  return sample;
}

// What the last publication sent, the encapsulation header left out.
uint8_t sent[1 << 16];
uint32_t sent_size;

// One call of mros2's publish loop for msg, with a frag_buf of N bytes:
// the next fragment, added to sent; in the first, the encapsulation
// header and the image's first N - 4 bytes.
template <size_t N, class T> typename T::FragCopyReturnType send_fragment(T& msg) {
  uint8_t frag_buf[N];
  uint32_t cdr_enc_offset = 0;
  if (0 == msg.getPubCnt()) {
    cdr_enc_offset = 4;
    frag_buf[0] = 0;
    frag_buf[1] = 1;
    frag_buf[2] = 0;
    frag_buf[3] = 0;
  }
  typename T::FragCopyReturnType ret = msg.copyToFragBuf(
      &frag_buf[cdr_enc_offset], static_cast<uint32_t>(sizeof(frag_buf) - cdr_enc_offset));
  if (ret.second <= sizeof sent - sent_size) {
    memcpy(sent + sent_size, &frag_buf[cdr_enc_offset], ret.second);
    sent_size += ret.second;
  }
  return ret;
}

// send_fragment flattened: every call in it inlined, the message's walk
// included, so that the compiler sees frag_buf in every copy, as in a
// firmware that publishes the type from one place.
template <size_t N, class T>
__attribute__((flatten)) typename T::FragCopyReturnType send_fragment_flattened(T& msg) {
  return send_fragment<N>(msg);
}

// How a type's fragments are sent: through send_fragment as the compiler
// chooses to inline it, or flattened.
struct AsCompiled {
  template <size_t N, class T> static typename T::FragCopyReturnType send(T& msg) {
    return send_fragment<N>(msg);
  }
};
struct Flattened {
  template <size_t N, class T> static typename T::FragCopyReturnType send(T& msg) {
    return send_fragment_flattened<N>(msg);
  }
};

// mros2's publish of msg in fragments of N bytes: calls that end with
// {true, 0}, each before it writing a byte at least. False if they did
// not end.
template <size_t N, class How, class T> bool publish_in_fragments(T& msg) {
  sent_size = 0;
  const uint32_t announced = msg.calcTotalSize();
  for (uint32_t calls = 0; calls <= announced; ++calls) {
    typename T::FragCopyReturnType ret = How::template send<N>(msg);
    if (ret.first && ret.second == 0) {
      msg.resetCount();
      return true;
    }
  }
  return false;
}

// 1 if msg's fragments of N bytes carry other bytes than image, after
// naming type and N.
template <size_t N, class How, class T> int differs(const char* type, T& msg, const Bytes& image) {
  if (publish_in_fragments<N, How>(msg) && sent_size == image.size() &&
      memcmp(sent, image.data(), sent_size) == 0)
    return 0;
  printf("differs %%s %%u\n", type, static_cast<unsigned>(N));
  return 1;
}

// The failures of type: the sample refused, or fragments of some size that
// carry other bytes than copyToBuf writes.
template <class How, class T> int check(const char* type, const Bytes& sample) {
  T msg;
  if (!msg.copyFromBuf(sample.data(), static_cast<uint32_t>(sample.size()))) {
    printf("refused %%s\n", type);
    return 1;
  }
  Bytes image(msg.calcRawTotalSize());
  msg.copyToBuf(image.data());
  msg.resetCount();
  return %(publications)s;
}

}  // namespace

int main() {
  const Bytes sample = patterned_sample();
  int failures = 0;
%(checks)s
  printf("%%d types, %%d fragment buffer sizes, %%d failures\n", %(type_count)d, %(size_count)d,
         failures);
  return failures == 0 ? 0 : 1;
}
'''


def write_program(types, path):
    """The caller's source for types ((header, C++ name) pairs), at path."""
    text = PROGRAM % {
        'includes': '\n'.join('#include "%s"' % header
                              for header in sorted({header for header, _ in types})),
        'publications': ' +\n         '.join(
            'differs<%d, %s>(type, msg, image)' % (size, 'How' if size == FLATTENED_SIZE
                                                   else 'AsCompiled')
            for size in FRAGMENT_BUFFER_SIZES),
        'checks': '\n'.join('  failures += check<%s, %s>("%s", sample);' % (
            'AsCompiled' if name in AS_COMPILED else 'Flattened', name, name)
            for _, name in types),
        'type_count': len(types),
        'size_count': len(FRAGMENT_BUFFER_SIZES),
    }
    with open(path, 'w') as stream:
        stream.write(text)
    return path


def compile_command(configuration, include_dir, source, output):
    """The command line that builds source for configuration into output:
    a program, or an object for a compiler in COMPILE_ONLY."""
    return (COMPILERS[configuration.compiler]
            + ['-std=' + configuration.standard, configuration.level] + WARNING_FLAGS
            + ['-I', include_dir, source, '-o', output]
            + (['-c'] if configuration.compiler in COMPILE_ONLY else []))


def build(configuration, include_dir, source, out_dir):
    """Builds source for configuration in out_dir: a :class:`Build`, its
    output None when the compiler failed, warnings the flags of its -W
    diagnostics in order, errors its count of other errors."""
    name = '%s%s-%s' % (configuration.compiler, configuration.level, configuration.standard)
    output = os.path.join(out_dir, name + ('.o' if configuration.compiler in COMPILE_ONLY
                                           else ''))
    result = subprocess.run(compile_command(configuration, include_dir, source, output),
                            capture_output=True, text=True)
    warnings = _WARNING.findall(result.stderr)
    errors = len(_ERROR.findall(result.stderr)) - len(_WERROR.findall(result.stderr))
    return Build(configuration, output if result.returncode == 0 else None, warnings, errors,
                 result.stderr)


def run(program):
    """A host program's check: (types, fragment buffer sizes, failures,
    the lines naming each failure)."""
    result = subprocess.run([program], capture_output=True, text=True, timeout=120)
    lines = result.stdout.splitlines()
    summary = re.match(r'^(\d+) types, (\d+) fragment buffer sizes, (\d+) failures$',
                       lines[-1] if lines else '')
    if summary is None or result.stderr:
        raise RuntimeError('%s failed (%d):\n%s%s' % (program, result.returncode,
                                                      result.stdout[-2000:], result.stderr))
    types, sizes, failures = (int(group) for group in summary.groups())
    return types, sizes, failures, lines[:-1]
