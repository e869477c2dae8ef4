# SPDX-License-Identifier: BSD-3-Clause
"""The real mROS v1 library, unchanged, with genmros' headers, on the PC
target: `genmros mros-v1-pc` builds the sample apps
custom_pubsub and string_pubsub from their own sources and the checkout's
mros-lib for 32-bit ARM Linux (the board's instruction set), and they run
under qemu-arm against a real rosmaster, the sample's own roscpp nodes
(ros_catkin_ws, built here with catkin_make) and rospy.

The checkout is the one MROS_V1_ROOT names; without one these tests are
skipped, saying so. Nothing of it is
copied: builds and workspaces are in temporary directories.

The library needs its peers on another address than its own (it ignores a
publisher at its own IP), and roscpp with a loopback ROS_IP takes TCPROS
connections on 127.0.0.1 only, so the apps run with ROS_IP=127.0.0.2 and the
ROS nodes with 127.0.0.1. The library's limits that a user meets are
pinned by the tests at the end.
"""

import http.client
import os
import re
import socket
import struct
import subprocess
import sys
import textwrap
import time
import xmlrpc.client

import pytest

from testing.ros_graph import (
    BOARD_IP, DELIVERY_TIMEOUT, PEER_IP, Board, RosGraph, free_port, sourced_environment)
from testing.tcpros_peer import (
    HostilePublisher, RawSubscriber, encode_header)
from support.build_integration import run
from support.user_checkouts import MROS_V1_ROOT
from support.pc_target_apps import build_sample
from support.sanitizer_reports import LIBRARY_REPORTS, sanitizer_reports

pytestmark = [pytest.mark.needs_mros_v1, pytest.mark.needs_qemu, pytest.mark.slow]

APPS = ('string_pubsub', 'custom_pubsub')
STRING_MD5 = '992ce8a1687cec8c8bd883ec73ca41d1'


@pytest.fixture(scope='module')
def ros_side(tmp_path_factory):
    """The sample apps' ROS packages (ros_catkin_ws/src, linked, unchanged)
    built with catkin_make: their roscpp nodes and genpy messages."""
    workspace = str(tmp_path_factory.mktemp('ros_catkin_ws'))
    os.mkdir(os.path.join(workspace, 'src'))
    for package in APPS:
        os.symlink(os.path.join(MROS_V1_ROOT, 'ros_catkin_ws', 'src', package),
                   os.path.join(workspace, 'src', package))
    # The sample's CMakeLists.txt does not make its nodes depend on its
    # messages, so their headers are generated first.
    run(['catkin_make', 'custom_pubsub_generate_messages'], workspace)
    run(['catkin_make'], workspace)
    environment = sourced_environment(os.path.join(workspace, 'devel', 'setup.bash'))
    environment['DEVEL_LIB'] = os.path.join(workspace, 'devel', 'lib')
    return environment


def sample_node(ros_side, package, node):
    """The command line of one of the sample's roscpp nodes."""
    return [os.path.join(ros_side['DEVEL_LIB'], package, node)]


def _samples(tmp_path_factory, name, *flags):
    """{app: program} of the sample apps built by genmros mros-v1-pc with flags."""
    build_root = str(tmp_path_factory.mktemp(name))
    return {app: build_sample(MROS_V1_ROOT, app, os.path.join(build_root, app), *flags)[0]
            for app in APPS}


@pytest.fixture(scope='module')
def programs(tmp_path_factory):
    """The sample apps, built for ARM Linux by genmros mros-v1-pc."""
    return _samples(tmp_path_factory, 'mros_v1_pc', '--target', 'arm')


def ros_node(graph, name, argv, **options):
    """A ROS node on the peer address, its log lines written as they come."""
    return graph.start(name, argv, {'ROS_IP': PEER_IP, 'ROSCONSOLE_STDOUT_LINE_BUFFERED': '1'},
                       **options)


def type_until_heard(publisher, line, board, pattern):
    """Types line into a sample publisher once a second until the app logs
    pattern: a roscpp publisher drops what it publishes before it has taken
    the library's connection header."""
    deadline = time.monotonic() + DELIVERY_TIMEOUT
    while True:
        start = len(board.process.lines())
        publisher.type(line)
        try:
            return board.process.wait_for(pattern, timeout=1.0, start=start)
        except AssertionError:
            if time.monotonic() > deadline:
                raise


STRING_TALKER = '''
    import rospy
    from std_msgs.msg import String
    rospy.init_node(%r)
    publisher = rospy.Publisher('test_string', String, queue_size=1)
    rate = rospy.Rate(2)
    while not rospy.is_shutdown():
        publisher.publish(String(data=%r))
        rate.sleep()
'''


def rospy_string_talker(graph, node, text, ros_ip=PEER_IP):
    """A rospy node publishing text on test_string twice a second."""
    return rospy_script(graph, node, STRING_TALKER % (node, text), ros_ip)


def rospy_script(graph, name, code, ros_ip=PEER_IP):
    script = textwrap.dedent(code)
    return graph.start(name, [sys.executable, '-c', script], {'ROS_IP': ros_ip})


def in_devel_space(environment, code):
    """What Python code writes to stdout, run in the sample's devel space."""
    return subprocess.run([sys.executable, '-c', textwrap.dedent(code)], env=environment,
                          capture_output=True, text=True, check=True).stdout


def genpy_bytes(environment, statement):
    """genpy's serialization of the message `statement` builds."""
    return bytes.fromhex(in_devel_space(environment, '''
        import io, sys
        from std_msgs.msg import String
        from custom_pubsub.msg import UserTypeTest, PersonName, LEDValues
        buffer = io.BytesIO()
        (%s).serialize(buffer)
        sys.stdout.write(buffer.getvalue().hex())
    ''' % statement))


def raw_md5(environment, name):
    """The MD5 sum of custom_pubsub's type name, as genpy has it."""
    return in_devel_space(environment, 'import custom_pubsub.msg as m, sys; '
                                       'sys.stdout.write(m.%s._md5sum)' % name)


def test_string_pubsub_publishes_to_roscpp_rospy_byte_equal_to_genpy(ros_side, programs, tmp_path):
    with RosGraph(ros_side) as graph:
        board = Board(graph, programs['string_pubsub'], str(tmp_path))
        board.process.wait_for(r'Data Publish Start', timeout=DELIVERY_TIMEOUT)
        roscpp = ros_node(graph, 'ultrasonic_subscriber',
                          sample_node(ros_side, 'string_pubsub', 'ultrasonic_subscriber'))
        rospy = rospy_script(graph, 'rospy_listener', '''
            import rospy
            from std_msgs.msg import String
            rospy.init_node('rospy_listener')
            rospy.Subscriber('mros_msg', String, lambda m: print('rospy heard %r' % m.data, flush=True))
            rospy.spin()
        ''')  # noqa: E501
        graph.wait_for_graph(subscribers=[('/mros_msg', '/ultrasonic_subscriber'),
                                          ('/mros_msg', '/rospy_listener')])
        raw = RawSubscriber(board.slave_uri, '/mros_msg', 'std_msgs/String', STRING_MD5)
        # An echo pulse of 300 ms on the ultrasonic sensor's pin (InterruptIn
        # rise and fall; long enough that the 10 ms input polling sees it on
        # a loaded machine), then the user button pressed and released: the
        # app starts publishing the distance once a second.
        board.set_inputs(P6_0=1, P2_15=1)
        time.sleep(0.3)
        board.set_inputs(P6_0=1, P2_15=0)
        time.sleep(0.3)
        board.set_inputs(P6_0=0)
        time.sleep(0.3)
        board.set_inputs(P6_0=1)
        body = raw.next_body()
        raw.close()
        text = body[4:].decode()
        distance = int(text[len('Distance['):-len(']cm')])
        # 300 ms at 0.0170 cm/us, give or take the 10 ms input polling and load.
        assert 4500 <= distance <= 8000, text
        assert body == genpy_bytes(ros_side, 'String(data=%r)' % text)
        heard = roscpp.wait_for(r'I heard \[(Distance\[\d+\]cm)\]', timeout=DELIVERY_TIMEOUT)[0]
        assert heard.group(1) == text
        heard = rospy.wait_for(r"rospy heard '(.*)'", timeout=DELIVERY_TIMEOUT)[0]
        assert heard.group(1) == text
        # The ultrasonic trigger, a Ticker at interrupt level, pulses its pin.
        assert {'P2_14 1', 'P2_14 0'} <= set(board.output_lines())


def test_string_pubsub_callback_gets_what_roscpp_and_rospy_publish(ros_side, programs, tmp_path):
    with RosGraph(ros_side) as graph:
        board = Board(graph, programs['string_pubsub'], str(tmp_path))
        roscpp = ros_node(graph, 'led_switch_publisher',
                          sample_node(ros_side, 'string_pubsub', 'led_switch_publisher'),
                          interactive=True)
        graph.wait_for_graph(publishers=[('/test_string', '/led_switch_publisher')],
                             subscribers=[('/test_string', '/mros_node2')])
        board.process.wait_for(r'sub connected', timeout=DELIVERY_TIMEOUT)
        type_until_heard(roscpp, 'red\n', board, r'I heard \[red\]')
        board.wait_for_output('P6_13 0.78125')
    # A new graph: with one publisher connected, the library reads no
    # other on the same topic (a limit of its own, see the end).
    with RosGraph(ros_side) as graph:
        board = Board(graph, programs['string_pubsub'], str(tmp_path))
        rospy_string_talker(graph, 'rospy_talker', 'blue')
        board.process.wait_for(r'I heard \[blue\]', timeout=DELIVERY_TIMEOUT)
        board.wait_for_output('P6_15 0.78125')


def round_trip_with_the_samples_roscpp_nodes(ros_side, program, directory, runner=('qemu-arm',)):
    """custom_pubsub's round trip: the sample's roscpp publisher to the app,
    which sets its LEDs and publishes what it got back to the sample's
    roscpp subscriber, every field checked; returns the app's Board."""
    with RosGraph(ros_side) as graph:
        board = Board(graph, program, directory, runner=runner)
        subscriber = ros_node(graph, 'custom_subscriber',
                              sample_node(ros_side, 'custom_pubsub', 'custom_subscriber'))
        publisher = ros_node(graph, 'custom_publisher',
                             sample_node(ros_side, 'custom_pubsub', 'custom_publisher'),
                             interactive=True)
        subscriber.wait_for(r'I heard from \[Charlie Parker\]', timeout=DELIVERY_TIMEOUT)
        graph.wait_for_graph(publishers=[('/test_msg', '/custom_publisher')],
                             subscribers=[('/test_msg', '/mros_node2')])
        board.process.wait_for(r'sub connected', timeout=DELIVERY_TIMEOUT)
        # The sample publisher reads a name and LED values 0..128 (red 32 = 0.25).
        type_until_heard(publisher, 'Phil Woods 32 64 96\n', board, r'recieved name: Phil Woods')
        for line in ('P6_13 0.25', 'P6_14 0.5', 'P6_15 0.75'):
            board.wait_for_output(line)
        # The app publishes what it received: back at roscpp, every field.
        start = len(subscriber.lines())
        subscriber.wait_for(r'I heard from \[Phil Woods\]', start=start, timeout=DELIVERY_TIMEOUT)
        subscriber.wait_for(r'red value \[0\.250000\]', start=start)
        subscriber.wait_for(r'green value \[0\.500000\]', start=start)
        subscriber.wait_for(r'blue value \[0\.750000\]', start=start)
        assert board.process.alive(), board.process.output()
    return board


def test_custom_pubsub_round_trip_with_the_samples_roscpp_nodes_and_rospy(ros_side, programs,
                                                                          tmp_path):
    round_trip_with_the_samples_roscpp_nodes(ros_side, programs['custom_pubsub'], str(tmp_path))
    # rospy in a graph of its own (see the string_pubsub test).
    with RosGraph(ros_side) as graph:
        board = Board(graph, programs['custom_pubsub'], str(tmp_path))
        rospy_script(graph, 'rospy_talker', '''
            import rospy
            from custom_pubsub.msg import UserTypeTest
            rospy.init_node('rospy_talker')
            publisher = rospy.Publisher('test_msg', UserTypeTest, queue_size=1)
            message = UserTypeTest()
            message.nameVal.firstName, message.nameVal.lastName = 'Dizzy', 'Gillespie'
            message.ledVal.red, message.ledVal.green, message.ledVal.blue = 0.125, 0.375, 0.625
            rate = rospy.Rate(2)
            while not rospy.is_shutdown():
                publisher.publish(message)
                rate.sleep()
        ''')
        board.process.wait_for(r'recieved name: Dizzy Gillespie', timeout=DELIVERY_TIMEOUT)
        expected = genpy_bytes(ros_side, 'UserTypeTest(ledVal=LEDValues(0.125, 0.375, 0.625), '
                                         "nameVal=PersonName('Dizzy', 'Gillespie'))")
        raw = RawSubscriber(board.slave_uri, '/mros_msg', 'custom_pubsub/UserTypeTest',
                            raw_md5(ros_side, 'UserTypeTest'))
        try:
            assert raw.next_body() == expected
        finally:
            raw.close()


@pytest.fixture(scope='module')
def sanitized(tmp_path_factory):
    """The sample apps, built for this PC with AddressSanitizer and
    UndefinedBehaviorSanitizer by genmros mros-v1-pc --sanitize."""
    return _samples(tmp_path_factory, 'mros_v1_pc_sanitize', '--target', 'native', '--sanitize')


def test_sanitized_custom_pubsub_round_trips_with_the_samples_roscpp_nodes(ros_side, sanitized,
                                                                           tmp_path):
    board = round_trip_with_the_samples_roscpp_nodes(ros_side, sanitized['custom_pubsub'],
                                                     str(tmp_path), runner=())
    assert sanitizer_reports(board.process.output()) <= LIBRARY_REPORTS


@pytest.fixture(scope='module')
def hardened_sanitized(tmp_path_factory):
    """The sample apps as `sanitized` builds them, on the library with
    genmros' patch set (--hardened)."""
    return _samples(tmp_path_factory, 'mros_v1_pc_sanitize_hardened', '--target', 'native',
                    '--sanitize', '--hardened')


def test_hardened_sanitized_custom_pubsub_round_trips_without_a_report(ros_side,
                                                                       hardened_sanitized,
                                                                       tmp_path):
    # The patch set reads the decoder's length fields at any alignment: not
    # even the library's own report above is left.
    board = round_trip_with_the_samples_roscpp_nodes(
        ros_side, hardened_sanitized['custom_pubsub'], str(tmp_path), runner=())
    assert sanitizer_reports(board.process.output()) == set()


# A request longer than the slave's 1024-byte buffer (MROS_PACKET_MAXSIZE_
# *_REQUEST_TOPIC, _PUBLISHER_UPDATE in mros_packet_config.h), without its end.
UNENDED_REQUEST = b'POST / HTTP/1.1\r\nContent-Length: 4000\r\n\r\n<methodCall>' + b'x' * 4000


@pytest.mark.parametrize('library', ['as it is', 'hardened'])
def test_a_request_that_fills_the_slaves_buffer(ros_side, sanitized, hardened_sanitized,
                                                library, tmp_path):
    # As it is, the slave writes the NUL after the request one byte past its
    # buffer (AddressSanitizer stops the app); hardened (bounded-slave-request),
    # it refuses the request and keeps serving.
    programs = {'as it is': sanitized, 'hardened': hardened_sanitized}[library]
    with RosGraph(ros_side) as graph:
        board = _sanitized_string_pubsub(graph, programs, str(tmp_path))
        _send_and_vanish(board.slave_port, UNENDED_REQUEST)
        board.process.wait_for(r'mros_proc_receive\(\) \d+ ret=12', timeout=DELIVERY_TIMEOUT)
        if library == 'hardened':
            raw = RawSubscriber(board.slave_uri, '/mros_msg', 'std_msgs/String', STRING_MD5)
            raw.close()
            assert board.process.alive(), board.process.output()
        else:
            board.process.popen.wait(timeout=DELIVERY_TIMEOUT)
    overflow = ('mros_protocol_slave_cimpl.c', 15, 'global-buffer-overflow')
    reports = sanitizer_reports(board.process.output())
    assert reports == ({overflow} if library == 'as it is' else set()), board.process.output()


def _open_sockets(pid):
    return sum(os.readlink('/proc/%d/fd/%s' % (pid, fd)).startswith('socket:')
               for fd in os.listdir('/proc/%d/fd' % pid))


def _threads(pid):
    return len(os.listdir('/proc/%d/task' % pid))


def _send_and_vanish(port, data, linger=0.3):
    """Connects to the board, sends data, waits a little and goes away."""
    connection = socket.create_connection((BOARD_IP, port), timeout=5)
    if data:
        connection.sendall(data)
    time.sleep(linger)
    connection.close()


def _held_until(pid, expected, timeout=DELIVERY_TIMEOUT):
    """(threads, sockets) once they are back to expected, or as they are at the timeout."""
    deadline = time.monotonic() + timeout
    while True:
        held = (_threads(pid), _open_sockets(pid))
        if held == expected or time.monotonic() > deadline:
            return held
        time.sleep(0.2)


def _sanitized_string_pubsub(graph, sanitized, directory):
    board = Board(graph, sanitized['string_pubsub'], directory, runner=[])
    graph.wait_for_graph(subscribers=[('/test_string', '/mros_node2')],
                         publishers=[('/mros_msg', '/mros_node')])
    time.sleep(2)  # the library's registrations with the master are done
    return board


def test_hostile_peers_leave_the_sanitized_app_running_and_holding_nothing(ros_side, sanitized,
                                                                           tmp_path):
    with RosGraph(ros_side) as graph:
        board = _sanitized_string_pubsub(graph, sanitized, str(tmp_path))
        pid = board.process.popen.pid
        before = (_threads(pid), _open_sockets(pid))
        # Peers that connect and vanish, on the slave (XML-RPC) and TCPROS ports.
        for _ in range(20):
            _send_and_vanish(board.slave_port, b'', linger=0)
            _send_and_vanish(board.publisher_port, b'', linger=0)
        # Malformed and truncated XML-RPC calls (each shorter than the
        # library's receive buffer, which has no bound of its own).
        for request in (b'GARBAGE\r\n\r\n', b'POST / HTTP/1.1\r\n',
                        b'POST / HTTP/1.1\r\nContent-Length: 400\r\n\r\n<?xml version=',
                        b'POST / HTTP/1.1\r\nContent-Length: -7\r\n\r\n',
                        b'\x00' * 200):
            _send_and_vanish(board.slave_port, request)
        # Malformed TCPROS connection headers and frames (the library's
        # limits below pin the headers it cannot take).
        for header in (struct.pack('<I', 0xffffffff), struct.pack('<I', 300) + b'topic=',
                       b'\x01', encode_header({'topic': '/mros_msg'})[:9]):
            _send_and_vanish(board.publisher_port, header)
        # A publisher announced by publisherUpdate that sends garbage.
        with HostilePublisher(graph, '/hostile', '/test_string', 'std_msgs/String') as hostile:
            connections = serve_blue(hostile, board, {},
                                     lambda: 'I heard [blue]' in board.process.output())
            for connection in connections:
                connection.sendall(struct.pack('<I', 40) + os.urandom(40) + b'\xff' * 8)
                connection.close()
            time.sleep(2)
        assert board.process.alive(), board.process.output()
        # Once the peers are gone, the app holds what it held before, and it
        # still serves a subscriber (whose socket the library keeps until it
        # next publishes: not measured).
        assert _held_until(pid, before) == before
        raw = RawSubscriber(board.slave_uri, '/mros_msg', 'std_msgs/String', STRING_MD5)
        assert raw.header['md5sum'] == STRING_MD5
        raw.close()
    assert sanitizer_reports(board.process.output()) <= LIBRARY_REPORTS


def test_limit_a_request_the_library_cannot_answer_leaks_its_socket(ros_side, sanitized, tmp_path):
    # The slave task and the publisher task return from a failed reply
    # without closing the peer's socket (mros_protocol_slave_cimpl.c after
    # mros_proc_slave, mros_protocol_publish_cimpl.c after
    # mros_proc_pub_tcpros): each such request keeps one socket until the
    # app's file descriptors run out.
    with RosGraph(ros_side) as graph:
        board = _sanitized_string_pubsub(graph, sanitized, str(tmp_path))
        pid = board.process.popen.pid
        before = _open_sockets(pid)
        body = b'<methodCall><methodName>requestTopic</methodName></methodCall>'
        _send_and_vanish(board.slave_port, b'POST / HTTP/1.1\r\nContent-Length: %d\r\n\r\n%s'
                         % (len(body), body))
        board.process.wait_for(r'mros_xmlpacket_request_topic_req_decode\(\)',
                               timeout=DELIVERY_TIMEOUT)
        _send_and_vanish(board.publisher_port,
                         encode_header({'topic': '/mros_msg'}) + b'\xff' * 64)
        board.process.wait_for(r'encode_tcpros_topic_res\(\)', timeout=DELIVERY_TIMEOUT)
        assert _held_until(pid, (_threads(pid), before + 2))[1] == before + 2
        assert board.process.alive(), board.process.output()
    assert sanitizer_reports(board.process.output()) <= LIBRARY_REPORTS


def test_hardened_a_request_the_library_cannot_answer_leaves_no_socket(ros_side,
                                                                       hardened_sanitized,
                                                                       tmp_path):
    # The case above with the patch set (answer-every-slave-call,
    # close-unserved-subscriber-connections): the sockets are closed. (The
    # patched library serves the short header above; a topic it does not
    # know, and one it only subscribes to, are what it cannot answer.)
    with RosGraph(ros_side) as graph:
        board = _sanitized_string_pubsub(graph, hardened_sanitized, str(tmp_path))
        pid = board.process.popen.pid
        before = (_threads(pid), _open_sockets(pid))
        body = b'<methodCall><methodName>requestTopic</methodName></methodCall>'
        _send_and_vanish(board.slave_port, b'POST / HTTP/1.1\r\nContent-Length: %d\r\n\r\n%s'
                         % (len(body), body))
        board.process.wait_for(r'mros_xmlpacket_request_topic_req_decode\(\)',
                               timeout=DELIVERY_TIMEOUT)
        for topic in ('/not_published', '/test_string'):
            _send_and_vanish(board.publisher_port, encode_header({'topic': topic}))
        board.process.wait_for(r'mros_protocol_publish_run\(\) \d+ ret=', timeout=DELIVERY_TIMEOUT,
                               count=2)
        assert _held_until(pid, before) == before
        assert board.process.alive(), board.process.output()
    assert sanitizer_reports(board.process.output()) == set()


@pytest.mark.parametrize('library', ['sanitized', 'hardened_sanitized'])
def test_a_publisher_nothing_answers_for_costs_a_socket_unless_hardened(ros_side, request,
                                                                        library, tmp_path):
    # publisherUpdate names a publisher at a port nothing listens at: the
    # slave's connection for requestTopic fails. As it is, the library keeps
    # that socket, and the caller's, since the slave returns from the error
    # without closing it: two a call. Hardened (close-publisher-connections-
    # on-errors, answer-every-slave-call), none.
    with RosGraph(ros_side) as graph:
        board = _sanitized_string_pubsub(graph, request.getfixturevalue(library), str(tmp_path))
        pid = board.process.popen.pid
        before = (_threads(pid), _open_sockets(pid))
        body = xmlrpc.client.dumps(('/master', '/test_string',
                                    ['http://%s:%d/' % (PEER_IP, free_port())]),
                                   'publisherUpdate').encode()
        for _ in range(3):
            _send_and_vanish(board.slave_port, b'POST / HTTP/1.1\r\nContent-Length: %d\r\n\r\n%s'
                             % (len(body), body))
        board.process.wait_for(r'mros_proc_slave_publisher_update_do_request_topic\(\) \d+ ret=',
                               timeout=DELIVERY_TIMEOUT, count=3)
        expected = before if library == 'hardened_sanitized' else (before[0], before[1] + 6)
        assert _held_until(pid, expected) == expected
        assert board.process.alive(), board.process.output()


def test_limit_a_connection_header_without_a_topic_crashes_the_library(ros_side, sanitized,
                                                                       tmp_path):
    # A field whose length runs past the header leaves the decoder without
    # a topic; the publisher task then calls strlen on the NULL topic.
    with RosGraph(ros_side) as graph:
        board = _sanitized_string_pubsub(graph, sanitized, str(tmp_path))
        _send_and_vanish(board.publisher_port, struct.pack('<I', 8) + struct.pack('<I', 100)
                         + b'abcd')
        assert board.process.popen.wait(timeout=DELIVERY_TIMEOUT) != 0
    output = board.process.output()
    assert 'ERROR: AddressSanitizer: SEGV on unknown address 0x000000000000' in output, output
    assert sanitizer_reports(output) == {
        ('mros_topic_cimpl.c', 95, 'null pointer passed as argument 1, which is declared to never '
                                   'be null'),
        ('mros_topic_cimpl.c', 95, 'SEGV')}


def test_hardened_a_header_whose_field_runs_past_it_or_that_names_no_topic_is_refused(
        ros_side, hardened_sanitized, tmp_path):
    # The case above and a header without a topic field, with the patch set
    # (validate-subscriber-header-fields): each refused with its line, its
    # socket closed, the node serving.
    with RosGraph(ros_side) as graph:
        board = _sanitized_string_pubsub(graph, hardened_sanitized, str(tmp_path))
        pid = board.process.popen.pid
        before = (_threads(pid), _open_sockets(pid))
        _send_and_vanish(board.publisher_port, struct.pack('<I', 8) + struct.pack('<I', 100)
                         + b'abcd')
        board.process.wait_for("refused a subscriber's connection header: a field runs past "
                               "its end or has no '='", timeout=DELIVERY_TIMEOUT)
        _send_and_vanish(board.publisher_port, encode_header({'callerid': '/no_topic',
                                                              'md5sum': '*'}))
        board.process.wait_for("refused a subscriber's connection header without a topic",
                               timeout=DELIVERY_TIMEOUT)
        assert _held_until(pid, before) == before
        RawSubscriber(board.slave_uri, '/mros_msg', 'std_msgs/String', STRING_MD5).close()
        assert board.process.alive(), board.process.output()
    assert sanitizer_reports(board.process.output()) == set()


# A frame length that wraps when the library adds its 4-byte length field,
# and more bytes than the library's first memory pool holds.
WRAPPING_FRAME = struct.pack('<I', 0xfffffffe) + b'\xab' * 6000


def _blue_then(graph, board, data):
    """A publisher of /test_string whose good frames reach the app, then data."""
    with HostilePublisher(graph, '/hostile', '/test_string', 'std_msgs/String') as hostile:
        connections = serve_blue(hostile, board, {},
                                 lambda: 'I heard [blue]' in board.process.output())
        for connection in connections:
            connection.sendall(data)
        time.sleep(2)
        for connection in connections:
            connection.close()


def test_limit_a_frame_length_that_wraps_overruns_a_memory_pool(ros_side, sanitized, tmp_path):
    # mros_protocol_topic_data_receive allocates len + 4 bytes: 2, a block
    # of the first pool, and receives the frame into it.
    with RosGraph(ros_side) as graph:
        board = _sanitized_string_pubsub(graph, sanitized, str(tmp_path))
        _blue_then(graph, board, WRAPPING_FRAME)
        assert board.process.popen.wait(timeout=DELIVERY_TIMEOUT) != 0
    output = board.process.output()
    assert "to the right of global variable 'ros_outer_topic_publisher_mempool1_memory'" \
        in output, output
    assert {(place, kind) for place, _, kind in sanitizer_reports(output)} == {
        ('mros_usr_config.c', 'global-buffer-overflow')}


def test_hardened_a_frame_length_that_wraps_is_refused(ros_side, hardened_sanitized, tmp_path):
    # The pair of the test above (bounded-publisher-frames).
    with RosGraph(ros_side) as graph:
        board = _sanitized_string_pubsub(graph, hardened_sanitized, str(tmp_path))
        _blue_then(graph, board, WRAPPING_FRAME)
        board.process.wait_for(
            r'refused a frame of 4294967294 bytes from a publisher: no memory pool block holds '
            r'it \(raise the largest ROS_OUTER_TOPIC_PUBLISHER_MEMPOOL<n>_SIZE\)',
            timeout=DELIVERY_TIMEOUT)
        RawSubscriber(board.slave_uri, '/mros_msg', 'std_msgs/String', STRING_MD5).close()
        assert board.process.alive(), board.process.output()
    assert sanitizer_reports(board.process.output()) == set()


def test_the_nodes_ports_take_connections_at_its_address_only(ros_side, programs, tmp_path):
    # As on the board, whose one address 127.0.0.1 never reaches: a
    # publisherUpdate naming 127.0.0.1 and the node's slave port must not
    # make the slave call itself.
    with RosGraph(ros_side) as graph:
        board = Board(graph, programs['string_pubsub'], str(tmp_path))
        RawSubscriber(board.slave_uri, '/mros_msg', 'std_msgs/String', STRING_MD5).close()
        for port in (board.slave_port, board.publisher_port):
            with pytest.raises(ConnectionRefusedError):
                socket.create_connection((PEER_IP, port), timeout=5)


@pytest.mark.parametrize('variable, value, problem', [
    ('ROS_MASTER_URI', 'localhost:11311', 'not http://HOST:PORT'),
    ('ROS_IP', 'not-an-address', 'not an IPv4 address or a name in /etc/hosts'),
    ('MROS_V1_SLAVE_PORT', '70000', 'not a TCP port (1 to 65535)'),
])
def test_an_unusable_ros_environment_stops_the_node_with_one_line(programs, variable, value,
                                                                  problem):
    environment = dict(os.environ, ROS_MASTER_URI='http://127.0.0.1:1/', ROS_IP=BOARD_IP)
    environment[variable] = value
    result = subprocess.run(['qemu-arm', programs['string_pubsub']], env=environment,
                            capture_output=True, text=True, timeout=DELIVERY_TIMEOUT)
    assert result.returncode == 2
    assert 'mROS PC target: %s=%s: %s\n' % (variable, value, problem) in result.stderr
    assert result.stderr.count('mROS PC target:') == 1


def test_limit_with_one_publisher_connected_no_other_is_read(ros_side, programs, tmp_path):
    with RosGraph(ros_side) as graph:
        board = Board(graph, programs['string_pubsub'], str(tmp_path))
        roscpp = ros_node(graph, 'led_switch_publisher',
                          sample_node(ros_side, 'string_pubsub', 'led_switch_publisher'),
                          interactive=True)
        board.process.wait_for(r'sub connected', timeout=DELIVERY_TIMEOUT)
        type_until_heard(roscpp, 'red\n', board, r'I heard \[red\]')
        rospy_string_talker(graph, 'rospy_talker', 'blue')
        graph.wait_for_graph(publishers=[('/test_string', '/rospy_talker')])
        time.sleep(8)
        assert 'I heard [blue]' not in board.process.output()
        type_until_heard(roscpp, 'green\n', board, r'I heard \[green\]')


def ros_tool(graph, *argv, timeout=30):
    """(exit status, output) of a ROS command-line tool run on the peer address."""
    tool = graph.start(' '.join(argv), list(argv), {'ROS_IP': PEER_IP})
    try:
        tool.popen.wait(timeout=timeout)
    except subprocess.TimeoutExpired:
        tool.stop()
    return tool.popen.returncode, tool.output()


def test_ros_tools_see_the_app_and_what_the_library_refuses(ros_side, programs, tmp_path):
    with RosGraph(ros_side) as graph:
        Board(graph, programs['custom_pubsub'], str(tmp_path))
        graph.wait_for_graph(publishers=[('/mros_msg', '/mros_node')],
                             subscribers=[('/test_msg', '/mros_node2')])
        # What the master knows works.
        assert ros_tool(graph, 'rosnode', 'list') == (0, '/mros_node\n/mros_node2')
        assert ros_tool(graph, 'rostopic', 'list') == (0, '/mros_msg\n/test_msg')
        assert ros_tool(graph, 'rostopic', 'type', '/mros_msg') == (
            0, 'custom_pubsub/UserTypeTest')
        status, info = ros_tool(graph, 'rostopic', 'info', '/mros_msg')
        assert status == 0 and 'Type: custom_pubsub/UserTypeTest' in info, info
        assert ' * /mros_node (http://%s:' % BOARD_IP in info, info
        # A subscriber of the type gets the data: rostopic echo.
        status, echoed = ros_tool(graph, 'rostopic', 'echo', '-n', '1', '/mros_msg')
        assert status == 0 and 'firstName: "Charlie"' in echoed and 'lastName: "Parker"' in echoed
        # The library answers no slave call but requestTopic: rosnode info
        # and rosnode ping get nothing from the node.
        status, info = ros_tool(graph, 'rosnode', 'info', '/mros_node')
        assert status == 1 and 'ERROR: Communication with node[http://%s:' % BOARD_IP in info
        status, ping = ros_tool(graph, 'rosnode', 'ping', '-c', '1', '/mros_node')
        assert 'connection to [/mros_node] timed out' in ping, ping
        # rostopic hz and rosbag record subscribe with AnyMsg, whose short
        # connection header the library cannot answer (see the AnyMsg limit).
        status, rates = ros_tool(graph, 'rostopic', 'hz', '/mros_msg', timeout=6)
        assert 'no new messages' in rates and 'average rate' not in rates, rates
        bag = str(tmp_path / 'mros.bag')
        ros_tool(graph, 'rosbag', 'record', '--duration=4', '-O', bag, '/mros_msg')
        status, bag_info = ros_tool(graph, 'rosbag', 'info', bag)
        # A bag with no message: rosbag info lists no duration, topics or messages.
        assert status == 0 and 'version: 2.0' in bag_info and 'messages:' not in bag_info, bag_info


def _gencpp_full_text(package, type_name):
    """genmsg's full definition text of a type of the sample's ROS package,
    which gencpp and roscpp send (its message types use built-ins only)."""
    import genmsg
    import genmsg.gentools
    import genmsg.msg_loader
    context = genmsg.MsgContext.create_default()
    search_path = {package: [os.path.join(MROS_V1_ROOT, 'ros_catkin_ws', 'src', package, 'msg')]}
    spec = genmsg.msg_loader.load_msg_by_type(context, '%s/%s' % (package, type_name),
                                              search_path)
    genmsg.msg_loader.load_depends(context, spec, search_path)
    return genmsg.gentools.compute_full_text(context, spec)


@pytest.fixture(scope='module')
def hardened_custom_pubsub(tmp_path_factory):
    """custom_pubsub built with the library's patch set (--hardened)."""
    return build_sample(MROS_V1_ROOT, 'custom_pubsub',
                        str(tmp_path_factory.mktemp('hardened_custom_pubsub')), '--target', 'arm',
                        '--hardened')[0]


def test_hardened_rostopic_hz_rosbag_record_and_play(ros_side, hardened_custom_pubsub,
                                                     tmp_path):
    # The test above with the library's patch set (test_hardening.py has the
    # others): rostopic hz and rosbag record get the data, the bag the text.
    import rosbag  # the ROS environment's
    with RosGraph(ros_side) as graph:
        board = Board(graph, hardened_custom_pubsub, str(tmp_path))
        graph.wait_for_graph(publishers=[('/mros_msg', '/mros_node')],
                             subscribers=[('/test_msg', '/mros_node2')])
        _, rates = ros_tool(graph, 'rostopic', 'hz', '/mros_msg', timeout=8)
        assert re.search(r'average rate: \d+\.\d+', rates), rates
        bag = str(tmp_path / 'board.bag')
        ros_tool(graph, 'rosbag', 'record', '--duration=5', '-O', bag, '/mros_msg')
        with rosbag.Bag(bag) as recorded:
            connections = list(recorded._connections.values())
            messages = list(recorded.read_messages(raw=True))
        assert len(connections) == 1 and len(messages) >= 2, board.process.output()
        header = {key: value.decode() for key, value in connections[0].header.items()}
        assert header['type'] == 'custom_pubsub/UserTypeTest'
        assert header['message_definition'] == _gencpp_full_text('custom_pubsub', 'UserTypeTest')
        # Played back into the board, on the topic it subscribes to.
        start = len(board.process.lines())
        status, played = ros_tool(graph, 'rosbag', 'play', bag, '/mros_msg:=/test_msg')
        assert status == 0, played
        board.process.wait_for('recieved name: ', timeout=DELIVERY_TIMEOUT, start=start)
        assert board.process.alive(), board.process.output()


def test_hardened_every_slave_call_is_answered(ros_side, hardened_custom_pubsub, tmp_path):
    # The slave's limits above, with the library's patch set: publisherUpdate
    # is answered, a call the library does not implement gets a fault, and
    # rosnode ping and rosnode info work.
    with RosGraph(ros_side) as graph:
        board = Board(graph, hardened_custom_pubsub, str(tmp_path))
        graph.wait_for_graph(publishers=[('/mros_msg', '/mros_node')],
                             subscribers=[('/test_msg', '/mros_node2')])
        slave = xmlrpc.client.ServerProxy(board.slave_uri)
        assert slave.publisherUpdate('/master', '/test_msg', []) == [1, '', 0]
        assert slave.getPublications('/caller') == [
            -1, 'not implemented by the mROS v1 library', 0]
        assert slave.getPid('/caller') == [1, '', 1]
        status, ping = ros_tool(graph, 'rosnode', 'ping', '-c', '1', '/mros_node')
        assert status == 0 and 'xmlrpc reply from http://%s:' % BOARD_IP in ping, ping
        status, info = ros_tool(graph, 'rosnode', 'info', '/mros_node')
        assert status == 0 and 'Publications:' in info and '/mros_msg' in info, info
        assert board.process.alive(), board.process.output()


def test_limit_no_message_definition_and_no_data_for_anymsg(ros_side, programs, tmp_path):
    with RosGraph(ros_side) as graph:
        board = Board(graph, programs['custom_pubsub'], str(tmp_path))
        board.process.wait_for(r'pub accepted|mROS Main task finish', timeout=DELIVERY_TIMEOUT)
        md5 = raw_md5(ros_side, 'UserTypeTest')
        raw = RawSubscriber(board.slave_uri, '/mros_msg', 'custom_pubsub/UserTypeTest', md5)
        try:
            assert raw.header['type'] == 'custom_pubsub/UserTypeTest'
            assert raw.header['md5sum'] == md5
            assert 'message_definition' not in raw.header
            raw.next_body()
        finally:
            raw.close()
        anymsg = rospy_script(graph, 'anymsg_listener', '''
            import rospy
            rospy.init_node('anymsg_listener')
            rospy.Subscriber('mros_msg', rospy.AnyMsg,
                             lambda m: print('anymsg got %d bytes' % len(m._buff), flush=True))
            rospy.spin()
        ''')
        graph.wait_for_graph(subscribers=[('/mros_msg', '/anymsg_listener')])
        time.sleep(5)
        assert 'anymsg got' not in anymsg.output()


def test_limit_publisher_update_gets_no_response(ros_side, programs, tmp_path):
    with RosGraph(ros_side) as graph:
        board = Board(graph, programs['string_pubsub'], str(tmp_path))
        graph.wait_for_graph(subscribers=[('/test_string', '/mros_node2')])
        slave = xmlrpc.client.ServerProxy(board.slave_uri)
        # The connection closes without a response (the library acts on the
        # call, connecting to the publishers it names); the master's XML-RPC
        # client retries.
        with pytest.raises(http.client.RemoteDisconnected):
            slave.publisherUpdate('/master', '/test_string', [])
        assert board.process.alive()


# ---- bad input from outside: the PC target keeps running ----

def serve_blue(hostile, board, extra_header, done):
    """Accepts the library's connections to hostile (it may connect twice,
    see the publisherUpdate limit), answers each with a TCPROS header (plus
    extra_header fields) and sends good frames ("blue") on all of them every
    half second until done(); returns the connections."""
    connections = []
    deadline = time.monotonic() + DELIVERY_TIMEOUT
    while not done():
        assert time.monotonic() < deadline, board.process.output()
        try:
            connection, header = hostile.accept(timeout=0.5)
            assert header['md5sum'] == STRING_MD5
            connection.sendall(encode_header(dict({
                'callerid': '/hostile', 'md5sum': STRING_MD5, 'type': 'std_msgs/String',
                'topic': '/test_string'}, **extra_header)))
            connections.append(connection)
        except socket.timeout:
            pass
        for connection in connections:
            try:
                connection.sendall(struct.pack('<I', 8) + b'\x04\x00\x00\x00blue')
            except OSError:
                pass
    return connections


@pytest.mark.parametrize('frame', [
    pytest.param(struct.pack('<I', 100) + b'\x04\x00\x00\x00red', id='cut-short'),
    pytest.param(struct.pack('<I', 0x7fffffff) + b'\x04\x00\x00\x00red', id='length-beyond'),
    pytest.param(b'\x05\x00', id='closed-in-the-length'),
])
def test_a_frame_cut_short_or_oversized_leaves_the_app_running(ros_side, programs, tmp_path,
                                                               frame):
    with RosGraph(ros_side) as graph:
        board = Board(graph, programs['string_pubsub'], str(tmp_path))
        graph.wait_for_graph(subscribers=[('/test_string', '/mros_node2')])
        with HostilePublisher(graph, '/hostile', '/test_string', 'std_msgs/String') as hostile:
            connections = serve_blue(hostile, board, {},
                                     lambda: 'I heard [blue]' in board.process.output())
            for connection in connections:
                connection.sendall(frame)
                connection.close()
            time.sleep(3)
        assert board.process.alive(), board.process.output()
        assert 'I heard [red]' not in board.process.output()
        # The app still serves: a subscriber gets its publisher's header.
        raw = RawSubscriber(board.slave_uri, '/mros_msg', 'std_msgs/String', STRING_MD5)
        raw.close()
        assert raw.header['md5sum'] == STRING_MD5


def test_a_master_that_goes_away_and_comes_back(ros_side, programs, tmp_path):
    with RosGraph(ros_side) as graph:
        board = Board(graph, programs['string_pubsub'], str(tmp_path))
        graph.wait_for_graph(subscribers=[('/test_string', '/mros_node2')],
                             publishers=[('/mros_msg', '/mros_node')])
        graph.master.stop()
        time.sleep(3)
        assert board.process.alive(), board.process.output()
        graph.master = graph.start('rosmaster again', ['rosmaster', '--core', '-p',
                                                       str(graph.port)])
        graph._wait_for_master()
        time.sleep(5)
        assert board.process.alive(), board.process.output()
        # What the library does: it registers once, at start, and does not
        # register again with a master that restarted.
        publishers, subscribers = graph.system_state()
        assert '/mros_node' not in publishers.get('/mros_msg', set())
        assert '/mros_node2' not in subscribers.get('/test_string', set())


def test_limit_a_long_header_from_a_publisher_overruns_the_library(ros_side, programs, tmp_path):
    # The library reads a publisher's connection-header reply into a
    # 512-byte buffer without a bound: 5000 bytes overwrite its own state,
    # and it crashes (in mros_topic_connector_get_obj, on a pointer made of
    # the header's bytes). The library's crash, not the PC target's.
    with RosGraph(ros_side) as graph:
        board = Board(graph, programs['string_pubsub'], str(tmp_path))
        graph.wait_for_graph(subscribers=[('/test_string', '/mros_node2')])
        with HostilePublisher(graph, '/hostile', '/test_string', 'std_msgs/String') as hostile:
            serve_blue(hostile, board, {'message_definition': 'x' * 5000},
                       lambda: not board.process.alive())
        board.process.popen.wait(timeout=DELIVERY_TIMEOUT)
        assert board.process.popen.returncode == -11, board.process.output()
        assert 'I heard [blue]' not in board.process.output()
