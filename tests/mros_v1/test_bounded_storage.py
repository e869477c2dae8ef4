# SPDX-License-Identifier: BSD-3-Clause
"""Bounded storage: strings and arrays inside the message, no heap,
exact maximum sizes, and bounds that are never exceeded silently."""

import os
import shutil
import subprocess

import pytest

from support.checkout import TEST_WS, run_genmros
from support.compile_checks import (LANGUAGE_MODES, STRICT_FLAGS, TARGET_PARAMS, TARGETS,
                                    every_header_translation_unit)
from testing.ros_paths import prefix_arguments, ros1_prefixes

DEBIAN_SET = ['sensor_msgs/Image', 'sensor_msgs/PointCloud2', 'sensor_msgs/JointState',
              'nav_msgs/Odometry', 'visualization_msgs/MarkerArray', 'std_msgs/Header',
              'std_msgs/Float64MultiArray']
NO_HEAP = ['-Wl,--wrap=%s' % symbol for symbol in
           ('malloc', 'calloc', 'realloc', '_malloc_r', '_calloc_r', '_realloc_r', '_Znwj',
            '_Znaj')]


def _options(path, text):
    path.write_text(text)
    return str(path)


@pytest.fixture(scope='module')
def bounded_exports(tmp_path_factory):
    """Bounded exports of test_ws and of the Debian set: {name: include root}."""
    root = tmp_path_factory.mktemp('bounded')
    options = _options(root / 'firmware.options', '* max_size:24 max_count:6\n')
    exports = {'test_ws': str(root / 'test_ws'), 'debian': str(root / 'debian')}
    run_genmros('mros-v1-export', '--workspace', TEST_WS, '-o', exports['test_ws'],
                *prefix_arguments(ros1_prefixes()),
                '--storage', 'bounded', '--options', options)
    arguments = ['mros-v1-export', '-o', exports['debian'],
                 *prefix_arguments(ros1_prefixes()), '--storage', 'bounded',
                 '--options', options]
    for name in DEBIAN_SET:
        arguments += ['--type', name]
    run_genmros(*arguments)
    return exports


@pytest.fixture(scope='module')
def bounded_sources(bounded_exports, tmp_path_factory):
    directory = tmp_path_factory.mktemp('bounded_sources')
    sources = {}
    for name, root in bounded_exports.items():
        sources[name] = str(directory / ('%s.cpp' % name))
        assert every_header_translation_unit(root, sources[name]) >= 7
    return sources


@pytest.mark.parametrize('target', TARGET_PARAMS)
@pytest.mark.parametrize('mode', LANGUAGE_MODES)
def test_bounded_headers_compile_without_warnings(bounded_exports, bounded_sources, target, mode):
    for name, source in bounded_sources.items():
        command = TARGETS[target] + ['-std=' + mode] + STRICT_FLAGS + [
            '-fsyntax-only', '-I', bounded_exports[name], source]
        result = subprocess.run(command, capture_output=True, text=True)
        assert result.returncode == 0, result.stderr[-4000:]
        assert 'warning:' not in result.stderr, result.stderr[-4000:]


@pytest.mark.slow  # arm-none-eabi-g++
@pytest.mark.parametrize('storage, links', [('bounded', True), ('heap', False)])
def test_bounded_firmware_links_without_an_allocator(bounded_exports, bounded_sources,
                                                     test_ws_export, tmp_path, storage, links):
    # The whole interface of every type, linked for a Cortex-M4 where malloc
    # and operator new are undefined (--wrap without a __wrap_ definition).
    # Heap storage must fail there, or the check would prove nothing.
    include = bounded_exports['test_ws'] if storage == 'bounded' else test_ws_export
    source = bounded_sources['test_ws'] if storage == 'bounded' else str(tmp_path / 'heap.cpp')
    if storage == 'heap':
        every_header_translation_unit(include, source)
    main = tmp_path / 'main.cpp'
    main.write_text('#include "%s"\nstatic uint8_t buffer[4096];\n'
                    'int main() { return exerciseAll(buffer, sizeof buffer); }\n' % source)
    command = TARGETS['cortex-m4'] + [
        '-std=gnu++98', '-Os', '-fno-exceptions', '-fno-rtti', '-ffunction-sections',
        '-fdata-sections', '-I', include, str(main), '-o', str(tmp_path / 'firmware.elf'),
        '--specs=nosys.specs', '-Wl,--gc-sections'] + NO_HEAP
    result = subprocess.run(command, capture_output=True, text=True)
    if links:
        assert result.returncode == 0, result.stderr[-4000:]
    else:
        assert result.returncode != 0 and "undefined reference to `__wrap__Znwj'" in result.stderr


BEHAVIOUR = r'''
#include <stdio.h>
#include <string.h>
// The firmware's hook: count what went over a bound, and keep the last.
static int overflows = 0;
static unsigned long last_capacity = 0, last_requested = 0;
#define MROS_BOUNDED_OVERFLOW(capacity, requested) \
  (++overflows, last_capacity = (capacity), last_requested = (requested))
#include <mros_test/PersonalData.h>
#include <mros_test_base/Labeled.h>

// Wire images written by hand, independent of the headers under test.
static uint32_t put32(uint8_t* out, uint32_t value) {
  for (int i = 0; i < 4; ++i) out[i] = static_cast<uint8_t>(value >> (8 * i));
  return 4;
}
static uint32_t putText(uint8_t* out, const char* text, uint32_t size) {
  put32(out, size);
  memcpy(out + 4, text, size);
  return 4 + size;
}
static uint32_t person(uint8_t* out, uint32_t first_size, uint32_t last_size) {
  static const char letters[] = "abcdefghijklmnopqrstuvwxyzabcdefghijklmnopqrstuvwxyz";
  uint32_t size = putText(out, letters, first_size);
  size += putText(out + size, letters, last_size);
  out[size++] = 83;  // age 83
  out[size++] = 0;
  return size + put32(out + size, 100000);
}

int main() {
  uint8_t wire[256];
  mros_test::PersonalData message;
  // Exactly at the bounds: read back whole.
  uint32_t size = person(wire, 32, 16);
  const int32_t consumed = message.deserialize(wire, size);
  printf("at bounds: %d of %u, %s %u\n", consumed, size, message.first_name.c_str(),
         static_cast<unsigned>(message.last_name.size()));
  // The largest image is the one the type announces.
  printf("max: %u %d\n", message.serializedLength(), static_cast<int>(mros_test::PersonalData::MROS_MAX_SERIALIZED_SIZE));
  // One byte over a bound: refused, never cut short.
  size = person(wire, 33, 16);
  printf("first_name over: %d\n", message.deserialize(wire, size));
  size = person(wire, 32, 17);
  printf("last_name over: %d\n", message.deserialize(wire, size));
  printf("hook after a peer's data over a bound: %d\n", overflows);
  // assign() beyond the bound is refused, keeps the value and says so.
  mros_test::PersonalData local;
  local.first_name = "Phil";
  const bool taken = local.first_name.assign("0123456789012345678901234567890123");
  printf("assign over: %d %s, hook %d (%lu of %lu)\n", taken, local.first_name.c_str(),
         overflows, last_requested, last_capacity);
  // = and the implicit constructor keep the first N bytes, and call the hook too.
  local.first_name = "0123456789012345678901234567890123";
  printf("= over: %s, hook %d\n", local.first_name.c_str(), overflows);
  mros::bounded_string<4> word = "abcdefg";
  printf("constructed over: %s, hook %d\n", word.c_str(), overflows);
  // A count over max_count is refused.
  mros_test_base::Labeled labeled;
  uint32_t labeled_size = putText(wire, "tag", 3);
  labeled_size += 16;  // ColorRGBA: four float32
  memset(wire + 7, 0, 16);
  const uint32_t weights_at = labeled_size;
  labeled_size += put32(wire + labeled_size, 4);
  memset(wire + labeled_size, 0, 4 * 8);
  labeled_size += 4 * 8;
  printf("weights at bound: %d of %u\n", labeled.deserialize(wire, labeled_size), labeled_size);
  put32(wire + weights_at, 5);
  memset(wire + labeled_size, 0, 8);
  printf("weights over: %d\n", labeled.deserialize(wire, labeled_size + 8));
  // push_back beyond max_count is refused; pop_back on empty changes nothing.
  labeled.weights.clear();
  int pushed = 0, popped = 0;
  for (int i = 0; i < 5; ++i) pushed += labeled.weights.push_back(i);
  printf("pushed %d of 5, hook %d\n", pushed, overflows);
  for (int i = 0; i < 5; ++i) popped += labeled.weights.pop_back();
  printf("popped %d of 5, size %u\n", popped, static_cast<unsigned>(labeled.weights.size()));
  return 0;
}
'''  # noqa: E501


def test_bounds_are_exact_and_never_exceeded(tmp_path):
    options = _options(tmp_path / 'bounds.options',
                       'mros_test/PersonalData.first_name max_size:32\n'
                       '* max_size:16 max_count:4\n')
    include = str(tmp_path / 'include')
    run_genmros('mros-v1-export', '--workspace', TEST_WS, '--type', 'mros_test/PersonalData',
                '--type', 'mros_test_base/Labeled', '-o', include,
                *prefix_arguments(ros1_prefixes()), '--storage', 'bounded', '--options', options)
    source = tmp_path / 'behaviour.cpp'
    source.write_text(BEHAVIOUR)
    program = str(tmp_path / 'behaviour')
    subprocess.run(['g++', '-std=gnu++98', '-fsanitize=address,undefined',
                    '-fno-sanitize-recover=all']
                   + STRICT_FLAGS + ['-I', include, str(source), '-o', program], check=True)
    output = subprocess.run([program], capture_output=True, text=True, check=True).stdout
    assert output.splitlines() == [
        'at bounds: 62 of 62, abcdefghijklmnopqrstuvwxyzabcdef 16',
        'max: 62 62',  # 4 + 32 + 4 + 16 + 2 + 4
        'first_name over: -1',
        'last_name over: -1',
        "hook after a peer's data over a bound: 0",
        'assign over: 0 Phil, hook 1 (34 of 32)',
        '= over: 01234567890123456789012345678901, hook 2',
        'constructed over: abcd, hook 3',
        'weights at bound: 59 of 59',
        'weights over: -1',
        'pushed 4 of 5, hook 4',
        'popped 4 of 5, size 0',
    ]
    with open(os.path.join(include, 'msg_max_size.h')) as stream:
        max_size = stream.read()
    # Labeled: 4 + 16 (label) + 16 (ColorRGBA) + 4 + 4 * 8 (weights) = 72
    assert '//   mros_test/PersonalData: at most 62 bytes\n' in max_size
    assert '//   mros_test_base/Labeled: at most 72 bytes\n' in max_size
    assert '#define PUB_MSG_MAX_SIZE 72\n' in max_size


def test_heap_storage_says_which_types_have_no_maximum_and_why(tmp_path):
    run_genmros('mros-v1-export', '--workspace', TEST_WS, '--type', 'mros_test/NestedTypes',
                '--type', 'mros_test_base/Vector3i', '-o', str(tmp_path),
                *prefix_arguments(ros1_prefixes()))
    with open(str(tmp_path / 'msg_max_size.h')) as stream:
        text = stream.read()
    assert ('//   mros_test/NestedTypes: no maximum, header.frame_id (string) has no bound; '
            'counted as 1024 bytes\n') in text
    assert '//   mros_test_base/Vector3i: exactly 12 bytes\n' in text
    assert '#define PUB_MSG_MAX_SIZE 1024\n' in text


def test_package_options_apply_to_bounded_exports_only(tmp_path):
    workspace = tmp_path / 'ws' / 'src'
    shutil.copytree(os.path.join(TEST_WS, 'src', 'mros_test_base'),
                    str(workspace / 'mros_test_base'))
    _options(workspace / 'mros_test_base' / 'msg' / 'genmros.options',
             'Labeled.label max_size:8\nLabeled.weights max_count:3\n')
    firmware = _options(tmp_path / 'firmware.options', '* max_size:40 max_count:9\n')
    run_genmros('mros-v1-export', '--workspace', str(tmp_path / 'ws'), '-o',
                str(tmp_path / 'heap'), *prefix_arguments(ros1_prefixes()))
    run_genmros('mros-v1-export', '--workspace', str(tmp_path / 'ws'),
                '-o', str(tmp_path / 'bounded'),
                *prefix_arguments(ros1_prefixes()), '--storage', 'bounded', '--options', firmware)
    heap = (tmp_path / 'heap' / 'mros_test_base' / 'Labeled.h').read_text()
    bounded = (tmp_path / 'bounded' / 'mros_test_base' / 'Labeled.h').read_text()
    assert 'std::string label;' in heap and 'std::vector<double> weights;' in heap
    assert 'mros::bounded_string<8> label;' in bounded
    assert 'mros::bounded_vector<double, 3> weights;' in bounded


@pytest.mark.parametrize('text, line, problem', [
    ('mros_test/PersonalData.first_name max_size:0\n', 1,
     'max_size must be a positive integer, not \'0\''),
    ('\n# comment\nmros_test/PersonalData.first_name max_size:-3\n', 3,
     "max_size must be a positive integer, not '-3'"),
    ('mros_test/PersonalData.first_name max_size:ten\n',
     1, "max_size must be a positive integer, not 'ten'"),
    ('mros_test/PersonalData.first_name max_length:10\n', 1,
     "unknown option 'max_length:10' (expected max_size:N or max_count:N)"),
    ('mros_test/PersonalData.first_name\n', 1, "'mros_test/PersonalData.first_name' sets no bound "
                                               '(expected max_size:N or max_count:N)'),
    ('PersonalData.first_name max_size:3\n', 1, "'PersonalData.first_name' names no field "
                                                "(expected package/Type.field or '*')"),
    ('mros_test/Nobody.first_name max_size:3\n', 1, "unknown type 'mros_test/Nobody'"),
    ('mros_test/PersonalData.middle_name max_size:3\n', 1,
     "type 'mros_test/PersonalData' has no field 'middle_name'"),
    ('mros_test/PersonalData.age max_size:3\n', 1,
     "max_size bounds strings; 'mros_test/PersonalData.age' is uint16"),
    ('mros_test/ArrayTypes.fixed_bytes max_count:3\n', 1,
     "max_count bounds variable arrays; 'mros_test/ArrayTypes.fixed_bytes' is uint8[4]"),
    ('mros_test/PersonalData.first_name max_count:3\n', 1,
     "max_count bounds variable arrays; 'mros_test/PersonalData.first_name' is string"),
])
def test_bad_options_are_refused_with_their_line(tmp_path, text, line, problem):
    options = _options(tmp_path / 'bad.options', text)
    output = tmp_path / 'include'
    result = run_genmros('mros-v1-export', '--workspace', TEST_WS,
                         '--type', 'mros_test/PersonalData', '-o', str(output),
                         *prefix_arguments(ros1_prefixes()),
                         '--storage', 'bounded', '--options', options, check=False)
    assert result.returncode == 1
    assert result.stderr.splitlines() == ['genmros: error: %s:%d: %s' % (options, line, problem)]
    assert not output.exists()


def test_a_field_without_a_bound_is_refused_at_its_definition(tmp_path):
    options = _options(tmp_path / 'partial.options',
                       'mros_test/PersonalData.first_name max_size:8\n')
    output = tmp_path / 'include'
    result = run_genmros('mros-v1-export', '--workspace', TEST_WS,
                         '--type', 'mros_test/PersonalData', '-o', str(output),
                         *prefix_arguments(ros1_prefixes()),
                         '--storage', 'bounded', '--options', options, check=False)
    definition = os.path.join(TEST_WS, 'src', 'mros_test', 'msg', 'PersonalData.msg')
    assert result.returncode == 1
    assert result.stderr.splitlines() == [
        "genmros: error: %s:3: field 'last_name' (string) has no max_size for bounded storage "
        "(add 'mros_test/PersonalData.last_name max_size:N' to an options file)" % definition]
    assert not output.exists()
