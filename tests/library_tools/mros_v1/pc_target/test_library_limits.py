# SPDX-License-Identifier: BSD-3-Clause
"""What the real mROS v1 library does past the sizes of its configuration
where the fit check cannot refuse the firmware: a frame of heap storage
(no largest size) beyond the largest memory pool, more ROS peers than its
node table holds (the firmware's code, not its types, decides how many
topics and peers it has), and a node name at its maximum length. The app is
tests/fixtures/mros_v1_pc_app/library_limits.cpp with custom_pubsub's
mros_config; docs/pc-target.md ("The library's own limits") describes each
case.
"""

import os
import re
import signal
import struct
import sys
import time

import pytest

from testing.ros_graph import (
    DELIVERY_TIMEOUT, PEER_IP, Board, RosGraph)
from testing.tcpros_peer import (
    HostilePublisher, closed_by_peer, encode_header, frame)
from support.user_checkouts import MROS_V1_ROOT
from support.pc_target_apps import build_app, library_copy

pytestmark = [pytest.mark.needs_mros_v1, pytest.mark.needs_qemu, pytest.mark.slow]

STRING_MD5 = '992ce8a1687cec8c8bd883ec73ca41d1'
NODE_NAME = '/mros_limits'
# The app's cases: its switches P6_1 P6_0.
RECEIVE, PUBLISH, TOPICS, LONG_NODE_NAME = ({'P6_0': 0, 'P6_1': 0}, {'P6_0': 1, 'P6_1': 0},
                                            {'P6_0': 0, 'P6_1': 1}, {'P6_0': 1, 'P6_1': 1})
TOPIC_COUNT = 8
USR_CONFIG = os.path.join('mros_ws', 'custom_pubsub', 'mros_config', 'mros_usr_config.h')
TABLES = ('MROS_TOPIC_MAX_NUM', 'MROS_NODE_MAX_NUM', 'MROS_PUB_TOPIC_CONNECTOR_MAX_NUM',
          'MROS_SUB_TOPIC_CONNECTOR_MAX_NUM')
OUT_OF_MEMORY = 'ret=12'  # MROS_E_NOMEM
NODE_TABLE_FULL = 'mros_node_create 170 ' + OUT_OF_MEMORY

EIGHT_TALKERS = '''
import rospy
from std_msgs.msg import String
rospy.init_node("eight_talkers")
publishers = [rospy.Publisher("t%%d" %% topic, String, queue_size=1) for topic in range(%d)]
rate = rospy.Rate(5)
while not rospy.is_shutdown():
    for topic, publisher in enumerate(publishers):
        publisher.publish(String(data="from t%%d" %% topic))
    rate.sleep()
''' % TOPIC_COUNT


def build_limits_app(mros_root, build_root):
    return build_app(mros_root, str(build_root), 'library_limits.cpp', types=['std_msgs/String'])


@pytest.fixture(scope='module')
def limits_program(tmp_path_factory):
    return build_limits_app(MROS_V1_ROOT, tmp_path_factory.mktemp('limits'))


@pytest.fixture(scope='module')
def wide_tables_program(tmp_path_factory):
    """The app on a copy of the library whose tables hold 40 entries each."""
    root = library_copy(MROS_V1_ROOT, str(tmp_path_factory.mktemp('mros_v1_tables')),
                        {(USR_CONFIG, name): 40 for name in TABLES})
    return build_limits_app(root, tmp_path_factory.mktemp('limits_tables'))


def start(graph, program, directory, case):
    board = Board(graph, program, directory, inputs=case)
    board.process.wait_for('limits ready', timeout=DELIVERY_TIMEOUT)
    return board


def string_frame(size):
    return frame(struct.pack('<I', size) + b'y' * size)


def test_limit_publishing_a_frame_larger_than_the_largest_pool_crashes_the_library(
        limits_program, tmp_path):
    # 2000 bytes of heap storage against custom_pubsub's pools of up to
    # 1024: ros::Publisher::publish logs the failed allocation and copies
    # the message through the pointer it left unset. Bounded storage makes
    # such a frame a build error (test_fit_check.py).
    with RosGraph() as graph:
        board = Board(graph, limits_program, str(tmp_path), inputs=PUBLISH)
        assert board.process.popen.wait(timeout=DELIVERY_TIMEOUT) == -signal.SIGSEGV
    output = board.process.output()
    assert re.search(r'publishing 2000 bytes\n.*mros_memory\.c mros_mem_alloc\(\) \d+ ret=12\n'
                     r'.*api/ros\.cpp publish\(\) \d+ ret=12\n', output), output
    assert 'published' not in output.replace('publishing', '')


def test_hardened_publish_drops_a_frame_larger_than_the_largest_pool(hardened_limits_program,
                                                                     tmp_path):
    # The same app on the library with genmros' patch set (--hardened).
    with RosGraph() as graph:
        board = Board(graph, hardened_limits_program, str(tmp_path), inputs=PUBLISH)
        dropped = board.process.wait_for(
            r'publish\(\) dropped a frame of (\d+) bytes: no memory pool block holds it \(raise '
            r'the largest ROS_INNER_TOPIC_PUBLISHER_MEMPOOL<n>_SIZE\)',
            timeout=DELIVERY_TIMEOUT)[0]
        board.process.wait_for(r'\] published$', timeout=DELIVERY_TIMEOUT)
        assert int(dropped.group(1)) > 2000
        time.sleep(1)
        assert board.process.alive(), board.process.output()


def test_limit_a_received_frame_larger_than_the_largest_pool_is_dropped_with_its_connection(
        limits_program, tmp_path):
    with RosGraph() as graph:
        board = start(graph, limits_program, str(tmp_path), RECEIVE)
        graph.wait_for_graph(subscribers=[('/in', NODE_NAME)])
        with HostilePublisher(graph, '/big_publisher', '/in', 'std_msgs/String') as publisher:
            # The library may connect twice (it never answers publisherUpdate).
            connections = []
            deadline = time.monotonic() + 4
            while time.monotonic() < deadline:
                try:
                    connection, header = publisher.accept(timeout=0.5)
                except OSError:
                    continue
                assert header['md5sum'] == STRING_MD5
                connection.sendall(encode_header({'callerid': '/big_publisher',
                                                  'md5sum': STRING_MD5, 'type': 'std_msgs/String',
                                                  'topic': '/in'}))
                connections.append(connection)
            assert connections
            for connection in connections:
                connection.sendall(string_frame(100))
            board.process.wait_for('in: heard 100 bytes', timeout=DELIVERY_TIMEOUT)
            heard_small = len(board.process.lines())
            for connection in connections:
                connection.sendall(string_frame(2000))
            # Each connection is closed, and not made again.
            assert all(closed_by_peer(connection) for connection in connections)
            with pytest.raises(OSError):
                publisher.accept(timeout=3)
        assert board.process.alive(), board.process.output()
    after = '\n'.join(board.process.lines()[heard_small:])
    assert 'heard' not in after
    assert re.search(r'mros_protocol_topic_data_receive\(\) \d+ ret=12', after), after
    assert after.count('removed connector') == len(connections)


def heard_topics(board):
    return set(re.findall(r't(\d): heard \[from t\1\]', board.process.output()))


def eight_talkers(graph, board):
    graph.wait_for_graph(subscribers=[('/t%d' % topic, NODE_NAME)
                                      for topic in range(TOPIC_COUNT)])
    graph.start('eight_talkers', [sys.executable, '-c', EIGHT_TALKERS], {'ROS_IP': PEER_IP})


def test_limit_more_peers_than_the_node_table_holds_lose_their_connections(
        limits_program, tmp_path):
    # Each TCPROS connection to a ROS publisher takes an entry of the node
    # table (MROS_NODE_MAX_NUM, 10 in the samples), and the library may
    # connect to a publisher twice. With 8 topics of one rospy node the table
    # runs out: the connection is dropped with a log line, and which topics
    # are ever delivered depends on the order (runs here saw 5 to 8 of 8).
    with RosGraph() as graph:
        board = start(graph, limits_program, str(tmp_path), TOPICS)
        eight_talkers(graph, board)
        board.process.wait_for(re.escape(NODE_TABLE_FULL), timeout=DELIVERY_TIMEOUT)
        assert board.process.alive(), board.process.output()


@pytest.fixture(scope='module')
def hardened_limits_program(tmp_path_factory):
    """The same app on the library with genmros' patch set (--hardened)."""
    return build_app(MROS_V1_ROOT, str(tmp_path_factory.mktemp('limits_hardened')),
                     'library_limits.cpp', types=['std_msgs/String'],
                     header_flags=['--hardened'])


def test_hardened_a_full_node_table_names_its_setting(tmp_path):
    # The case above on the library with the patch set: it answers
    # publisherUpdate, so it connects to each publisher once and custom_pubsub's
    # 10 nodes hold the 8 topics; with room for 6 the line says which setting
    # to raise, and its value.
    small_table = 6
    root = library_copy(MROS_V1_ROOT, str(tmp_path / 'mros_v1'),
                        {(USR_CONFIG, 'MROS_NODE_MAX_NUM'): small_table})
    program = build_app(root, str(tmp_path / 'app'), 'library_limits.cpp',
                        types=['std_msgs/String'], header_flags=['--hardened'])
    with RosGraph() as graph:
        board = start(graph, program, str(tmp_path), TOPICS)
        eight_talkers(graph, board)
        board.process.wait_for(re.escape(
            'no room for another node: the table holds MROS_NODE_MAX_NUM = %d (raise it in '
            'mros_usr_config.h)' % small_table), timeout=DELIVERY_TIMEOUT)
        assert board.process.alive(), board.process.output()
    assert NODE_TABLE_FULL not in board.process.output()


def test_hardened_every_topic_is_delivered_with_the_samples_tables(hardened_limits_program,
                                                                   tmp_path):
    with RosGraph() as graph:
        board = start(graph, hardened_limits_program, str(tmp_path), TOPICS)
        eight_talkers(graph, board)
        for topic in range(TOPIC_COUNT):
            board.process.wait_for(r't%d: heard \[from t%d\]' % (topic, topic),
                                   timeout=DELIVERY_TIMEOUT)
    assert NODE_TABLE_FULL not in board.process.output()


def test_with_the_tables_raised_every_topic_is_delivered(wide_tables_program, tmp_path):
    with RosGraph() as graph:
        board = start(graph, wide_tables_program, str(tmp_path), TOPICS)
        eight_talkers(graph, board)
        deadline = time.monotonic() + DELIVERY_TIMEOUT
        while len(heard_topics(board)) < TOPIC_COUNT:
            assert time.monotonic() < deadline, board.process.output()
            time.sleep(0.2)
        assert NODE_TABLE_FULL not in board.process.output()


def test_limit_a_node_name_one_short_of_its_maximum_never_registers(limits_program, tmp_path):
    # MROS_NODE_NAME_MAXLEN is 20 in the samples, and the library accepts a
    # name of up to 20 characters, but it keeps the name with its leading
    # '/' in a field of 20 bytes, so a name of 19 has no room for its NUL
    # (and one of 20 overruns the field): 'mros_limits_node_19' reaches no
    # master, and nothing says so. Keep node names under 19 characters.
    with RosGraph() as graph:
        board = start(graph, limits_program, str(tmp_path), LONG_NODE_NAME)
        time.sleep(5)
        _, subscribers = graph.system_state()
        assert '/in' not in subscribers, subscribers
        assert board.process.alive(), board.process.output()
        assert 'CONFIG ERROR' not in board.process.output()
