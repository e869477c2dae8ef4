"""What peers can make an mROS POSIX node hold (issue 10): connections that
trickle bytes (slowloris), lengths claimed but never sent, and fake
publishers announced through publisherUpdate. The node's threads and
resident memory stay bounded, and a well-behaved peer is still served."""

import socket
import struct
import time
import xmlrpc.client

from ros_processes import free_port
from tcpros_peer import HostilePublisher, encode_header
from test_posix_connections import mros_listener

PERSON = r'name:Charlie Parker'


def _status(process):
    """(threads, resident kB) of a running node, from /proc."""
    fields = {}
    with open('/proc/%d/status' % process.popen.pid) as stream:
        for line in stream:
            key, _, value = line.partition(':')
            fields[key] = value.split()
    return int(fields['Threads'][0]), int(fields['VmRSS'][0])


def _slave_uri(graph, node):
    code, message, uri = graph.master_proxy().lookupNode('/test', node)
    assert code == 1, message
    return uri


def _host_port(uri):
    host, port = uri[len('http://'):].rstrip('/').split(':')
    return host, int(port)


def _open(address, count):
    connections = []
    for _ in range(count):
        try:
            connections.append(socket.create_connection(address, timeout=5))
        except OSError:
            break
    return connections


def _closed(connection):
    connection.settimeout(0.2)
    try:
        return connection.recv(1) == b''
    except socket.timeout:
        return False
    except OSError:
        return True


def _talker(graph, workspace):
    graph.start('rospy talker', workspace.rospy('personal_data_talker.py'))


def test_slowloris_is_cut_off_and_bounded(ros_graph, ros_workspace, mros_firmware):
    listener = mros_listener(ros_graph, mros_firmware, 'mros_node2')
    threads_before, _ = _status(listener)
    address = _host_port(_slave_uri(ros_graph, '/mros_node2'))
    # 200 connections, each sending one byte of a request every half second:
    # each byte used to re-arm a 5 s timeout, so they lived for ever.
    connections = _open(address, 200)
    assert len(connections) >= 100
    started = time.monotonic()
    peak_threads = 0
    while time.monotonic() - started < 8:
        for connection in connections:
            try:
                connection.send(b'P')
            except OSError:
                pass
        peak_threads = max(peak_threads, _status(listener)[0])
        time.sleep(0.5)
    closed = sum(_closed(connection) for connection in connections)
    for connection in connections:
        connection.close()
    # At most 32 slave calls are served at once, each for at most 5 s.
    assert peak_threads <= threads_before + 32 + 2, (threads_before, peak_threads)
    assert closed == len(connections), '%d of %d trickling connections still open' % (
        len(connections) - closed, len(connections))
    _talker(ros_graph, ros_workspace)
    listener.wait_for(PERSON, timeout=20)


def test_claimed_lengths_cost_what_arrives(ros_graph, ros_workspace, mros_firmware):
    listener = mros_listener(ros_graph, mros_firmware, 'mros_node2')
    _, rss_before = _status(listener)
    address = _host_port(_slave_uri(ros_graph, '/mros_node2'))
    # 30 requests announcing 4 MB bodies that never come (120 MB if believed).
    connections = _open(address, 30)
    for connection in connections:
        connection.sendall(b'POST /RPC2 HTTP/1.1\r\nContent-Length: 4000000\r\n\r\n<?xml')
    time.sleep(1.0)
    _, rss_claimed = _status(listener)
    for connection in connections:
        connection.close()

    # A publisher that announces a 60 MB frame and sends 10 bytes of it.
    with HostilePublisher(ros_graph, '/raw_publisher', '/test_msg', 'mros_test/PersonalData') as publisher:
        connection, request = publisher.accept()
        connection.sendall(encode_header({'callerid': '/raw_publisher', 'type': request['type'],
                                          'md5sum': request['md5sum'], 'latching': '0'}))
        connection.sendall(struct.pack('<I', 60 * 1024 * 1024) + b'0123456789')
        time.sleep(1.0)
        _, rss_frame = _status(listener)
        connection.close()
    assert rss_claimed - rss_before < 20 * 1024, (rss_before, rss_claimed)
    assert rss_frame - rss_before < 20 * 1024, (rss_before, rss_frame)
    _talker(ros_graph, ros_workspace)
    listener.wait_for(PERSON, timeout=20)


def test_fake_publishers_are_bounded(ros_graph, ros_workspace, mros_firmware):
    listener = mros_listener(ros_graph, mros_firmware, 'mros_node2')
    threads_before, rss_before = _status(listener)
    slave = xmlrpc.client.ServerProxy(_slave_uri(ros_graph, '/mros_node2'))
    # Anyone may call publisherUpdate: 200 publishers nobody listens at.
    unreachable = ['http://127.0.0.1:%d/' % free_port() for _ in range(200)]
    code, _, _ = slave.publisherUpdate('/intruder', '/test_msg', unreachable)
    assert code == 1
    time.sleep(2.0)
    threads, rss = _status(listener)
    # At most 32 publishers per topic are connected to, one thread each.
    assert threads <= threads_before + 32 + 2, (threads_before, threads)
    assert rss - rss_before < 40 * 1024, (rss_before, rss)
    listener.wait_for(r'/test_msg: 200 publishers listed; connecting to the first 32')
    # The master's own list comes back with the real publisher.
    _talker(ros_graph, ros_workspace)
    listener.wait_for(PERSON, timeout=30)
    assert listener.alive()


def test_too_many_subscribers_are_refused_and_others_served(ros_graph, ros_workspace, mros_firmware):
    talker = ros_graph.start('mROS talker', mros_firmware.node('mros_personal_talker'))
    talker.wait_for(r'published Phil Woods', timeout=10)
    threads_before, _ = _status(talker)
    code, message, uri = ros_graph.master_proxy().lookupNode('/test', '/mros_node')
    assert code == 1, message
    code, _, protocol = xmlrpc.client.ServerProxy(uri).requestTopic('/test', '/mros_str', [['TCPROS']])
    assert code == 1
    address = (protocol[1], protocol[2])
    # Idle connections that never send their header: refused beyond the cap
    # of 64, cut off after the 5 s handshake deadline.
    idle = _open(address, 100)
    time.sleep(1.0)
    threads, _ = _status(talker)
    assert threads <= threads_before + 64 + 2, (threads_before, threads)
    refused = sum(_closed(connection) for connection in idle)
    assert refused >= len(idle) - 64
    time.sleep(5.5)
    assert all(_closed(connection) for connection in idle)
    for connection in idle:
        connection.close()
    listener = ros_graph.start('rospy listener', ros_workspace.rospy('personal_data_listener.py',
                                                                    'test_msg:=/mros_str'))
    listener.wait_for(r'I heard from mROS: Phil Woods', timeout=20)
