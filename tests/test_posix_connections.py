"""Connections of mROS POSIX nodes in a real ROS graph: several publishers
and subscribers on one topic, late joiners, a publisher that dies mid-stream
and comes back, and peers that send malformed headers or frames (the node
closes that connection and keeps working)."""

import socket
import struct
import xmlrpc.client

import pytest

from tcpros_peer import (HostilePublisher, closed_by_peer, encode_header, frame, personal_data,
                         read_header, receive_exactly)

PERSON = r'I heard from mROS: Phil Woods age:83 score:(\d+)'


def bus_info(graph, node):
    code, message, uri = graph.master_proxy().lookupNode('/test', node)
    assert code == 1, message
    return xmlrpc.client.ServerProxy(uri).getBusInfo('/test')[2]


def mros_listener(graph, firmware, name, topic='/test_msg'):
    listener = graph.start(name, firmware.node('mros_personal_listener', '__name:=' + name,
                                               'test_msg:=' + topic))
    graph.wait_for_graph(subscribers=[(topic, '/' + name)])
    return listener


def heard_names(listener, start=0):
    return {line.split('name:')[1] for line in listener.lines()[start:] if 'name:' in line}


def test_several_publishers_and_subscribers_on_one_topic(ros_graph, ros_workspace, mros_firmware):
    listeners = [mros_listener(ros_graph, mros_firmware, name, '/mros_str')
                 for name in ('mros_listener_a', 'mros_listener_b')]
    roscpp_listener = ros_graph.start('roscpp listener',
                                      ros_workspace.roscpp('personal_data_listener'))
    talkers = [ros_graph.start(name, mros_firmware.node('mros_personal_talker', '__name:=' + name))
               for name in ('mros_talker_a', 'mros_talker_b')]
    ros_graph.start('rospy talker', ros_workspace.rospy('personal_data_talker.py',
                                                        'test_msg:=/mros_str'))
    for listener in listeners:
        listener.wait_for(r'name:Charlie Parker', timeout=20)
        listener.wait_for(r'name:Phil Woods', timeout=20)
        inbound = sorted(c[1] for c in bus_info(ros_graph, '/' + listener.name.split()[0])
                         if c[2] == 'i' and c[4] == '/mros_str')
        assert len(inbound) == 3, inbound
    roscpp_listener.wait_for(r'I heard from mROS: Charlie Parker', timeout=20)
    roscpp_listener.wait_for(PERSON, timeout=20)
    for talker in talkers:
        talker.wait_for(r'subscriber /ros_personal_listener connected to /mros_str')
        outbound = sorted(c[1] for c in bus_info(ros_graph, '/' + talker.name) if c[2] == 'o')
        assert outbound == ['/mros_listener_a', '/mros_listener_b', '/ros_personal_listener']


def test_late_subscribers_get_the_stream(ros_graph, ros_workspace, mros_firmware):
    talker = ros_graph.start('mROS talker', mros_firmware.node('mros_personal_talker'))
    talker.wait_for(r'published Phil Woods age:83 score:100003', timeout=10)
    late = ros_graph.start('late rospy listener', ros_workspace.rospy('personal_data_listener.py'))
    scores = [int(m.group(1)) for m in late.wait_for(PERSON, timeout=20, count=3)]
    assert scores[0] > 100003 and scores == list(range(scores[0], scores[0] + 3))

    ros_talker = ros_graph.start('roscpp talker', ros_workspace.roscpp('personal_data_talker'))
    ros_talker.wait_for(r'published Charlie Parker age:32 score:100103', timeout=10)
    late_mros = mros_listener(ros_graph, mros_firmware, 'mros_late_listener')
    late_mros.wait_for(r'name:Charlie Parker', timeout=20, count=2)


def test_publisher_that_dies_is_reconnected_when_it_comes_back(ros_graph, ros_workspace,
                                                               mros_firmware):
    listener = mros_listener(ros_graph, mros_firmware, 'mros_node2')
    talker = ros_graph.start('roscpp talker', ros_workspace.roscpp('personal_data_talker'))
    listener.wait_for(r'score:100102', timeout=20)
    talker.kill()  # SIGKILL: no unregistration, the connection just drops
    listener.wait_for(r'/test_msg: publisher http://127\.0\.0\.1:\d+/ disconnected', timeout=10)
    assert listener.alive()
    restart = len(listener.lines())
    ros_graph.start('roscpp talker again', ros_workspace.roscpp('personal_data_talker'))
    listener.wait_for(r'score:100102', timeout=20, start=restart)
    assert listener.alive()


MALFORMED_FRAMES = {
    # A string length of 1000 in a 10-byte body.
    'truncated body': (frame(struct.pack('<I', 1000) + b'abcdef'),
                       r'malformed mros_test/PersonalData message of 10 bytes from publisher '
                       r'http://127\.0\.0\.1:\d+/; closing the connection'),
    'oversized length': (struct.pack('<I', 0xFFFFFFF0),
                         r'malformed frame from publisher http://127\.0\.0\.1:\d+/: message length '
                         r'4294967280 exceeds the limit of \d+ bytes; closing the connection'),
    'trailing bytes': (frame(personal_data('Eve', 'Raw', 40, 8) + b'\x00'),
                       r'malformed mros_test/PersonalData message of 21 bytes'),
}


@pytest.mark.parametrize('case', sorted(MALFORMED_FRAMES))
def test_malformed_frame_closes_the_connection_and_the_node_survives(
        case, ros_graph, ros_workspace, mros_firmware):
    listener = mros_listener(ros_graph, mros_firmware, 'mros_node2')
    payload, logged = MALFORMED_FRAMES[case]
    with HostilePublisher(ros_graph, '/raw_publisher', '/test_msg',
                          'mros_test/PersonalData') as publisher:
        connection, request = publisher.accept()
        assert request['callerid'] == '/mros_node2' and request['topic'] == '/test_msg'
        connection.sendall(encode_header({'callerid': '/raw_publisher', 'type': request['type'],
                                          'md5sum': request['md5sum'], 'latching': '0'}))
        connection.sendall(frame(personal_data('Eve', 'Raw', 40, 7)))  # a good one first
        listener.wait_for(r'name:Eve Raw')
        connection.sendall(payload)
        listener.wait_for(logged)
        assert closed_by_peer(connection)
        connection.close()
    ros_graph.start('rospy talker', ros_workspace.rospy('personal_data_talker.py'))
    listener.wait_for(r'name:Charlie Parker', timeout=20)
    assert listener.alive()


def test_publisher_header_with_another_md5_or_no_fields_is_refused(ros_graph, mros_firmware):
    listener = mros_listener(ros_graph, mros_firmware, 'mros_node2')
    replies = [
        (encode_header({'callerid': '/raw_publisher', 'type': 'mros_test/PersonalData',
                        'md5sum': '0' * 32}),
         r'/test_msg: publisher http://127\.0\.0\.1:\d+/ sends \[mros_test/PersonalData/0{32}\], '
         r'but we subscribed with \[mros_test/PersonalData/[0-9a-f]{32}\]\. Dropping connection\.'),
        (struct.pack('<II', 8, 4) + b'abcd',
         r"bad connection header from publisher http://127\.0\.0\.1:\d+/: header field without '='"),
    ]
    for index, (reply, logged) in enumerate(replies):
        with HostilePublisher(ros_graph, '/raw_publisher_%d' % index, '/test_msg',
                              'mros_test/PersonalData') as publisher:
            connection, _ = publisher.accept()
            connection.sendall(reply)
            listener.wait_for(logged)
            assert closed_by_peer(connection)
            connection.close()
    assert listener.alive() and 'I heard a msg' not in listener.output()


def tcpros_address(graph, node, topic):
    code, message, uri = graph.master_proxy().lookupNode('/test', node)
    assert code == 1, message
    _, _, (_, host, port) = xmlrpc.client.ServerProxy(uri).requestTopic('/test', topic,
                                                                        [['TCPROS']])
    return host, port


def test_subscriber_headers_are_checked(ros_graph, ros_workspace, mros_firmware):
    talker = ros_graph.start('mROS talker', mros_firmware.node('mros_personal_talker'))
    ros_graph.wait_for_graph(publishers=[('/mros_str', '/mros_node')])
    address = tcpros_address(ros_graph, '/mros_node', '/mros_str')
    good = {'callerid': '/raw_subscriber', 'topic': '/mros_str', 'type': 'mros_test/PersonalData'}

    def connect():
        return socket.create_connection(address, timeout=10)

    with connect() as connection:  # a header length of 4 GiB
        connection.sendall(struct.pack('<I', 0xFFFFFFFF))
        talker.wait_for(r'dropped a TCPROS connection: header of 4294967295 bytes exceeds the '
                        r'limit of 262144')
        assert closed_by_peer(connection)
    with connect() as connection:  # a field longer than the header
        connection.sendall(struct.pack('<II', 8, 100) + b'topic')
        talker.wait_for(r'dropped a TCPROS connection: header field runs past the end')
        assert closed_by_peer(connection)
    with connect() as connection:  # the right type name with another MD5 sum
        connection.sendall(encode_header(dict(good, md5sum='0' * 32)))
        reply = read_header(connection)
        assert reply['error'].startswith(
            'Client [/raw_subscriber] wants topic /mros_str to have datatype/md5sum '
            '[mros_test/PersonalData/%s], but our version has [mros_test/PersonalData/' % ('0' * 32))
        talker.wait_for(r'Client \[/raw_subscriber\] wants topic /mros_str')
        assert closed_by_peer(connection)
    with connect() as connection:  # a correct subscriber gets frames
        connection.sendall(encode_header(dict(good, md5sum='*')))
        reply = read_header(connection)
        assert reply['type'] == 'mros_test/PersonalData' and reply['callerid'] == '/mros_node'
        assert 'string first_name' in reply['message_definition']
        (length,) = struct.unpack('<I', receive_exactly(connection, 4))
        body = receive_exactly(connection, length)
        assert body[:-6] == personal_data('Phil', 'Woods', 83, 0)[:-6]
        assert struct.unpack('<Hi', body[-6:])[0] == 83
    listener = ros_graph.start('roscpp listener', ros_workspace.roscpp('personal_data_listener'))
    listener.wait_for(PERSON, timeout=20, count=2)
    assert talker.alive()
