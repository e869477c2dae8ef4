# SPDX-License-Identifier: BSD-3-Clause
"""The real DDS peer the mros2 tests stand the ROS 2 side with
(testing/dds_peer.py, testing/dds_raw_peer.cpp), held against itself: one
Fast DDS participant's samples reach another byte for byte and in order on
ROS 2's topic and type names, and not a reader of another type nor one
asking for more durability than the writer offers; the echo mode writes
back what it received. The samples
are CDR written by hand, so a fault here is the peer's, not generated
code's."""

import struct

import pytest

from testing.dds_peer import PeerError, build, echoer, free_domain_id, receiver, send
from testing.ros_paths import ros2_include_prefix

pytestmark = pytest.mark.skipif(ros2_include_prefix('fastdds') is None,
                                reason='needs Fast DDS (Debian: libfastrtps-dev)')

TOPIC = 'rt/chatter'
STRING_TYPE = 'std_msgs::msg::dds_::String_'
# Little endian CDR, as ROS 2 writes it.
ENCAPSULATION = bytes([0x00, 0x01, 0x00, 0x00])


def string_sample(text):
    """A std_msgs/String in CDR: the header, the length with the NUL, the
    characters, the NUL, padding to 4 bytes."""
    body = struct.pack('<I', len(text) + 1) + text.encode() + b'\0'
    return ENCAPSULATION + body + b'\0' * (-len(body) % 4)


@pytest.fixture(scope='module')
def peer(tmp_path_factory):
    return build(str(tmp_path_factory.mktemp('dds_peer')))


def test_hand_written_sample():
    assert string_sample('hello') == bytes.fromhex('00010000' '06000000' '68656c6c6f00' '0000')


def test_samples_reach_another_participant_byte_for_byte_in_order(peer):
    samples = [string_sample('hello'), string_sample(''), string_sample('hello world, again')]
    domain = free_domain_id()
    with receiver(peer, TOPIC, STRING_TYPE, len(samples), domain) as reading:
        send(peer, TOPIC, STRING_TYPE, samples, domain)
        assert reading.samples() == samples


def test_a_reader_of_another_type_gets_nothing(peer):
    sample = string_sample('hello')
    domain = free_domain_id()
    with receiver(peer, TOPIC, 'std_msgs::msg::dds_::Header_', 1, domain) as other_type, \
            receiver(peer, TOPIC, STRING_TYPE, 1, domain) as same_type:
        send(peer, TOPIC, STRING_TYPE, [sample], domain)
        assert same_type.samples() == [sample]
        with pytest.raises(PeerError, match='received 0 sample'):
            other_type.samples(timeout=3)


def test_echo_writes_back_what_it_received(peer):
    samples = [string_sample('ping %d' % number) for number in range(3)]
    domain = free_domain_id()
    with receiver(peer, 'rt/reply', STRING_TYPE, len(samples), domain) as replies, \
            echoer(peer, TOPIC, STRING_TYPE, 'rt/reply', len(samples), domain) as echoing:
        send(peer, TOPIC, STRING_TYPE, samples, domain)
        assert echoing.samples() == samples
        assert replies.samples() == samples


def test_a_reader_asking_for_more_durability_than_offered_gets_nothing(peer):
    sample = string_sample('hello')
    domain = free_domain_id()
    with receiver(peer, TOPIC, STRING_TYPE, 1, domain) as transient_local, \
            receiver(peer, TOPIC, STRING_TYPE, 1, domain, durability='volatile') as volatile:
        send(peer, TOPIC, STRING_TYPE, [sample], domain, durability='volatile')
        assert volatile.samples() == [sample]
        with pytest.raises(PeerError, match='received 0 sample'):
            transient_local.samples(timeout=2)
        transient_local.wait_for_log('INCOMPATIBLE QOS')
