# SPDX-License-Identifier: BSD-3-Clause
"""colcon_mros.mros_v1.cpp: how the type model is spelled in C++ (called directly;
test_generation.py and the compile tests hold the headers themselves)."""

import os

import pytest

from colcon_mros.core.storage import storage_for
from colcon_mros.errors import GenmrosError
from colcon_mros.mros_v1.cpp import (SUPPORT_HEADERS, CppMessage, CppType, cpp_constant_literal,
                                     field_cpp_type)
from colcon_mros.mros_v1.names import RESERVED_NAMES
from colcon_mros.ros1.model import ModelBuilder
from colcon_mros.ros1.parse import SpecLoader
from support.checkout import REPO
from testing.ros_paths import ros1_package_dir

STD_MSGS = ros1_package_dir('std_msgs')


def _message(tmp_path, text, storage=None):
    directory = tmp_path / 'demo' / 'msg'
    directory.mkdir(parents=True)
    (directory / 'Sample.msg').write_text(text)
    search_path = {'demo': [str(directory)], 'std_msgs': [STD_MSGS]}
    loader = SpecLoader(search_path, RESERVED_NAMES)
    spec = loader.load_message_file(str(directory / 'Sample.msg'), 'demo')
    return ModelBuilder(loader, storage).message(spec.full_name), search_path


def test_fields_take_the_containers_of_their_bounds(tmp_path):
    text = 'string name\nstring[] tags\nint32[3] triple\nHeader header\nfloat64[] values\n'
    heap, search_path = _message(tmp_path, text)
    assert [field_cpp_type(f) for f in heap.fields] == [
        'std::string', 'std::vector<std::string>', 'mros::array<int32_t, 3>', 'std_msgs::Header',
        'std::vector<double>']
    options = tmp_path / 'bounds.options'
    options.write_text('* max_size:8 max_count:2\n')
    bounded, _ = _message(tmp_path / 'b', text,
                          storage_for('bounded', [str(options)], search_path))
    assert [field_cpp_type(f) for f in bounded.fields] == [
        'mros::bounded_string<8>', 'mros::bounded_vector<mros::bounded_string<8>, 2>',
        'mros::array<int32_t, 3>', 'std_msgs::Header', 'mros::bounded_vector<double, 2>']


def test_names_guards_and_escapes(tmp_path):
    message, _ = _message(tmp_path, 'int32 class\nint32 EOF=-1\nint32 Sample\n')
    view = CppMessage(message)
    assert (view.cpp_name, view.header, view.origin) == ('demo::Sample', 'demo/Sample.h',
                                                         'demo/msg/Sample.msg')
    assert view.header_guard == 'MROS_MSG_4_demo_Sample_H'
    assert [f.cpp_name for f in view.fields] == ['class_', 'Sample_']
    assert [(c.cpp_name, c.cpp_literal) for c in view.constants] == [('EOF_', '-1')]
    assert CppType('a_b/C').header_guard != CppType('a/b_C').header_guard


def test_members_that_meet_after_escaping_are_refused(tmp_path):
    message, _ = _message(tmp_path, 'int32 EOF\nint32 EOF_\n')
    with pytest.raises(GenmrosError) as error:
        CppMessage(message)
    assert str(error.value) == "%s:2: name 'EOF_' is already declared on line 1" % os.path.join(
        str(tmp_path), 'demo', 'msg', 'Sample.msg')


@pytest.mark.parametrize('ros_type, value, literal', [
    ('int64', -(1 << 63),
     '(-static_cast<int64_t>(static_cast<uint64_t>(0x7fffffffu) << 32 | 0xffffffffu) - 1)'),
    ('uint64', (1 << 64) - 1, '(static_cast<uint64_t>(0xffffffffu) << 32 | 0xffffffffu)'),
    ('int32', -(1 << 31), '(-2147483647 - 1)'),
    ('uint8', 255, '255u'),
    ('bool', True, '1'),
    ('float32', 0.1, '0.1f'),
    ('float32', 1e-50, '0.0f'),
    ('float32', 1e-40, '9.99994610111476e-41f'),
    ('float64', 1e-400, '0.0'),
    ('float64', float('-inf'), '-std::numeric_limits<double>::infinity()'),
    ('string', 'a "b" ??=', '"a \\"b\\" ?\\?="'),
])
def test_constant_literals(ros_type, value, literal):
    assert cpp_constant_literal(ros_type, value) == literal


def test_catkins_cmake_installs_the_support_headers_by_their_names():
    # genmros-extras.cmake takes the names from genmros-names.cmake, without
    # asking genmros (no process per package).
    with open(os.path.join(REPO, 'share', 'genmros', 'cmake', 'genmros-extras.cmake')) as stream:
        assert 'list(TRANSFORM GENMROS_SUPPORT_HEADERS PREPEND' in stream.read()
    with open(os.path.join(REPO, 'cmake', 'genmros-names.cmake')) as stream:
        assert 'set(GENMROS_SUPPORT_HEADERS "%s")' % ';'.join(SUPPORT_HEADERS) in stream.read()
