# SPDX-License-Identifier: BSD-3-Clause
"""Bounded storage (genmros mros2-export --storage bounded) holds every
string and sequence inside the message: the headers need no heap, write
what Fast-CDR writes, and refuse a sample that breaks a bound."""

import random
import subprocess

import pytest

from support.checkout import run_genmros
from testing import fastcdr, mros2_harness, ros2_messages

from colcon_mros.core.storage import BoundedStorage
from colcon_mros.mros2.cpp import CppMessageName
from colcon_mros.ros2.interfaces import all_packages
from colcon_mros.ros2.model import ModelBuilder

TYPES = ['sensor_msgs/msg/JointState', 'std_msgs/msg/String', 'sensor_msgs/msg/Imu',
         'geometry_msgs/msg/PolygonStamped']
BOUNDS = '* max_size:16 max_count:4\nsensor_msgs/JointState.name max_count:3\n'


@pytest.fixture(scope='module')
def bounded(rosbags_corpus, tmp_path_factory):
    """(include dir, models) of TYPES in bounded storage."""
    root = tmp_path_factory.mktemp('bounded')
    options = root / 'firmware.options'
    options.write_text(BOUNDS)
    workspace = rosbags_corpus.workspace
    include_dir = str(root / 'include')
    run_genmros('mros2-export', '--workspace', workspace, '--prefix', workspace,
                '--storage', 'bounded', '--options', str(options), '-o', include_dir,
                *['--type=%s' % name for name in TYPES])
    builder = ModelBuilder(all_packages([workspace], []), BoundedStorage([str(options)]))
    return include_dir, [builder.message(name) for name in TYPES]


def test_bounded_headers_hold_their_bounds(bounded):
    include_dir, _ = bounded
    with open('%s/sensor_msgs/msg/joint_state.hpp' % include_dir) as stream:
        header = stream.read()
    assert 'mros::bounded_vector<mros::bounded_string<16>, 3> name;' in header
    assert 'mros::bounded_vector<double, 4> position;' in header


def test_bounded_headers_write_what_fastcdr_writes_and_refuse_what_breaks_a_bound(
        bounded, fastcdr_program, tmp_path):
    include_dir, messages = bounded
    names = [CppMessageName(m) for m in messages]
    echo = mros2_harness.Echo(mros2_harness.build_echo(
        include_dir, [n.header for n in names], [n.cpp_name for n in names], str(tmp_path)))
    rng = random.Random(50)
    instances = [(i, ros2_messages.random_value(m, rng)) for i, m in enumerate(messages)
                 for _ in range(10)]
    references = fastcdr.encode_many(fastcdr_program, [
        ros2_messages.fastcdr_ops(messages[i], value) for i, value in instances])
    echoed = echo.run([(i, 16, r) for (i, _), r in zip(instances, references)])
    assert [e.raw for e in echoed] == references
    assert all(e.fragmented == e.whole for e in echoed)

    joint_state = messages[0]
    value = ros2_messages.random_value(joint_state, rng)
    over = []
    for name, item in (('name', ['a', 'b', 'c', 'd']), ('name', ['x' * 17]),
                       ('position', [1.0] * 5)):
        broken = dict(value, **{name: item})
        over.append(fastcdr.encode(fastcdr_program,
                                   ros2_messages.fastcdr_ops(joint_state, broken)))
    assert [e.refused for e in echo.run([(0, 64, data) for data in over])] == [True] * 3


def test_bounded_messages_need_no_heap(bounded, tmp_path):
    include_dir, messages = bounded
    names = [CppMessageName(m) for m in messages]
    source = tmp_path / 'no_heap.cpp'
    source.write_text(''.join('#include "%s"\n' % n.header for n in names) + ''.join(
        'bool round_trip_%d(uint8_t* buffer, uint32_t size) {\n'
        '  static %s message;\n'
        '  if (!message.copyFromBuf(buffer, size)) return false;\n'
        '  message.copyToBuf(buffer);\n'
        '  return message.copyToFragBuf(buffer, 64).first;\n'
        '}\n' % (index, name.cpp_name) for index, name in enumerate(names)))
    obj = str(tmp_path / 'no_heap.o')
    subprocess.run(['arm-none-eabi-g++', '-std=c++11', '-Os', '-mcpu=cortex-m4', '-mthumb',
                    '-fno-exceptions', '-fno-rtti', '-Wall', '-Wextra', '-Werror', '-I',
                    include_dir, '-c', str(source), '-o', obj], check=True)
    undefined = subprocess.run(['arm-none-eabi-nm', '-u', '-C', obj], capture_output=True,
                               text=True, check=True).stdout
    for symbol in ('operator new', 'malloc', 'operator delete', 'free'):
        assert symbol not in undefined, undefined
