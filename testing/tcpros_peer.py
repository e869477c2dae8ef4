# SPDX-License-Identifier: BSD-3-Clause
"""A raw TCPROS peer for the robustness tests and the network fuzzer: it
speaks the wire protocol byte by byte, so a test can send what real ROS
nodes never send (truncated bodies, oversized lengths, broken headers, a
foreign MD5 sum) to an mROS node and check that the node closes that
connection and keeps working.
HostilePublisher registers at the real master like any ROS publisher;
RawSubscriber asks a node's slave API for a topic and keeps the bytes. Neither
sends a message_definition (a subscriber need not, and the mROS v1 library
cannot take a long connection header)."""

import socket
import struct
import threading
import time
import xmlrpc.client
import xmlrpc.server


def encode_header(fields):
    body = b''
    for key, value in fields.items():
        field = ('%s=%s' % (key, value)).encode()
        body += struct.pack('<I', len(field)) + field
    return struct.pack('<I', len(body)) + body


def receive_exactly(connection, size):
    data = b''
    while len(data) < size:
        chunk = connection.recv(size - len(data))
        if not chunk:
            raise EOFError('connection closed after %d of %d bytes' % (len(data), size))
        data += chunk
    return data


def read_header(connection):
    (length,) = struct.unpack('<I', receive_exactly(connection, 4))
    body = receive_exactly(connection, length)
    fields, position = {}, 0
    while position < length:
        (size,) = struct.unpack('<I', body[position:position + 4])
        key, _, value = body[position + 4:position + 4 + size].decode().partition('=')
        fields[key] = value
        position += 4 + size
    return fields


def frame(body):
    return struct.pack('<I', len(body)) + body


def personal_data(first_name, last_name, age, score):
    """mros_test/PersonalData on the wire, written by hand."""
    def string(text):
        return struct.pack('<I', len(text.encode())) + text.encode()
    return string(first_name) + string(last_name) + struct.pack('<Hi', age, score)


def closed_by_peer(connection, timeout=5.0):
    """True if the peer closes the connection (reads reach end of stream)."""
    connection.settimeout(timeout)
    try:
        while connection.recv(4096):
            pass
        return True
    except (ConnectionResetError, BrokenPipeError):
        return True
    except socket.timeout:
        return False


class HostilePublisher:
    """A publisher registered at the master whose TCPROS side the test drives:
    accept() returns the connection of a subscriber and the header it sent."""

    def __init__(self, graph, node_name, topic, datatype):
        self.graph, self.node_name, self.topic, self.datatype = graph, node_name, topic, datatype
        self.listener = socket.create_server(('127.0.0.1', 0))
        tcpros_port = self.listener.getsockname()[1]
        self.slave = xmlrpc.server.SimpleXMLRPCServer(('127.0.0.1', 0), logRequests=False,
                                                      allow_none=True)
        self.slave.register_function(
            lambda caller, topic, protocols: [1, 'ready', ['TCPROS', '127.0.0.1', tcpros_port]],
            'requestTopic')
        self.slave.register_function(lambda *args: [1, '', 0], 'publisherUpdate')
        self.uri = 'http://127.0.0.1:%d/' % self.slave.server_address[1]
        self.thread = threading.Thread(target=self.slave.serve_forever, daemon=True)

    def __enter__(self):
        self.thread.start()
        code, message, _ = self.graph.master_proxy().registerPublisher(
            self.node_name, self.topic, self.datatype, self.uri)
        assert code == 1, message
        return self

    def __exit__(self, *exc_info):
        self.graph.master_proxy().unregisterPublisher(self.node_name, self.topic, self.uri)
        self.slave.shutdown()
        self.slave.server_close()
        self.listener.close()

    def accept(self, timeout=10.0):
        self.listener.settimeout(timeout)
        connection, _ = self.listener.accept()
        connection.settimeout(timeout)
        return connection, read_header(connection)


class TimedTransport(xmlrpc.client.Transport):
    """XML-RPC over HTTP that gives up after timeout seconds: a slave whose
    socket still accepts but whose task no longer serves must not hang a test."""

    def __init__(self, timeout):
        super().__init__()
        self._timeout = timeout

    def make_connection(self, host):
        connection = super().make_connection(host)
        connection.timeout = self._timeout
        return connection


class RawSubscriber:
    """A TCPROS subscriber that keeps the bytes: asks the publishing node's
    slave (slave_uri) for the topic until it answers within timeout,
    connects, sends its header (with extra_fields) and reads the reply
    header and whole frames."""

    def __init__(self, slave_uri, topic, message_type, md5sum, timeout=30.0, extra_fields=None):
        deadline = time.monotonic() + timeout
        while True:
            try:
                slave = xmlrpc.client.ServerProxy(
                    slave_uri, transport=TimedTransport(max(deadline - time.monotonic(), 0.5)))
                code, message, protocol = slave.requestTopic('/raw_subscriber', topic,
                                                             [['TCPROS']])
                if code == 1:
                    break
            except OSError:
                message = 'slave not up'
            assert time.monotonic() < deadline, 'requestTopic %s: %s' % (topic, message)
            time.sleep(0.5)
        self.connection = socket.create_connection((protocol[1], protocol[2]), timeout=timeout)
        self.connection.sendall(encode_header(dict({
            'callerid': '/raw_subscriber', 'topic': topic, 'type': message_type,
            'md5sum': md5sum, 'tcp_nodelay': '1'}, **(extra_fields or {}))))
        self.header = read_header(self.connection)

    def next_body(self):
        (length,) = struct.unpack('<I', receive_exactly(self.connection, 4))
        return receive_exactly(self.connection, length)

    def close(self):
        self.connection.close()
