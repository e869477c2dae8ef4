# SPDX-License-Identifier: BSD-3-Clause
"""What genmros writes: which files, for which types, and what they do when compiled."""

import filecmp
import glob
import os
import shutil
import subprocess

import pytest

from colcon_mros.mros_v1.cpp import SUPPORT_HEADER, SUPPORT_HEADERS, SUPPORT_VERSION_HEADER
from support.checkout import REPO, TEST_WS, run_genmros
from testing.ros_paths import prefix_arguments, ros1_package_dir, ros1_prefixes

FIXTURES = os.path.join(REPO, 'tests', 'fixtures')
STRICT = ['g++', '-std=c++11', '-Wall', '-Wextra', '-Werror', '-pedantic']


def _tree(root):
    return sorted(os.path.relpath(p, root)
                  for p in glob.glob(os.path.join(root, '**', '*.h'), recursive=True))


def _build_and_run(tmp_path, include_dirs, source_text, extra_sources=()):
    source = tmp_path / 'main.cpp'
    source.write_text(source_text)
    program = str(tmp_path / 'main')
    command = (STRICT + ['-o', program, str(source)] + list(extra_sources)
               + ['-I' + d for d in include_dirs])
    compiled = subprocess.run(command, capture_output=True, text=True)
    assert compiled.returncode == 0, compiled.stderr[-4000:]
    return subprocess.run([program], capture_output=True, text=True, check=True).stdout


AGGREGATES = ['message_class_specialization.h', 'message_headers.h', 'msg_max_size.h',
              'mros_v1_delivery.h', 'mros_v1_fit_check.h']


def test_export_of_one_type_brings_its_whole_closure(tmp_path):
    run_genmros('mros-v1-export', '--type', 'geometry_msgs/PoseStamped', '-o', str(tmp_path),
                *prefix_arguments(ros1_prefixes()))
    assert _tree(str(tmp_path)) == sorted(AGGREGATES + [
        'geometry_msgs/Point.h', 'geometry_msgs/Pose.h', 'geometry_msgs/PoseStamped.h',
        'geometry_msgs/Quaternion.h', 'std_msgs/Header.h'] + list(SUPPORT_HEADERS))


def test_export_of_a_workspace_covers_every_type_and_dependency(test_ws_export):
    expected = {'mros_test_base/Vector3i.h', 'mros_test_base/Labeled.h', 'std_msgs/ColorRGBA.h',
                'std_msgs/Header.h', 'geometry_msgs/Twist.h', 'geometry_msgs/Vector3.h',
                'geometry_msgs/Point.h', 'mros_test/LookupPerson.h',
                'mros_test/LookupPersonRequest.h', 'mros_test/LookupPersonResponse.h'}
    expected.update('mros_test/%s.h' % os.path.basename(p)[:-4]
                    for p in glob.glob(os.path.join(TEST_WS, 'src', 'mros_test', 'msg', '*.msg')))
    assert expected <= set(_tree(test_ws_export))
    assert 'std_msgs/String.h' not in _tree(test_ws_export)


def test_generator_mode_writes_what_export_writes(test_ws_export, tmp_path):
    flags = ['-I', 'std_msgs:' + ros1_package_dir('std_msgs'),
             '-I', 'geometry_msgs:' + ros1_package_dir('geometry_msgs')]
    for package in ('mros_test_base', 'mros_test'):
        flags += ['-I', '%s:%s' % (package, os.path.join(TEST_WS, 'src', package, 'msg'))]
    definitions = sorted(glob.glob(os.path.join(TEST_WS, 'src', '*', 'msg', '*.msg')) +
                         glob.glob(os.path.join(TEST_WS, 'src', '*', 'srv', '*.srv')))
    for path in definitions:
        package = path.split(os.sep)[-3]
        run_genmros('generate', path, '-p', package, '-o', str(tmp_path / package), *flags)
    generated = _tree(str(tmp_path))
    assert 'mros_test/LookupPersonRequest.h' in generated and set(
        SUPPORT_HEADERS) <= set(generated)
    for relative in generated:
        assert filecmp.cmp(str(tmp_path / relative),
                           os.path.join(test_ws_export, relative), shallow=False), relative


def test_a_header_refuses_a_support_header_of_another_genmros(test_ws_export, tmp_path):
    include = str(tmp_path / 'include')
    shutil.copytree(test_ws_export, include)
    support = os.path.join(include, SUPPORT_VERSION_HEADER)
    with open(support) as stream:
        text = stream.read()
    version = run_genmros('--version').stdout.split()[1]
    major, minor, patch = (int(part) for part in version.split('.'))
    defined = '#define MROS_MESSAGE_SUPPORT_VERSION %d\n' % (major * 10000 + minor * 100 + patch)
    assert defined in text
    source = tmp_path / 'use.cpp'
    source.write_text('#include <mros_test/PersonalData.h>\nint main() { return 0; }\n')
    command = ['g++', '-std=gnu++98', '-fsyntax-only', '-I', include, str(source)]
    assert subprocess.run(command, capture_output=True, text=True).returncode == 0
    with open(support, 'w') as stream:
        stream.write(text.replace(defined, '#define MROS_MESSAGE_SUPPORT_VERSION 99999\n'))
    result = subprocess.run(command, capture_output=True, text=True)
    assert result.returncode != 0
    assert ('error: #error "the %s found first is not the one genmros %s wrote with this header'
            % (SUPPORT_HEADER, version)) in result.stderr


COMMENTED_MSG = r"""# What the type is for,
# before a blank line.

# above a
int32 a  # after a
# not a's: a blank line follows

string S=value # part of the value
# ends in a backslash \
int32 b
# a trigraph in C++98: ??/
int32 c
"""


def test_the_msg_comments_become_the_type_and_members_comments(tmp_path):
    package = tmp_path / 'ws' / 'src' / 'commented'
    (package / 'msg').mkdir(parents=True)
    (package / 'package.xml').write_text(
        '<package format="2"><name>commented</name><version>1.0.0</version><description>c'
        '</description><maintainer email="dev@example.com">d</maintainer><license>BSD'
        '</license></package>\n')
    (package / 'msg' / 'Commented.msg').write_text(COMMENTED_MSG)
    include = str(tmp_path / 'include')
    run_genmros('mros-v1-export', '--workspace', str(tmp_path / 'ws'), '-o', include,
                *prefix_arguments(ros1_prefixes()))
    with open(os.path.join(include, 'commented', 'Commented.h')) as stream:
        header = stream.read()
    assert ('  // above a\n  // after a\n  int32_t a;  // int32 a\n'
            '  // ends in a backslash\n  int32_t b;  // int32 b\n'
            '  // a trigraph in C++98: ? ?/\n  int32_t c;  // int32 c\n') in header
    assert ('// What the type is for,\n// before a blank line.\n'
            'struct Commented : mros::Message<Commented>') in header
    assert "// not a's" not in header
    assert '"value # part of the value"' in header
    # Under strict C++98 (trigraphs on) b and c are still members.
    source = tmp_path / 'use.cpp'
    source.write_text('#include <commented/Commented.h>\n'
                      'int main() { commented::Commented m; m.b = 1; m.c = 2; return m.a; }\n')
    compiled = subprocess.run(['g++', '-std=c++98', '-Wall', '-Wextra', '-Werror', '-pedantic',
                               '-fsyntax-only', '-I', include, str(source)],
                              capture_output=True, text=True)
    assert compiled.returncode == 0, compiled.stderr[-3000:]


def test_type_ids_depend_on_the_type_name_only(tmp_path):
    run_genmros('mros-v1-export', '--type', 'std_msgs/Header', '-o', str(tmp_path / 'a'),
                *prefix_arguments(ros1_prefixes()))
    run_genmros('mros-v1-export', '--package', 'sensor_msgs', '--type', 'std_msgs/Header',
                '-o', str(tmp_path / 'b'), *prefix_arguments(ros1_prefixes()))
    assert filecmp.cmp(str(tmp_path / 'a' / 'std_msgs' / 'Header.h'),
                       str(tmp_path / 'b' / 'std_msgs' / 'Header.h'), shallow=False)


def test_fields_named_like_cpp_keywords_compile_and_round_trip(tmp_path):
    workspace = tmp_path / 'ws' / 'src'
    shutil.copytree(os.path.join(FIXTURES, 'keyword_msgs'), str(workspace / 'keyword_msgs'))
    include = str(tmp_path / 'include')
    run_genmros('mros-v1-export', '--workspace', str(tmp_path / 'ws'), '-o', include,
                *prefix_arguments(ros1_prefixes()))
    output = _build_and_run(tmp_path, [include], r'''
#include <cstdio>
#include <keyword_msgs/Keywords.h>
int main() {
  keyword_msgs::Keywords sent;
  sent.class_ = -7;
  sent.new_ = "fresh";
  sent.delete_.assign(3, 0.5);
  sent.operator_[1] = 1;
  sent.namespace_ = 200;
  sent.NULL_ = -1;
  sent.serialize_ = 65535;
  sent.dataSize_ = "size";
  uint8_t buffer[256];
  const int32_t size = sent.serialize(buffer, sizeof buffer);
  keyword_msgs::Keywords received;
  const int32_t consumed = received.deserialize(buffer, static_cast<uint32_t>(size));
  std::printf("%d %d %d %s %zu %d %u %lld %u %s %d %s\n", size, consumed, received.class_, received.new_.c_str(),
              received.delete_.size(), received.operator_[1], received.namespace_,
              static_cast<long long>(received.NULL_), received.serialize_, received.dataSize_.c_str(),
              keyword_msgs::Keywords::register_, keyword_msgs::Keywords::typename_);
  return 0;
}
''')  # noqa: E501
    # 4 + (4+5) + (4+3*8) + 2 + 1 + 8 + 2 + (4+4) = 62 bytes
    assert output.split() == ['62', '62', '-7', 'fresh', '3', '1',
                              '200', '-1', '65535', 'size', '1', 'text']


def test_constants_hold_the_values_written_in_the_msg_file(test_ws_export, tmp_path):
    output = _build_and_run(tmp_path, [test_ws_export], r'''
#include <cinttypes>
#include <cstdio>
#include <mros_test/Constants.h>
typedef mros_test::Constants C;
int main() {
  std::printf("%d %d %d %d %u %d %u\n", C::FLAG_ON, C::FLAG_OFF, C::I8_MIN, C::I8_MAX, C::U8_MAX, C::BYTE_MIN,
              C::CHAR_TOP);
  std::printf("%d %u %" PRId32 " %" PRId32 " %" PRIu32 "\n", C::I16_MIN, C::U16_MAX, C::I32_MIN, C::I32_MAX,
              C::U32_MAX);
  std::printf("%" PRId64 " %" PRId64 " %" PRIu64 "\n", C::I64_MIN, C::I64_MAX, C::U64_MAX);
  std::printf("%.9g %.17g %g\n", C::F32_PI, C::F64_SMALL, C::F64_NEG);
  std::printf("[%s] [%s]\n", C::GREETING, C::EMPTY);
  const int32_t& bound = C::I32_MAX;  // odr-use: needs the out-of-class definition
  return bound == 2147483647 ? 0 : 1;
}
''')  # noqa: E501
    assert output.split('\n')[:5] == [
        '1 0 -128 127 255 -128 255',
        '-32768 65535 -2147483648 2147483647 4294967295',
        '-9223372036854775808 9223372036854775807 18446744073709551615',
        '3.14159274 1e-300 -2.5',
        '[Hello, "mROS" \\ # not a comment ??=] []',
    ]


def test_variable_size_budget_sizes_the_publish_buffer(tmp_path):
    run_genmros('mros-v1-export', '--workspace', TEST_WS, '--type', 'mros_test/PersonalData',
                '--type', 'mros_test_base/Vector3i', '-o', str(tmp_path),
                *prefix_arguments(ros1_prefixes()),
                '--variable-size-budget', '96')
    with open(str(tmp_path / 'msg_max_size.h')) as stream:
        assert '#define PUB_MSG_MAX_SIZE 96' in stream.read()


def test_template_directory_override(tmp_path):
    templates = str(tmp_path / 'templates')
    shutil.copytree(os.path.join(REPO, 'colcon_mros', 'mros_v1', 'templates'), templates)
    with open(os.path.join(templates, 'msg.h.em'), 'a') as stream:
        stream.write('// custom template\n')
    output = str(tmp_path / 'include' / 'mros_test')
    run_genmros('generate', os.path.join(TEST_WS, 'src', 'mros_test', 'msg', 'PersonalData.msg'),
                '-p', 'mros_test', '-o', output, '-e', templates)
    with open(os.path.join(output, 'PersonalData.h')) as stream:
        assert stream.read().endswith('// custom template\n')


@pytest.mark.parametrize('arguments, expected', [
    (['--help'], ['genmros mros-v1-export', 'genmros mros2-export']),
    (['generate', '--help'], ['genmros generate [-h]', '-p PACKAGE', '-o DIR']),
    (['mros-v1-export', '--help'],
     ['--workspace WS', '--package PKG', '--type PKG/TYPE', '--variable-size-budget']),
])
def test_help_describes_both_modes(arguments, expected):
    result = run_genmros(*arguments)
    for text in expected:
        assert text in result.stdout


def test_generator_mode_fills_an_export_dir_with_the_whole_closure(test_ws_export, tmp_path):
    flags = ['-I', 'std_msgs:' + ros1_package_dir('std_msgs'),
             '-I', 'geometry_msgs:' + ros1_package_dir('geometry_msgs')]
    for package in ('mros_test_base', 'mros_test'):
        flags += ['-I', '%s:%s' % (package, os.path.join(TEST_WS, 'src', package, 'msg'))]
    export_dir = tmp_path / 'export'
    run_genmros('generate', os.path.join(TEST_WS, 'src', 'mros_test', 'srv', 'LookupPerson.srv'),
                '-p', 'mros_test', '-o', str(tmp_path / 'devel' / 'mros_test'),
                '--export-dir', str(export_dir), *flags)
    assert _tree(str(export_dir / 'include')) == sorted([
        'geometry_msgs/Point.h', 'mros_test/LookupPerson.h', 'mros_test/LookupPersonRequest.h',
        'mros_test/LookupPersonResponse.h', 'mros_test/PersonalData.h'] + list(SUPPORT_HEADERS))
    for relative in _tree(str(export_dir / 'include')):
        assert filecmp.cmp(str(export_dir / 'include' / relative),
                           os.path.join(test_ws_export, relative), shallow=False), relative
    definitions = sorted(os.path.relpath(os.path.join(d, n), str(export_dir / 'share'))
                         for d, _, names in os.walk(str(export_dir / 'share')) for n in names)
    assert definitions == ['geometry_msgs/msg/Point.msg', 'geometry_msgs/package.xml',
                           'mros_test/msg/PersonalData.msg', 'mros_test/package.xml',
                           'mros_test/srv/LookupPerson.srv']
    assert filecmp.cmp(str(export_dir / 'share' / 'geometry_msgs' / 'msg' / 'Point.msg'),
                       os.path.join(ros1_package_dir('geometry_msgs'), 'Point.msg'), shallow=False)


def test_catkin_devel_space_underlays_are_found(tmp_path):
    # A devel space keeps no package.xml or .msg files, only catkin's pointer
    # to the sources (genmsg's pkg-msg-paths.cmake.develspace.in).
    devel = tmp_path / 'devel'
    cmake_dir = devel / 'share' / 'mros_test_base' / 'cmake'
    cmake_dir.mkdir(parents=True)
    (cmake_dir / 'mros_test_base-msg-paths.cmake').write_text(
        '# generated from genmsg/cmake/pkg-msg-paths.cmake.develspace.in\n\n'
        'set(mros_test_base_MSG_INCLUDE_DIRS "%s")\n'
        'set(mros_test_base_MSG_DEPENDENCIES std_msgs)\n'
        % os.path.join(TEST_WS, 'src', 'mros_test_base', 'msg'))
    run_genmros('mros-v1-export', '--type', 'mros_test_base/Labeled',
                '-o', str(tmp_path / 'include'),
                '--prefix', str(devel), *prefix_arguments(ros1_prefixes()))
    assert _tree(str(tmp_path / 'include')) == sorted(AGGREGATES + [
        'mros_test_base/Labeled.h', 'std_msgs/ColorRGBA.h'] + list(SUPPORT_HEADERS))
