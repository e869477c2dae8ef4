# SPDX-License-Identifier: BSD-3-Clause
"""The mros2 headers are byte-exact with ROS 2's serializers, both ways.

Random instances of every type of ROS 2's test interface files (Debian's
ros2-test-interface-files) and of std_msgs, geometry_msgs and sensor_msgs as
ROS 2 defines them (their definitions from rosbags' type store, written out
as packages and read by genmros' rosidl front end) go:

- into generated code as Fast-CDR (Debian's libfastcdr) and rosbags write
  them: the checked copyFromBuf takes them, and copyToBuf writes the same
  bytes again, as one buffer, in mros2's fragments and when published twice;
- out of generated code into Fast-CDR, which reads back the instance.

The echo program is compiled from the generated headers for this machine,
for 32-bit ARM Linux (run under qemu-arm) and for big-endian s390x (under
qemu-s390x).
"""

import os
import random

import pytest

from testing import fastcdr, ros2_messages

from support.mros2_corpus import TEST_INTERFACE_PACKAGE, typestore
from testing.ros_paths import ros2_package_dir

INSTANCES_PER_TYPE = 12
# mros2's fragment buffer is 64 bytes; smaller ones cut inside every value.
FRAGMENT_SIZES = (64, 16, 8)


def _instances(corpus, seed):
    rng = random.Random(seed)
    return [(index, ros2_messages.random_value(message, rng))
            for index, message in enumerate(corpus.messages)
            for _ in range(INSTANCES_PER_TYPE)]


def _padded(raw):
    return raw + bytes(-len(raw) % 4)


def _check_echo(corpus, instances, references, echoed):
    for (index, _), reference, result in zip(instances, references, echoed):
        name = corpus.messages[index].full_name
        assert not result.refused, '%s: the checked copyFromBuf refused %s' % (name,
                                                                               reference.hex())
        assert result.raw == reference, '%s: wrote %s, reference %s' % (
            name, result.raw.hex(), reference.hex())
        assert result.whole == _padded(reference), name
        assert result.fragmented == result.whole, '%s: fragments differ' % name
        assert result.again == result.whole, '%s: the second publication differs' % name


TARGET_PARAMS = ['host', pytest.param('arm', marks=[pytest.mark.slow, pytest.mark.needs_qemu]),
                 pytest.param('s390x', marks=[pytest.mark.slow, pytest.mark.needs_qemu])]


@pytest.mark.parametrize('target', TARGET_PARAMS)
def test_fastcdr_bytes_come_back_byte_for_byte(test_interface_corpus, rosbags_corpus,
                                               fastcdr_program, target):
    for number, corpus in enumerate((test_interface_corpus, rosbags_corpus)):
        instances = _instances(corpus, seed=number)
        references = fastcdr.encode_many(
            fastcdr_program, [ros2_messages.fastcdr_ops(corpus.messages[i], value)
                              for i, value in instances])
        samples = [(index, FRAGMENT_SIZES[n % len(FRAGMENT_SIZES)], reference)
                   for n, ((index, _), reference) in enumerate(zip(instances, references))]
        _check_echo(corpus, instances, references, corpus.echo(target).run(samples))


def test_generated_bytes_read_back_in_fastcdr(test_interface_corpus, rosbags_corpus,
                                              fastcdr_program):
    for number, corpus in enumerate((test_interface_corpus, rosbags_corpus)):
        instances = _instances(corpus, seed=10 + number)
        echo = corpus.echo()
        ops = [ros2_messages.fastcdr_ops(corpus.messages[i], value) for i, value in instances]
        echoed = echo.run([(i, 64, data) for (i, _), data
                           in zip(instances, fastcdr.encode_many(fastcdr_program, ops))])
        for (index, value), op_list, result in zip(instances, ops, echoed):
            decoded = fastcdr.decode(fastcdr_program, result.raw, ros2_messages.op_kinds(op_list))
            assert ros2_messages.value_from_ops(corpus.messages[index], iter(decoded)) == value


def test_rosbags_bytes_come_back_and_rosbags_reads_ours(test_interface_corpus, rosbags_corpus):
    from rosbags.typesys import get_types_from_msg
    store = typestore()
    msg_dir = ros2_package_dir(TEST_INTERFACE_PACKAGE)
    for path in sorted(os.listdir(msg_dir)):
        name = '%s/msg/%s' % (TEST_INTERFACE_PACKAGE, path[:-4])
        with open(os.path.join(msg_dir, path)) as stream:
            store.register(get_types_from_msg(stream.read(), name))
    checked = 0
    for number, corpus in enumerate((test_interface_corpus, rosbags_corpus)):
        instances = [(i, v) for i, v in _instances(corpus, seed=20 + number)
                     if corpus.messages[i].kind == 'msg'
                     and not ros2_messages.has_wstring(corpus.messages[i])]
        references = []
        for index, value in instances:
            message = corpus.messages[index]
            references.append(bytes(store.serialize_cdr(
                ros2_messages.rosbags_message(store, message, value), message.full_name)))
        echoed = corpus.echo().run(
            [(i, 64, reference) for (i, _), reference in zip(instances, references)])
        _check_echo(corpus, instances, references, echoed)
        for (index, _), reference, result in zip(instances, references, echoed):
            name = corpus.messages[index].full_name
            ours = store.deserialize_cdr(result.raw, name)
            assert bytes(store.serialize_cdr(ours, name)) == reference, name
            checked += 1
    assert checked > 500


def test_every_cut_of_a_sample_is_refused(test_interface_corpus, fastcdr_program):
    """The checked copyFromBuf never takes a sample cut short: every prefix
    of every sample is refused."""
    corpus = test_interface_corpus
    rng = random.Random(30)
    samples = []
    images = fastcdr.encode_many(fastcdr_program, [
        ros2_messages.fastcdr_ops(message, ros2_messages.random_value(message, rng))
        for message in corpus.messages])
    for index, data in enumerate(images):
        samples += [(index, 64, data[:length]) for length in range(len(data))]
    echoed = corpus.echo().run(samples)
    accepted = [(corpus.messages[i].full_name, len(d)) for (i, _, d), r in zip(samples, echoed)
                if not r.refused]
    assert accepted == []
