# SPDX-License-Identifier: BSD-3-Clause
"""genmros mros-v1-pc --hardened: the sample string_pubsub on the real
library with genmros' patch set applied to a copy (colcon_mros/mros_v1/
patches), against the same app on the library as it is. Each patch's test
here fails without it; test_mros_v1_pc.py pins the unpatched library's
behaviour (test_limit_*)."""

import os
import re
import socket
import struct
import sys
import time
import xmlrpc.client

import pytest

from testing.ros_graph import (DELIVERY_TIMEOUT, PEER_IP, Board,
                               RosGraph)
from testing.tcpros_peer import (
    HostilePublisher, RawSubscriber, closed_by_peer, encode_header)
from support.checkout import run_genmros
from support.user_checkouts import MROS_V1_ROOT
from support.pc_target_apps import build_sample

pytestmark = [pytest.mark.needs_mros_v1, pytest.mark.needs_qemu, pytest.mark.slow]

STRING_MD5 = '992ce8a1687cec8c8bd883ec73ca41d1'
# gcc quotes the name as the locale allows.
STRTOL_WARNING = re.compile(r"implicit declaration of function .strtol.")


def _build(build_root, *flags, app='string_pubsub'):
    return build_sample(MROS_V1_ROOT, app, os.path.join(build_root, 'build'), '--target', 'arm',
                        *flags)


@pytest.fixture(scope='module')
def hardened(tmp_path_factory):
    return _build(str(tmp_path_factory.mktemp('hardened')), '--hardened')


@pytest.fixture(scope='module')
def as_it_is(tmp_path_factory):
    return _build(str(tmp_path_factory.mktemp('as_it_is')))


@pytest.fixture(scope='module')
def hardened_custom_pubsub(tmp_path_factory):
    return _build(str(tmp_path_factory.mktemp('hardened_custom')), '--hardened',
                  app='custom_pubsub')[0]


def test_the_hardened_build_leaves_the_checkout_as_it_is_and_declares_strtol(hardened,
                                                                             as_it_is):
    program, output = hardened
    assert 'mROS v1 library of %s (hardened)' % MROS_V1_ROOT in output
    assert not STRTOL_WARNING.search(output), output
    _, unpatched_output = as_it_is
    assert STRTOL_WARNING.search(unpatched_output), unpatched_output
    check = run_genmros('mros-v1-harden', '--mros-v1-root', MROS_V1_ROOT, '--check', check=False)
    assert check.returncode == 1 and check.stdout
    assert all(line.startswith('not applied') for line in check.stdout.splitlines())


def _listening_board(graph, program, directory):
    """string_pubsub in graph, once it subscribes to /test_string."""
    board = Board(graph, program, directory)
    graph.wait_for_graph(subscribers=[('/test_string', '/mros_node2')])
    return board


def _subscriber_connection(hostile, board):
    try:
        connection, header = hostile.accept(timeout=DELIVERY_TIMEOUT)
    except OSError as error:
        raise AssertionError('the board did not connect (%s):\n%s'
                             % (error, board.process.output()))
    assert header['md5sum'] == STRING_MD5, header
    return connection


def _reply_header(extra=None):
    fields = {'callerid': '/hostile', 'md5sum': STRING_MD5, 'type': 'std_msgs/String',
              'topic': '/test_string'}
    fields.update(extra or {})
    return encode_header(fields)


def _refused_and_still_serving(board, connection, peer, longer_than):
    """The board refused a connection header of more than longer_than bytes
    from a peer ('publisher' or 'subscriber') with its line, closed the
    connection (no socket is left behind), and still serves: its slave and
    publisher take a subscriber."""
    assert closed_by_peer(connection), board.process.output()
    refusal = board.process.wait_for(
        r"refused a %s's connection header of (\d+) bytes: the buffer holds 512 "
        r'\(raise MROS_PACKET_MAXSIZE_REQ_TCPROS and MROS_PACKET_MAXSIZE_RES_TCPROS\)' % peer,
        timeout=DELIVERY_TIMEOUT)[0]
    assert int(refusal.group(1)) > longer_than
    raw = RawSubscriber(board.slave_uri, '/mros_msg', 'std_msgs/String', STRING_MD5)
    raw.close()
    assert raw.header['md5sum'] == STRING_MD5
    assert board.process.alive(), board.process.output()


def test_hardened_a_long_header_from_a_publisher_is_refused_and_the_node_stays_up(hardened,
                                                                                  tmp_path):
    # Unpatched, the library reads this header past its 512-byte buffer and
    # crashes (test_mros_v1_pc.py, test_limit_a_long_header_from_a_publisher_...).
    program, _ = hardened
    with RosGraph() as graph:
        board = _listening_board(graph, program, str(tmp_path))
        with HostilePublisher(graph, '/hostile', '/test_string', 'std_msgs/String') as hostile:
            connection = _subscriber_connection(hostile, board)
            connection.sendall(_reply_header({'message_definition': 'x' * 5000}))
            _refused_and_still_serving(board, connection, 'publisher', 5000)


def test_hardened_a_long_header_from_a_subscriber_is_refused_and_the_node_stays_up(hardened,
                                                                                   tmp_path):
    # Unpatched, the library reads it past its 512-byte buffer (AddressSanitizer's
    # report in test_mros_v1_pc_types.py; on the board, the slave task's state).
    program, _ = hardened
    with RosGraph() as graph:
        board = Board(graph, program, str(tmp_path))
        graph.wait_for_graph(publishers=[('/mros_msg', '/mros_node')])
        # Once a subscriber is served, the slave is up for the next.
        RawSubscriber(board.slave_uri, '/mros_msg', 'std_msgs/String', STRING_MD5).close()
        code, _, protocol = xmlrpc.client.ServerProxy(board.slave_uri).requestTopic(
            '/long_subscriber', '/mros_msg', [['TCPROS']])
        assert code == 1
        connection = socket.create_connection((protocol[1], protocol[2]),
                                              timeout=DELIVERY_TIMEOUT)
        connection.sendall(encode_header({
            'callerid': '/long_subscriber', 'topic': '/mros_msg', 'type': 'std_msgs/String',
            'md5sum': STRING_MD5, 'message_definition': 'x' * 3000}))
        _refused_and_still_serving(board, connection, 'subscriber', 3000)


ANYMSG_LISTENER = """
import rospy
rospy.init_node('anymsg_listener')
rospy.Subscriber('mros_msg', rospy.AnyMsg,
                 lambda m: print('anymsg got %d bytes' % len(m._buff), flush=True))
rospy.spin()
"""


def test_hardened_an_anymsg_subscriber_gets_data(hardened_custom_pubsub, tmp_path):
    # rospy's AnyMsg, as rostopic hz and rosbag record subscribe; unpatched it
    # gets nothing (test_mros_v1_pc.py, test_limit_no_message_definition_...).
    with RosGraph() as graph:
        board = Board(graph, hardened_custom_pubsub, str(tmp_path))
        listener = graph.start('anymsg_listener', [sys.executable, '-c', ANYMSG_LISTENER],
                               {'ROS_IP': PEER_IP})
        got = listener.wait_for(r'anymsg got (\d+) bytes', timeout=DELIVERY_TIMEOUT, count=2)
        assert all(int(match.group(1)) > 0 for match in got)
        assert board.process.alive(), board.process.output()


def test_hardened_the_publisher_header_carries_the_definition_text(hardened, tmp_path):
    # Unpatched, the library stores the text and never sends it
    # (test_mros_v1_pc.py, test_limit_no_message_definition_...).
    from std_msgs.msg import String  # genpy's, from the ROS environment
    program, _ = hardened
    with RosGraph() as graph:
        board = Board(graph, program, str(tmp_path))
        graph.wait_for_graph(publishers=[('/mros_msg', '/mros_node')])
        raw = RawSubscriber(board.slave_uri, '/mros_msg', 'std_msgs/String', STRING_MD5)
        raw.close()
    assert raw.header['message_definition'] == String._full_text


@pytest.mark.parametrize('library', ['as_it_is', 'hardened'])
def test_subscribers_that_left_give_their_room_back_when_hardened(request, library, tmp_path):
    # string_pubsub publishes mros_msg only after its button (P6_0) is
    # pressed. Twelve subscribers come and go meanwhile: more than its node
    # table (MROS_NODE_MAX_NUM, 10) and subscription connections (10, one
    # its own) hold. As it is, the library finds they left only when a send
    # to them fails, so the thirteenth gets its reply header and no room:
    # never a message. Hardened (release-subscribers-that-left), each new
    # subscriber finds the ones that left and takes their room.
    program, _ = request.getfixturevalue(library)
    with RosGraph() as graph:
        board = Board(graph, program, str(tmp_path))
        graph.wait_for_graph(publishers=[('/mros_msg', '/mros_node')])
        try:
            for _ in range(12):
                RawSubscriber(board.slave_uri, '/mros_msg', 'std_msgs/String', STRING_MD5).close()
                time.sleep(0.3)  # the publisher task has added it to its tables
            last = RawSubscriber(board.slave_uri, '/mros_msg', 'std_msgs/String', STRING_MD5)
        except AssertionError as error:
            raise AssertionError('%s\nthe board:\n%s' % (error, board.process.output()))
        board.set_inputs(P6_0=0)
        last.connection.settimeout(10)
        if library == 'hardened':
            assert last.next_body()[4:].startswith(b'Distance[')
        else:
            with pytest.raises(socket.timeout):
                last.next_body()
        assert board.process.alive(), board.process.output()


def _string_frame(text):
    """A std_msgs/String frame on the wire."""
    body = struct.pack('<I', len(text)) + text
    return struct.pack('<I', len(body)) + body


def _send_blue_until_heard(connection, board):
    deadline = time.monotonic() + DELIVERY_TIMEOUT
    while 'I heard [blue]' not in board.process.output():
        assert time.monotonic() < deadline, board.process.output()
        connection.sendall(_string_frame(b'blue'))
        time.sleep(0.5)


def _until_blue_is_heard(publisher, board):
    """Serves the board's connection to publisher with good frames until the app hears one."""
    connection = _subscriber_connection(publisher, board)
    connection.sendall(_reply_header())
    _send_blue_until_heard(connection, board)


def _blue_is_heard_after_failing_publishers(program, directory, count, fail):
    """count publishers of /test_string, each connection from the app ended
    by fail(connection), and then a good publisher whose frames the app hears."""
    with RosGraph() as graph:
        board = _listening_board(graph, program, directory)
        for index in range(count):
            with HostilePublisher(graph, '/failing_%d' % index, '/test_string',
                                  'std_msgs/String') as publisher:
                fail(_subscriber_connection(publisher, board))
        with HostilePublisher(graph, '/good', '/test_string', 'std_msgs/String') as publisher:
            _until_blue_is_heard(publisher, board)
        assert board.process.alive(), board.process.output()


def test_hardened_publishers_that_fail_give_their_topic_entries_back(hardened, tmp_path):
    # Each publisher that closes the connection before its reply header
    # makes the subscriber task remove its connector. Unpatched, that takes
    # the topic's entry out of the connection table without freeing it: after
    # MROS_TOPIC_MAX_NUM (20 in string_pubsub) such publishers the app
    # connects to no publisher again (found by the network fuzzer; with
    # release-topic-entries taken out, this test fails that way).
    _blue_is_heard_after_failing_publishers(hardened[0], str(tmp_path), 22,
                                            lambda connection: connection.close())


def _cut_short(connection):
    connection.sendall(_reply_header() + struct.pack('<I', 100) + b'\x04\x00\x00\x00')
    connection.close()


def test_hardened_frames_cut_short_give_their_memory_pool_blocks_back(hardened, tmp_path):
    # string_pubsub's pools for frames from other nodes hold 28 blocks (16 +
    # 8 + 4). Unpatched, each frame a publisher cuts short keeps its block,
    # so after 28 no frame is received again (found by the network fuzzer;
    # with bounded-publisher-frames taken out, this test fails that way).
    _blue_is_heard_after_failing_publishers(hardened[0], str(tmp_path), 30, _cut_short)


def test_hardened_a_frame_no_block_holds_is_skipped_and_the_topic_goes_on(hardened, tmp_path):
    # string_pubsub's largest block for frames from other nodes is 1024 bytes.
    # Unpatched, and with bounded-publisher-frames before it skipped the
    # frame, the library closes the connection after such a frame and never
    # connects to that publisher again: one large message ends the topic,
    # where roscpp goes on.
    program, _ = hardened
    with RosGraph() as graph:
        board = _listening_board(graph, program, str(tmp_path))
        with HostilePublisher(graph, '/large', '/test_string', 'std_msgs/String') as publisher:
            connection = _subscriber_connection(publisher, board)
            connection.sendall(_reply_header() + _string_frame(b'x' * 2000))
            board.process.wait_for(
                r'refused a frame of 2004 bytes from a publisher: no memory pool block holds it '
                r'\(raise the largest ROS_OUTER_TOPIC_PUBLISHER_MEMPOOL<n>_SIZE\)',
                timeout=DELIVERY_TIMEOUT)
            _send_blue_until_heard(connection, board)
        assert board.process.alive(), board.process.output()


def test_hardened_a_publisher_that_never_answers_does_not_stop_the_node(hardened, tmp_path):
    # A publisher that accepts the app's connection and never sends its
    # connection header. Unpatched (receive-time-out taken out), the
    # subscriber task waits for it for good, holding the library's lock, and
    # no publisher is heard again; patched, the receive gives up after
    # MROS_COMM_RECEIVE_TIMEOUT_MSEC (3 s) and the connection is closed.
    program, _ = hardened
    with RosGraph() as graph:
        board = _listening_board(graph, program, str(tmp_path))
        with HostilePublisher(graph, '/silent', '/test_string', 'std_msgs/String') as silent:
            connection = _subscriber_connection(silent, board)
            started = time.monotonic()
            assert closed_by_peer(connection, timeout=DELIVERY_TIMEOUT), board.process.output()
            assert time.monotonic() - started >= 2.5
        with HostilePublisher(graph, '/good', '/test_string', 'std_msgs/String') as publisher:
            _until_blue_is_heard(publisher, board)
        assert board.process.alive(), board.process.output()
