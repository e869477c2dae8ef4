# SPDX-License-Identifier: BSD-3-Clause
"""A real Fast DDS participant takes what the generated code writes, and the
generated code takes what Fast DDS' side writes, on ROS 2's topic and type
names.

The generated code's bytes (as mros2's runtime publishes them: the
encapsulation header, the image, padding to 4) go through one Fast DDS
participant (testing/dds_raw_peer.cpp, standing for the board's transport)
to another on ``rt/<topic>`` under the type name the generated header gives
(``pkg::msg::dds_::Type_``); there Fast-CDR reads back every value. The
other way, Fast-CDR's bytes cross the same way and the generated code's
checked copyFromBuf reads them and writes them again byte for byte.
"""

import random

import pytest

from testing import dds_peer, fastcdr, ros2_messages

TYPES = {
    'test_interface_files': ['test_interface_files/msg/MultiNested',
                             'test_interface_files/msg/Arrays', 'test_interface_files/msg/Strings',
                             'test_interface_files/msg/WStrings'],
    'rosbags': ['std_msgs/msg/String', 'geometry_msgs/msg/Twist', 'sensor_msgs/msg/JointState',
                'sensor_msgs/msg/Imu'],
}
SAMPLES_PER_TYPE = 3


@pytest.fixture(scope='module')
def peer_program(tmp_path_factory):
    return dds_peer.build(str(tmp_path_factory.mktemp('dds_peer')))


def _corpus(request, name):
    return request.getfixturevalue('test_interface_corpus' if name == 'test_interface_files'
                                   else 'rosbags_corpus')


@pytest.mark.slow
@pytest.mark.parametrize('corpus_name', sorted(TYPES))
def test_fast_dds_and_the_generated_code_exchange_samples(request, corpus_name, peer_program,
                                                          fastcdr_program):
    corpus = _corpus(request, corpus_name)
    indexes = [[m.full_name for m in corpus.messages].index(n) for n in TYPES[corpus_name]]
    echo = corpus.echo()
    type_names = echo.type_names()
    rng = random.Random(40)
    for index in indexes:
        message = corpus.messages[index]
        values = [ros2_messages.random_value(message, rng) for _ in range(SAMPLES_PER_TYPE)]
        ops = [ros2_messages.fastcdr_ops(message, value) for value in values]
        references = fastcdr.encode_many(fastcdr_program, ops)
        ours = [e.whole for e in echo.run([(index, 64, r) for r in references])]
        topic = 'rt/mros2_%s' % message.name.lower()
        assert type_names[index] == '%s::msg::dds_::%s_' % (message.package, message.name)

        # The generated code's bytes to the ROS 2 side: Fast-CDR reads the values.
        domain = dds_peer.free_domain_id()
        with dds_peer.receiver(peer_program, topic, type_names[index], len(ours),
                               domain) as ros2_side:
            dds_peer.send(peer_program, topic, type_names[index], ours, domain)
            received = ros2_side.samples()
        assert received == ours, message.full_name
        for value, op_list, data in zip(values, ops, received):
            decoded = fastcdr.decode(fastcdr_program, data, ros2_messages.op_kinds(op_list))
            assert ros2_messages.value_from_ops(message, iter(decoded)) == value

        # Fast-CDR's bytes from the ROS 2 side: the checked decode takes them.
        domain = dds_peer.free_domain_id()
        with dds_peer.receiver(peer_program, topic, type_names[index], len(references),
                               domain) as board_side:
            dds_peer.send(peer_program, topic, type_names[index], references, domain)
            arrived = board_side.samples()
        echoed = echo.run([(index, 64, data) for data in arrived])
        assert [e.raw for e in echoed] == references, message.full_name
