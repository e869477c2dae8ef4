#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""How fast genmros' mros2 messages encode and decode, side by side with Fast-CDR.

    /usr/bin/python3 bench/mros2/codec_speed.py [--rounds N] [--seconds S] [--keep DIR]

For std_msgs/String, geometry_msgs/Twist, sensor_msgs/JointState (6 joints),
sensor_msgs/Imu, sensor_msgs/Image (640x480 rgb8) and
test_interface_files/msg/MultiNested: the headers of `genmros mros2-export`
(the ROS 2 packages written from rosbags' type store, as the tests do, and
ROS 2's test interface files from the ROS 2 prefixes), and one C++ program (-O2, host)
that fills an instance of each type with fixed data and times, on that same
C++ object:

- ours encode: copyToBuf into a preallocated buffer;
- Fast-CDR encode: a serialize function generated here from genmros' model
  (Cdr::serialize per number and string, Fast-CDR's std::array and
  std::vector overloads for containers of numbers, loops for strings and
  nested messages), a FastBuffer over a preallocated buffer, the Cdr reset
  every round (Debian's libfastcdr-dev 1.0.26, what Fast DDS' type support
  serializes with);
- ours decode: the checked copyFromBuf(data, size);
- Fast-CDR decode into the same C++ type.

Before timing, the program checks that both encoders write the same bytes
(both buffers zeroed first: Fast-CDR leaves padding bytes as the buffer held
them) and that Fast-CDR's decode of them encodes back to them. Each figure
is the median of --rounds timed loops of about --seconds each; decoding
reuses one object, so vectors keep their capacity, for both.
"""

import argparse
import os
import subprocess
import sys
import tempfile

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
TEST_PYTHON = os.path.join(REPO, 'build', 'test-python')
GENMROS = ['/usr/bin/python3', '-m', 'colcon_mros']
ENVIRONMENT = dict(os.environ, PYTHONPATH=REPO)

ROSBAGS_TYPES = ['std_msgs/msg/String', 'geometry_msgs/msg/Twist', 'sensor_msgs/msg/JointState',
                 'sensor_msgs/msg/Imu', 'sensor_msgs/msg/Image']
PREFIX_TYPES = ['test_interface_files/msg/MultiNested']
# Sequence lengths other than the default (3, or a bounded sequence's maximum if smaller).
COUNTS = {
    ('sensor_msgs/msg/JointState', 'name'): 6,
    ('sensor_msgs/msg/JointState', 'position'): 6,
    ('sensor_msgs/msg/JointState', 'velocity'): 6,
    ('sensor_msgs/msg/JointState', 'effort'): 6,
    ('sensor_msgs/msg/Image', 'data'): 640 * 480 * 3,
}
# Fixed values other than the generated ones: C++ expressions.
VALUES = {
    ('sensor_msgs/msg/Image', 'height'): '480',
    ('sensor_msgs/msg/Image', 'width'): '640',
    ('sensor_msgs/msg/Image', 'step'): '640 * 3',
    ('sensor_msgs/msg/Image', 'encoding'): '"rgb8"',
    ('std_msgs/msg/String', 'data'): '"Hello from mros2, message number 42"',
    ('std_msgs/msg/Header', 'frame_id'): '"base_link"',
}
DEFAULT_COUNT = 3
TEXT = 'joint_%u'


def _models(workspace):
    sys.path.insert(0, REPO)
    from colcon_mros.core.storage import HeapStorage
    from colcon_mros.ros2.interfaces import all_packages
    from colcon_mros.ros2.model import ModelBuilder
    ours = ModelBuilder(all_packages([workspace], []), HeapStorage())
    from testing.ros_paths import ros2_prefixes
    installed = ModelBuilder(all_packages((), ros2_prefixes()), HeapStorage())
    return ([ours.message(name) for name in ROSBAGS_TYPES]
            + [installed.message(name) for name in PREFIX_TYPES])


def _all_types(messages):
    """Every message type of messages and the types they contain, contained first."""
    ordered, seen = [], set()

    def visit(message):
        if message.full_name in seen:
            return
        seen.add(message.full_name)
        for member in message.members:
            if member.element == 'message':
                visit(member.message)
        ordered.append(message)
    for message in messages:
        visit(message)
    return ordered


class Emitter:
    """The C++ of the benchmark: fill, Fast-CDR serialize and deserialize per type."""

    def __init__(self):
        from colcon_mros.mros2.cpp import NUMBER_TYPES, CppMember, CppMessageName, identifier
        self.number_types = NUMBER_TYPES
        self.cpp_member = CppMember
        self.cpp_name = lambda message: CppMessageName(message).cpp_name
        self.header = lambda message: CppMessageName(message).header
        self.identifier = identifier

    def _count(self, message, member):
        if member.container == 'array':
            return str(member.count)
        count = COUNTS.get((message.full_name, member.name), DEFAULT_COUNT)
        return str(count if member.count is None else min(count, member.count))

    def _value(self, message, member, index):
        """A C++ expression of an element's fixed value; index an expression."""
        fixed = VALUES.get((message.full_name, member.name))
        if fixed is not None:
            return fixed
        if member.element == 'string':
            return 'text("%s", %s)' % (TEXT, index)
        number = self.number_types[member.number_type]
        if member.number_type == 'boolean':
            return '((seed + %s) %% 2 == 1)' % index
        if member.number_type in ('float', 'double'):
            return 'static_cast<%s>(seed * 0.5 + %s * 0.25 + 0.125)' % (number, index)
        return 'static_cast<%s>(seed * 7u + %s * 3u + 1u)' % (number, index)

    def fill(self, message):
        lines = ['void fill(%s& m, unsigned seed) {' % self.cpp_name(message), '  (void)seed;']
        for member in message.members:
            if member.element == 'wstring':
                raise SystemExit('no wstring in this benchmark: %s' % message.full_name)
            name = 'm.' + self.identifier(member.name)
            if member.container is None:
                if member.element == 'message':
                    lines.append('  fill(%s, seed + 1);' % name)
                elif member.element == 'string' and member.string_bound is not None:
                    lines.append('  %s = std::string(%s).substr(0, %d).c_str();'
                                 % (name, self._value(message, member, 'seed'),
                                    member.string_bound))
                else:
                    lines.append('  %s = %s;' % (name, self._value(message, member, 'seed')))
                continue
            count = self._count(message, member)
            if member.container != 'array':
                lines.append('  %s.resize(%s);' % (name, count))
            lines.append('  for (unsigned i = 0; i < %s; ++i) {' % count)
            if member.element == 'message':
                lines.append('    fill(%s[i], seed + i);' % name)
            elif member.element == 'string' and member.string_bound is not None:
                lines.append('    %s[i] = std::string(%s).substr(0, %d).c_str();'
                             % (name, self._value(message, member, 'i'), member.string_bound))
            else:
                lines.append('    %s[i] = %s;' % (name, self._value(message, member, 'i')))
            lines.append('  }')
        return lines + ['}']

    def serialize(self, message):
        lines = ['void fcdr_serialize(Cdr& cdr, const %s& m) {' % self.cpp_name(message)]
        for member in message.members:
            name = 'm.' + self.identifier(member.name)
            bounded_string = member.element == 'string' and member.string_bound is not None

            def element(item):
                if member.element == 'message':
                    return 'fcdr_serialize(cdr, %s);' % item
                if bounded_string:
                    return 'cdr.serialize(%s.c_str());' % item
                return 'cdr.serialize(%s);' % item
            if member.container is None:
                lines.append('  ' + element(name))
            elif member.element == 'number' and member.container == 'bounded_sequence':
                lines.append('  cdr.serialize(static_cast<uint32_t>(%s.size()));' % name)
                lines.append('  cdr.serializeArray(%s.data(), %s.size());' % (name, name))
            elif member.element == 'number':
                lines.append('  cdr.serialize(%s);' % name)  # std::array, std::vector
            else:
                if member.container != 'array':
                    lines.append('  cdr.serialize(static_cast<uint32_t>(%s.size()));' % name)
                lines.append('  for (const auto& e : %s) %s' % (name, element('e')))
        return lines + ['}']

    def deserialize(self, message):
        lines = ['void fcdr_deserialize(Cdr& cdr, %s& m) {' % self.cpp_name(message),
                 '  uint32_t n = 0;', '  (void)n;']
        for member in message.members:
            name = 'm.' + self.identifier(member.name)
            bounded_string = member.element == 'string' and member.string_bound is not None

            def element(item):
                if member.element == 'message':
                    return 'fcdr_deserialize(cdr, %s);' % item
                if bounded_string:
                    return '{ std::string s; cdr.deserialize(s); %s.assign(s); }' % item
                return 'cdr.deserialize(%s);' % item
            if member.container is None:
                lines.append('  ' + element(name))
            elif member.element == 'number' and member.container == 'bounded_sequence':
                lines.append('  cdr.deserialize(n); %s.resize_for_overwrite(n);' % name)
                lines.append('  cdr.deserializeArray(%s.data(), n);' % name)
            elif member.element == 'number':
                lines.append('  cdr.deserialize(%s);' % name)  # std::array, std::vector
            else:
                if member.container != 'array':
                    lines.append('  cdr.deserialize(n); %s.resize(n);' % name)
                lines.append('  for (auto& e : %s) %s' % (name, element('e')))
        return lines + ['}']

    def program(self, messages):
        types = _all_types(messages)
        lines = ['#include <%s>' % header for header in sorted({self.header(m) for m in types})]
        lines += [PROLOGUE]
        for message in types:
            name = self.cpp_name(message)
            lines += ['void fill(%s& m, unsigned seed);' % name,
                      'void fcdr_serialize(Cdr& cdr, const %s& m);' % name,
                      'void fcdr_deserialize(Cdr& cdr, %s& m);' % name]
        lines += [BENCH]
        for message in types:
            lines += self.fill(message) + self.serialize(message) + self.deserialize(message)
        lines += ['int main(int argc, char** argv) {',
                  '  double seconds = atof(argv[1]);',
                  '  int rounds = atoi(argv[2]);',
                  '  (void)argc;']
        for message in messages:
            lines.append('  bench<%s>("%s", seconds, rounds);'
                         % (self.cpp_name(message), message.full_name))
        return '\n'.join(lines + ['  return 0;', '}']) + '\n'


PROLOGUE = r'''
#include <fastcdr/Cdr.h>
#include <fastcdr/FastBuffer.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <algorithm>
#include <chrono>
#include <string>
#include <vector>

using eprosima::fastcdr::Cdr;
using eprosima::fastcdr::FastBuffer;

static std::string text(const char* format, unsigned index) {
  char buffer[64];
  snprintf(buffer, sizeof buffer, format, index);
  return buffer;
}

// Keeps the compiler from dropping work whose result nobody reads.
template <class T> static void escape(T* p) { asm volatile("" : : "g"(p) : "memory"); }

// ns per call of f: loops of about seconds each, the median of rounds.
template <class F> static double time_ns(F f, double seconds, int rounds) {
  typedef std::chrono::steady_clock clock;
  long iterations = 1;
  for (;;) {  // calibrate: at least 1/10 of the time
    auto start = clock::now();
    for (long i = 0; i < iterations; ++i) f();
    double took = std::chrono::duration<double>(clock::now() - start).count();
    if (took >= seconds / 10) {
      iterations = std::max(1L, static_cast<long>(iterations * seconds / took));
      break;
    }
    iterations *= 4;
  }
  std::vector<double> samples;
  for (int r = 0; r < rounds; ++r) {
    auto start = clock::now();
    for (long i = 0; i < iterations; ++i) f();
    samples.push_back(std::chrono::duration<double, std::nano>(clock::now() - start).count() /
                      iterations);
  }
  std::sort(samples.begin(), samples.end());
  return samples[samples.size() / 2];
}
'''

# After the declarations of fill and the Fast-CDR functions, which it calls.
BENCH = r'''
template <class T> static void bench(const char* name, double seconds, int rounds) {
  T message;
  fill(message, 1);
  uint32_t size = message.calcRawTotalSize();
  std::vector<char> ours(size + 64, 0), theirs(size + 64, 0);
  uint8_t* ours_bytes = reinterpret_cast<uint8_t*>(ours.data());

  // The bytes must be the same before anything is timed.
  message.copyToBuf(ours_bytes);
  uint32_t written = message.getTotalSize();
  FastBuffer out_buffer(theirs.data(), theirs.size());
  Cdr encoder(out_buffer, Cdr::LITTLE_ENDIANNESS, Cdr::DDS_CDR);
  fcdr_serialize(encoder, message);
  if (written != size || encoder.getSerializedDataLength() != size ||
      memcmp(ours.data(), theirs.data(), ours.size()) != 0) {
    fprintf(stderr, "%s: the encoders disagree (ours %u bytes, Fast-CDR %zu)\n", name, written,
            encoder.getSerializedDataLength());
    exit(1);
  }
  T decoded;
  FastBuffer in_buffer(theirs.data(), size);
  Cdr decoder(in_buffer, Cdr::LITTLE_ENDIANNESS, Cdr::DDS_CDR);
  fcdr_deserialize(decoder, decoded);
  std::vector<char> again(size + 64, 0);
  decoded.copyToBuf(reinterpret_cast<uint8_t*>(again.data()));
  if (!decoded.copyFromBuf(ours_bytes, size) || memcmp(again.data(), ours.data(), size) != 0) {
    fprintf(stderr, "%s: a decoder does not give back the message\n", name);
    exit(1);
  }

  double ours_encode = time_ns([&] { message.copyToBuf(ours_bytes); escape(ours_bytes); },
                               seconds, rounds);
  double fastcdr_encode = time_ns([&] {
    encoder.reset();
    fcdr_serialize(encoder, message);
    escape(theirs.data());
  }, seconds, rounds);
  bool ok = true;
  double ours_decode = time_ns([&] {
    ok &= decoded.copyFromBuf(ours_bytes, size);
    escape(&decoded);
  }, seconds, rounds);
  double fastcdr_decode = time_ns([&] {
    decoder.reset();
    fcdr_deserialize(decoder, decoded);
    escape(&decoded);
  }, seconds, rounds);
  if (!ok) {
    fprintf(stderr, "%s: copyFromBuf refused\n", name);
    exit(1);
  }
  printf("%s %u %.1f %.1f %.1f %.1f\n", name, size, ours_encode, fastcdr_encode, ours_decode,
         fastcdr_decode);
  fflush(stdout);
}
'''


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    parser.add_argument('--rounds', type=int, default=5)
    parser.add_argument('--seconds', type=float, default=0.2, help='per timed loop')
    parser.add_argument('--keep', help='write the export and the program here and keep them')
    args = parser.parse_args()
    if not os.path.isdir(os.path.join(TEST_PYTHON, 'rosbags')):
        print('%s: needs rosbags in %s: run scripts/setup.sh --tests' % (sys.argv[0], TEST_PYTHON),
              file=sys.stderr)
        return 2
    sys.path.insert(0, TEST_PYTHON)
    sys.path.insert(0, REPO)
    from rosbags.typesys import Stores, get_typestore
    from testing import ros2_messages
    from testing.ros_paths import prefix_arguments, ros2_prefixes

    with tempfile.TemporaryDirectory(prefix='codec_speed_') as scratch:
        work = args.keep or scratch
        os.makedirs(work, exist_ok=True)
        store = get_typestore(Stores.ROS2_HUMBLE)
        workspace = ros2_messages.write_packages(store, ROSBAGS_TYPES, os.path.join(work, 'ws'))
        include_ws, include_usr = os.path.join(work, 'ws_export'), os.path.join(work, 'usr_export')
        subprocess.run(GENMROS + ['mros2-export', '--workspace', workspace, '-o', include_ws]
                       + ['--type=%s' % name for name in ROSBAGS_TYPES],
                       check=True, stdout=subprocess.DEVNULL, env=ENVIRONMENT)
        subprocess.run(GENMROS + ['mros2-export', *prefix_arguments(ros2_prefixes()),
                                  '-o', include_usr]
                       + ['--type=%s' % name for name in PREFIX_TYPES],
                       check=True, stdout=subprocess.DEVNULL, env=ENVIRONMENT)
        messages = _models(workspace)
        source = os.path.join(work, 'codec_speed.cpp')
        with open(source, 'w') as stream:
            stream.write(Emitter().program(messages))
        program = os.path.join(work, 'codec_speed')
        subprocess.run(['g++', '-std=c++14', '-O2', '-I', include_ws, '-I', include_usr, source,
                        '-o', program, '-lfastcdr'], check=True)
        output = subprocess.run([program, str(args.seconds), str(args.rounds)], check=True,
                                capture_output=True, text=True).stdout

    print('\nEncode and decode, ns per message, median of %d loops of ~%.1f s; -O2, g++ on the '
          'host, Fast-CDR 1.0.26' % (args.rounds, args.seconds))
    print('| type | bytes | ours encode ns | Fast-CDR encode ns | Fast-CDR / ours '
          '| ours decode ns | Fast-CDR decode ns | Fast-CDR / ours |')
    print('|---|---:|---:|---:|---:|---:|---:|---:|')
    for line in output.splitlines():
        name, size, ours_encode, fastcdr_encode, ours_decode, fastcdr_decode = line.split()
        ours_encode, fastcdr_encode, ours_decode, fastcdr_decode = (
            float(v) for v in (ours_encode, fastcdr_encode, ours_decode, fastcdr_decode))
        print('| %s | %s | %s | %s | %.2fx | %s | %s | %.2fx |'
              % (name, size, _ns(ours_encode), _ns(fastcdr_encode), fastcdr_encode / ours_encode,
                 _ns(ours_decode), _ns(fastcdr_decode), fastcdr_decode / ours_decode))
    return 0


def _ns(value):
    return '%.0f' % value if value >= 100 else '%.1f' % value


if __name__ == '__main__':
    sys.exit(main())
