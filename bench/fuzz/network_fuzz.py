#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""Fuzz the mROS v1 library's network side on the PC target, loopback only.

    /usr/bin/python3 bench/fuzz/network_fuzz.py [--seconds 600] [--inputs N] [--seed S]
                                                [--as-it-is] [--build-dir DIR]

builds bench/fuzz/relay_app (a node relaying std_msgs/String,
sensor_msgs/JointState, geometry_msgs/PoseStamped, sensor_msgs/Imu and
geometry_msgs/Twist from src/<Type> to back/<Type>) with genmros mros-v1-pc
--target native --sanitize --hardened (--as-it-is: the library unpatched),
starts it beside a real rosmaster and sends it, in turn:

- mutated XML-RPC calls to its slave port (every slave method, valid and
  broken HTTP, lying Content-Length, long and binary bodies);
- mutated TCPROS connection headers to its publisher port, as subscribers;
- a hostile publisher: a publisherUpdate tells the node to connect to a
  fresh port of the fuzzer's, whose requestTopic answer, connection header
  and frames (lying lengths inside the message, truncated and long frames)
  are mutated.

Subscribers on every back/<Type> drain what the node relays meanwhile. Every
few seconds the fuzzer asks the slave requestTopic and counts the node's threads,
sockets and resident memory. The peers are raw sockets: they send no
message_definition, so the app is built without the fit check (ROS nodes'
headers would not fit custom_pubsub's 512-byte buffers; the hardened library
refuses them).

At the end (after --seconds, or --inputs inputs) the fuzzer waits until the
node has read what its hostile publishers left, relays genpy's serialization
of samples of each type through the node and compares the bytes, then stops
the node. It prints a table and exits non-zero if the node died or stopped
answering, a sanitizer reported anything, the threads grew, the node held
more sockets at the end than at the start, the memory grew past
MEMORY_GROWTH_LIMIT after the first quarter, or a type no longer came back
byte-exact; the node's log (with gdb's stacks and ss's sockets where it
failed) and the last inputs are kept in the build directory. The test suite
runs it for 45 s; the figures in bench/README.md are of a 10-minute run.
"""

import argparse
import base64
import collections
import io
import json
import os
import random
import re
import select
import selectors
import shutil
import socket
import struct
import subprocess
import sys
import tempfile
import threading
import time
import xmlrpc.client

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, REPO)  # this checkout's genmros, which also builds the app

from testing.ros_graph import (  # noqa: E402
    BOARD_IP, PEER_IP, Board, RosGraph)
from testing.tcpros_peer import (  # noqa: E402
    HostilePublisher, RawSubscriber, TimedTransport, encode_header, frame, read_header)

RELAY_APP = os.path.join(HERE, 'relay_app')
# The relay's types, by the name of their topics.
TYPES = {'String': 'std_msgs/String', 'JointState': 'sensor_msgs/JointState',
         'PoseStamped': 'geometry_msgs/PoseStamped', 'Imu': 'sensor_msgs/Imu',
         'Twist': 'geometry_msgs/Twist'}
SLAVE_METHODS = ['requestTopic', 'getPid', 'getBusInfo', 'getBusStats', 'getMasterUri',
                 'getSubscriptions', 'getPublications', 'publisherUpdate', 'paramUpdate',
                 'shutdown', 'noSuchMethod']
# ASan's quarantine holds freed memory up to its size before reusing it: a
# small one lets a leak show in the resident memory within minutes.
SANITIZER_OPTIONS = {'ASAN_OPTIONS': 'quarantine_size_mb=8:detect_leaks=0',
                     'UBSAN_OPTIONS': 'print_stacktrace=1'}
MEMORY_GROWTH_LIMIT = 16 * 1024 * 1024
HEALTH_PERIOD = 5.0  # seconds between requestTopic, thread and memory readings
ANSWER_TIMEOUT = 10.0  # for the node's slave to answer requestTopic
PEER_TIMEOUT = 0.2  # how long a fuzzing peer waits for the node
RELAY_TIMEOUT = 10  # for each sample to come back in the check afterwards
# The library reads one frame of each publisher connection per cycle
# (MROS_LOOP_RATE, 100 ms): a dead publisher's backlog keeps the topic's
# one-message queue busy until it is read. A hostile publisher sends at
# most this much, header and frames, about what a small lwIP TCP window
# holds on a board; the check waits until the node has read it all.
HOSTILE_STREAM_LIMIT = 4096
SETTLE_TIMEOUT = 120
TCP_LISTEN = '0A'  # the state column of /proc/net/tcp
RESEND_PERIOD = 0.3
# The library as it is writes its reply header into the buffer the
# subscriber's header came in, sized to that header: a raw subscriber's must
# be as long as the reply. TCPROS ignores this field.
REPLY_ROOM = {'padding': '.' * 200}
SANITIZER_REPORT = re.compile(r'runtime error:|ERROR: AddressSanitizer|ERROR: LeakSanitizer')
INTERESTING_WORDS = [0, 1, 3, 4, 0x7f, 0x80, 0xff, 0x100, 0x1ff, 0x200, 0x3ff, 0x400, 0xffff,
                     0x10000, 0x7fffffff, 0x80000000, 0xfffffffe, 0xffffffff]


# --- the node --------------------------------------------------------------

def build(mros_root, build_root, hardened):
    """The relay app built with the sanitizers; returns the program."""
    app = shutil.copytree(RELAY_APP, os.path.join(build_root, 'relay_app'), dirs_exist_ok=True)
    for sample_file in ('mros_config', 'app.h'):  # custom_pubsub's configuration and tasks
        if not os.path.lexists(os.path.join(app, sample_file)):
            os.symlink(os.path.join(mros_root, 'mros_ws', 'custom_pubsub', sample_file),
                       os.path.join(app, sample_file))
    output = os.path.join(build_root, 'build-hardened' if hardened else 'build-as-it-is')
    command = [sys.executable, '-m', 'colcon_mros', 'mros-v1-pc', app, '-o', output,
               '--mros-v1-root', mros_root, '--target', 'native', '--sanitize', '--no-fit-check',
               '--build-only']
    command += ['--hardened'] if hardened else []
    for datatype in TYPES.values():
        command += ['--type', datatype]
    result = subprocess.run(command, cwd=REPO, capture_output=True, text=True)
    if result.returncode != 0:
        raise SystemExit('genmros mros-v1-pc failed:\n' + result.stdout[-3000:]
                         + result.stderr[-3000:])
    return os.path.join(output, 'fuzz_relay')


def samples():
    """{topic name: (type, MD5 sum, [genpy's bytes of each sample])}."""
    from geometry_msgs.msg import PoseStamped, Twist
    from sensor_msgs.msg import Imu, JointState
    from std_msgs.msg import String
    messages = {
        'String': [String(), String(data='mROS'), String(data='x' * 300)],
        'JointState': [JointState(), JointState(name=['shoulder', 'elbow'], position=[0.5, -1.25],
                                                velocity=[2.0], effort=[])],
        'PoseStamped': [PoseStamped()],
        'Imu': [Imu()],
        'Twist': [Twist()],
    }
    pose = messages['PoseStamped'][0]
    pose.header.seq, pose.header.stamp.secs, pose.header.frame_id = 7, 1700000000, 'map'
    pose.pose.position.x, pose.pose.orientation.w = 1.5, 1.0
    messages['JointState'][1].header.frame_id = 'arm'
    messages['Imu'][0].orientation_covariance = [float(i) for i in range(9)]
    messages['Imu'][0].header.frame_id = 'imu_link'
    messages['Twist'][0].linear.x, messages['Twist'][0].angular.z = 0.25, -3.5
    result = {}
    for name, instances in messages.items():
        wire = []
        for message in instances:
            buffer = io.BytesIO()
            message.serialize(buffer)
            wire.append(buffer.getvalue())
        result[name] = (instances[0]._type, instances[0]._md5sum, wire)
    return result


Reading = collections.namedtuple('Reading', 'seconds threads sockets resident')


class NodeHealth:
    """requestTopic answered (also by the library as it is, which answers no
    getPid); threads, sockets and resident memory of the node's
    process, read every HEALTH_PERIOD."""

    def __init__(self, board):
        self.board = board
        self.readings = []
        self.start = time.monotonic()

    def check(self):
        """Reads the figures; returns an error text or None."""
        pid = self.board.process.popen.pid
        if not self.board.process.alive():
            return 'the node exited with status %s' % self.board.process.popen.returncode
        try:
            with open('/proc/%d/status' % pid) as status:
                resident = int(re.search(r'^VmRSS:\s+(\d+) kB', status.read(), re.M).group(1))
            sockets = sum(os.readlink('/proc/%d/fd/%s' % (pid, fd)).startswith('socket:')
                          for fd in os.listdir('/proc/%d/fd' % pid))
            self.readings.append(Reading(time.monotonic() - self.start,
                                         len(os.listdir('/proc/%d/task' % pid)), sockets,
                                         resident * 1024))
        except (OSError, AttributeError):
            return 'the node exited'
        proxy = xmlrpc.client.ServerProxy(self.board.slave_uri,
                                          transport=TimedTransport(ANSWER_TIMEOUT))
        try:
            code, _, _ = proxy.requestTopic('/network_fuzz', '/back/String', [['TCPROS']])
        except (OSError, xmlrpc.client.Error) as error:
            return 'the node did not answer requestTopic within %.0f s: %s' % (ANSWER_TIMEOUT,
                                                                               error)
        return None if code == 1 else 'requestTopic answered %r' % code

    def bounded(self):
        """An error text if the threads grew, the node holds more sockets
        at the end than at the start (with the drain's five connected), or
        the memory grew past MEMORY_GROWTH_LIMIT after the first quarter of
        the run."""
        if len(self.readings) < 2:
            return None
        first, most = self.readings[0].threads, max(r.threads for r in self.readings)
        if most > first:
            return "the node's threads grew from %d to %d" % (first, most)
        if self.readings[-1].sockets > self.readings[0].sockets:
            return "the node holds %d sockets at the end, %d at the start" % (
                self.readings[-1].sockets, self.readings[0].sockets)
        growth = self.readings[-1].resident - self.readings[len(self.readings) // 4].resident
        if growth > MEMORY_GROWTH_LIMIT:
            return "the node's resident memory grew by %d KiB after the first quarter" % (
                growth // 1024)
        return None

    def figures(self):
        """{threads: (start, most), sockets: (start, most, end), resident KiB: (start,
        quarter, end)}."""
        if not self.readings:
            return {}
        first, quarter, last = (self.readings[0], self.readings[len(self.readings) // 4],
                                self.readings[-1])
        return {'threads': (first.threads, max(r.threads for r in self.readings)),
                'sockets': (first.sockets, max(r.sockets for r in self.readings), last.sockets),
                'resident_kib': tuple(r.resident // 1024 for r in (first, quarter, last))}


def unread_from_publishers(board):
    """Bytes waiting in the receive queues of the node's connections to
    publishers (those it opened: not at its slave or publisher port; a
    subscriber's bytes after its header are never read), from /proc."""
    pid = board.process.popen.pid
    inodes = set()
    for fd in os.listdir('/proc/%d/fd' % pid):
        target = os.readlink('/proc/%d/fd/%s' % (pid, fd))
        if target.startswith('socket:['):
            inodes.add(target[len('socket:['):-1])
    unread = 0
    with open('/proc/%d/net/tcp' % pid) as table:
        for row in list(table)[1:]:
            fields = row.split()
            local_port = int(fields[1].split(':')[1], 16)
            if fields[9] in inodes and fields[3] != TCP_LISTEN \
                    and local_port not in (board.slave_port, board.publisher_port):
                unread += int(fields[4].split(':')[1], 16)
    return unread


def settle(board):
    """Waits until the node has read what publishers sent it; the seconds it took."""
    start = time.monotonic()
    while unread_from_publishers(board) and time.monotonic() - start < SETTLE_TIMEOUT:
        time.sleep(0.5)
    return time.monotonic() - start


def failure_record(pid):
    """For the record of a failed run: every thread's backtrace and the
    process' TCP connections, where gdb and ss are installed."""
    record = ''
    if shutil.which('gdb'):
        record += subprocess.run(['gdb', '-p', str(pid), '-batch', '-ex', 'thread apply all bt'],
                                 capture_output=True, text=True, timeout=120).stdout
    if shutil.which('ss'):
        record += subprocess.run(['ss', '-tanp'], capture_output=True, text=True).stdout
    return record


# --- mutation ---------------------------------------------------------------

class Mutator:
    """Byte-level mutations in the manner of libFuzzer's, from one seeded
    random generator, so a run is repeated by its seed."""

    def __init__(self, rng):
        self.rng = rng

    def mutate(self, data, tokens=()):
        data = bytearray(data)
        for _ in range(self.rng.randint(1, 4)):
            data = self.rng.choice(self._operations)(self, data, tokens)
        return bytes(data)

    def _position(self, data):
        return self.rng.randint(0, len(data))

    def _flip_bit(self, data, _):
        if data:
            data[self.rng.randrange(len(data))] ^= 1 << self.rng.randrange(8)
        return data

    def _interesting_byte(self, data, _):
        if data:
            data[self.rng.randrange(len(data))] = self.rng.choice([0, 0x7f, 0x80, 0xff, 0x3c,
                                                                   0x3e, 0x3d, 0x0a])
        return data

    def _interesting_word(self, data, _):
        position = self._position(data)
        word = self.rng.choice(INTERESTING_WORDS + [len(data), len(data) - 4, len(data) + 1])
        data[position:position + 4] = struct.pack('<I', word & 0xffffffff)
        return data

    def _insert_random(self, data, _):
        position = self._position(data)
        data[position:position] = bytes(self.rng.randrange(256)
                                        for _ in range(self.rng.randint(1, 32)))
        return data

    def _insert_token(self, data, tokens):
        if tokens:
            position = self._position(data)
            data[position:position] = self.rng.choice(tokens)
        return data

    def _delete(self, data, _):
        start = self._position(data)
        del data[start:start + self.rng.randint(1, 64)]
        return data

    def _repeat(self, data, _):
        start = self._position(data)
        piece = data[start:start + self.rng.randint(1, 64)]
        data[start:start] = piece * self.rng.randint(1, 200)
        return data

    def _truncate(self, data, _):
        return data[:self._position(data)]

    def _long_run(self, data, _):
        position = self._position(data)
        data[position:position] = bytes([self.rng.choice(b'A<>=\x00\xff')]) * self.rng.choice(
            [255, 256, 511, 512, 513, 1023, 1024, 1025, 3000, 70000])
        return data

    _operations = [_flip_bit, _interesting_byte, _interesting_word, _insert_random,
                   _insert_token, _delete, _repeat, _truncate, _long_run]


def http_post(body, host, content_length=None):
    length = len(body) if content_length is None else content_length
    return ('POST /RPC2 HTTP/1.1\r\nHost: %s\r\nUser-Agent: network_fuzz\r\n'
            'Content-Type: text/xml\r\nContent-Length: %d\r\n\r\n'
            % (host, length)).encode() + body


def http_answer(body):
    return ('HTTP/1.0 200 OK\r\nServer: network_fuzz\r\nContent-Type: text/xml\r\n'
            'Content-Length: %d\r\n\r\n' % len(body)).encode() + body


def exchange(address, data, timeout=PEER_TIMEOUT):
    """Connects, sends data, reads what comes within timeout, closes."""
    try:
        with socket.create_connection(address, timeout=timeout) as connection:
            connection.sendall(data)
            connection.shutdown(socket.SHUT_WR)
            while connection.recv(65536):
                pass
    except OSError:
        pass


# --- the three ways in --------------------------------------------------------

class Fuzzer:
    """The fuzzing peers of one node; each method sends one input and
    returns what it sent, for the record of the last inputs."""

    def __init__(self, board, samples_by_name, rng):
        self.board, self.samples, self.rng = board, samples_by_name, rng
        self.mutator = Mutator(rng)
        self.slave_address = (BOARD_IP, board.slave_port)
        self.publisher_address = (BOARD_IP, board.publisher_port)
        self.names = list(TYPES)
        self.xml_tokens = [b'<value>', b'</value>', b'<string>', b'<array><data>', b'</data>',
                           b'<i4>', b'</i4>', b'<methodName>', b'</param>', b'&amp;', b'http://',
                           b'TCPROS', b'/src/String', b':', b'\r\n\r\n', b'Content-Length: ']
        self.header_tokens = [b'callerid=', b'topic=', b'md5sum=', b'type=', b'md5sum=*',
                              b'message_definition=', b'latching=1', b'tcp_nodelay=1', b'=']

    def _name(self):
        return self.rng.choice(self.names)

    def slave_call(self):
        name = self._name()
        method = self.rng.choice(SLAVE_METHODS)
        topic = self.rng.choice(['/src/', '/back/']) + name
        params = {
            'requestTopic': ('/fuzz', topic, [['TCPROS']]),
            'publisherUpdate': ('/master', topic, ['http://%s:%d/' % (
                PEER_IP, self.rng.choice([1, self.board.slave_port, 65535]))]),
            'paramUpdate': ('/fuzz', '/param', 1),
            'shutdown': ('/fuzz', 'fuzzing'),
        }.get(method, ('/fuzz',))
        body = xmlrpc.client.dumps(params, method).encode()
        kind = self.rng.random()
        if kind < 0.45:
            data = http_post(self.mutator.mutate(body, self.xml_tokens),
                             '%s:%d' % self.slave_address)
        elif kind < 0.6:
            data = http_post(body, '%s:%d' % self.slave_address,
                             self.rng.choice(INTERESTING_WORDS[:12]))
        else:
            data = self.mutator.mutate(http_post(body, '%s:%d' % self.slave_address),
                                       self.xml_tokens)
        exchange(self.slave_address, data)
        return 'slave', data

    def subscriber_header(self):
        name = self._name()
        datatype, md5sum, _ = self.samples[name]
        fields = {'callerid': '/fuzz_subscriber', 'topic': '/back/' + name, 'type': datatype,
                  'md5sum': self.rng.choice([md5sum, '*']), 'tcp_nodelay': '1'}
        for key in list(fields):
            if self.rng.random() < 0.1:
                del fields[key]
        header = encode_header(fields)
        if self.rng.random() < 0.8:
            header = self.mutator.mutate(header, self.header_tokens)
        exchange(self.publisher_address, header)
        return 'subscriber header', header

    def hostile_publisher(self):
        """A publisherUpdate naming a new port of ours; the node's
        requestTopic there, its connection and the frames get mutated
        answers."""
        record = []
        self._publish_to_the_node(record)
        return 'hostile publisher', b'\n'.join(record)

    def _publish_to_the_node(self, record):
        """hostile_publisher's exchanges, each answer sent added to record."""
        name = self._name()
        datatype, md5sum, wire = self.samples[name]
        topic = '/src/' + name
        with socket.create_server((PEER_IP, 0)) as xmlrpc_listener, \
                socket.create_server((PEER_IP, 0)) as tcpros_listener:
            uri = 'http://%s:%d/' % (PEER_IP, xmlrpc_listener.getsockname()[1])
            update = xmlrpc.client.dumps(('/master', topic, [uri]), 'publisherUpdate').encode()
            exchange(self.slave_address, http_post(update, '%s:%d' % self.slave_address))
            answer = xmlrpc.client.dumps(
                ([1, 'ready', ['TCPROS', PEER_IP, tcpros_listener.getsockname()[1]]],),
                methodresponse=True).encode()
            if self.rng.random() < 0.3:
                answer = self.mutator.mutate(answer, self.xml_tokens)
            record.append(answer)
            if not self._answer_request_topic(xmlrpc_listener, answer):
                return
            tcpros_listener.settimeout(1.0)
            try:
                connection, _ = tcpros_listener.accept()
            except OSError:
                return
            with connection:
                connection.settimeout(1.0)
                try:
                    read_header(connection)
                except (OSError, EOFError, ValueError, struct.error):
                    return
                header = encode_header({'callerid': '/fuzz_publisher', 'md5sum': md5sum,
                                        'type': datatype, 'topic': topic})
                if self.rng.random() < 0.3:
                    header = self.mutator.mutate(header, self.header_tokens)
                frames = header
                for _ in range(self.rng.randint(1, 5)):
                    body = self.rng.choice(wire)
                    kind = self.rng.random()
                    if kind < 0.6:  # a frame whose message lies about its lengths
                        frames += frame(self.mutator.mutate(body))
                    elif kind < 0.8:
                        frames += self.mutator.mutate(frame(body))
                    else:
                        frames += frame(body)
                frames = frames[:HOSTILE_STREAM_LIMIT]
                record.append(frames)
                try:
                    connection.sendall(frames)
                    time.sleep(self.rng.choice([0, 0.01, 0.05]))
                except OSError:
                    pass

    def _answer_request_topic(self, listener, answer):
        listener.settimeout(1.0)
        try:
            connection, _ = listener.accept()
        except OSError:
            return False
        with connection:
            connection.settimeout(1.0)
            request = b''
            try:
                while b'</methodCall>' not in request:
                    chunk = connection.recv(4096)
                    if not chunk:
                        break
                    request += chunk
                connection.sendall(http_answer(answer))
            except OSError:
                return False
        return True

    def run_one(self):
        return self.rng.choice([self.slave_call, self.subscriber_header,
                                self.hostile_publisher])()


# --- the check afterwards ---------------------------------------------------

def relayed_byte_exact(graph, board, samples_by_name):
    """Each sample of each type through the node: [(name, error text)] of
    those that did not come back as they went. A sample is sent again every
    RESEND_PERIOD until it is back: the relay's queues hold one message and
    drop the older one when another comes in."""
    failures = []
    for name, (datatype, md5sum, wire) in samples_by_name.items():
        try:
            back = RawSubscriber(board.slave_uri, '/back/' + name, datatype, md5sum, timeout=10,
                                 extra_fields=REPLY_ROOM)
        except (AssertionError, OSError, EOFError) as error:
            failures.append((name, 'no subscription to /back/%s: %s' % (name, error)))
            continue
        with HostilePublisher(graph, '/network_fuzz_check_' + name.lower(), '/src/' + name,
                              datatype) as publisher:
            try:
                connection, _ = publisher.accept(timeout=10)
                connection.sendall(encode_header({'callerid': publisher.node_name,
                                                  'md5sum': md5sum, 'type': datatype,
                                                  'topic': publisher.topic}))
                failure = _relay_each(connection, back, wire)
                connection.close()
            except (OSError, EOFError) as error:
                failure = 'no connection from the node to a new publisher: %s' % error
        back.close()
        if failure:
            failures.append((name, failure))
    return failures


def _relay_each(connection, back, wire):
    """An error text, or None if every sample came back as it went."""
    others = []
    for index, sample in enumerate(wire):
        deadline = time.monotonic() + RELAY_TIMEOUT
        while True:
            connection.sendall(frame(sample))
            if select.select([back.connection], [], [], RESEND_PERIOD)[0]:
                body = back.next_body()
                if body == sample:
                    break
                # Else a message of the fuzzing still queued, or an earlier
                # sample sent again.
                others.append(body)
            if time.monotonic() > deadline:
                return 'sample %d did not come back within %d s; came back: %s' % (
                    index, RELAY_TIMEOUT, ' '.join(body.hex() for body in others[-3:]))
    return None


class Drain:
    """A subscriber on every back/<Type>, reading whatever the node relays
    while it is fuzzed, so the relay's publish path runs too."""

    def __init__(self, board, samples_by_name):
        self.connections = []
        for name, (datatype, md5sum, _) in samples_by_name.items():
            subscriber = RawSubscriber(board.slave_uri, '/back/' + name, datatype, md5sum,
                                       extra_fields=REPLY_ROOM)
            subscriber.connection.settimeout(None)
            self.connections.append(subscriber.connection)
        self.received = 0
        self.thread = threading.Thread(target=self._read, daemon=True)
        self.thread.start()

    def _read(self):
        selector = selectors.DefaultSelector()
        for connection in self.connections:
            selector.register(connection, selectors.EVENT_READ)
        while selector.get_map():
            for key, _ in selector.select(1.0):
                try:
                    data = key.fileobj.recv(65536)
                except OSError:
                    data = b''
                if not data:
                    selector.unregister(key.fileobj)
                self.received += len(data)

    def close(self):
        for connection in self.connections:
            try:
                connection.shutdown(socket.SHUT_RDWR)
            except OSError:
                pass
            connection.close()


# --- the run ------------------------------------------------------------------

class Run:
    """What one run did and found."""

    def __init__(self, seed):
        self.seed = seed
        self.inputs = 0
        self.counts = collections.Counter()  # inputs of each kind
        self.last_inputs = collections.deque(maxlen=20)  # (kind, bytes)
        self.minutes = 0.0
        self.settle_seconds = 0.0
        self.failures = []
        self.reports = []  # the sanitizers' lines
        self.relayed_bytes = 0
        self.health = {}
        self.record = ''  # gdb's stacks and the sockets, where the node failed


def fuzz(program, seconds, max_inputs, seed, scratch):
    """Fuzzes the node for seconds or max_inputs inputs, then checks it;
    returns the Run."""
    samples_by_name = samples()
    run = Run(seed)
    os.environ.update(SANITIZER_OPTIONS)
    with RosGraph() as graph:
        board = Board(graph, program, scratch, runner=[])
        board.process.wait_for('relay ready', timeout=30)
        drain = Drain(board, samples_by_name)
        health = NodeHealth(board)
        error = _send_inputs(run, board, Fuzzer(board, samples_by_name, random.Random(seed)),
                             health, seconds, max_inputs)
        # The drain's five subscriptions and the relay's own five fill the
        # sample configuration's ten subscription connections.
        drain.close()
        run.relayed_bytes = drain.received
        if error:
            run.failures.append('after %d inputs: %s' % (run.inputs, error))
        else:
            run.settle_seconds = settle(board)
            run.failures += ['%s: %s' % item
                             for item in relayed_byte_exact(graph, board, samples_by_name)]
            error = health.check()  # the last reading: what the node holds afterwards
            run.failures += ['after the check: ' + error] if error else []
            bound = health.bounded()
            run.failures += [bound] if bound else []
        if run.failures and board.process.alive():
            run.record = failure_record(board.process.popen.pid)
        board.process.stop()
        output = board.process.output()
    run.health = health.figures()
    run.reports = [line for line in output.splitlines() if SANITIZER_REPORT.search(line)]
    if run.reports and not any('sanitizer' in failure for failure in run.failures):
        run.failures.append('a sanitizer report')
    if run.failures:
        with open(os.path.join(scratch, 'last_inputs.json'), 'w') as stream:
            json.dump([(kind, base64.b64encode(data).decode()) for kind, data in run.last_inputs],
                      stream, indent=1)
        with open(os.path.join(scratch, 'node.log'), 'w') as stream:
            stream.write(output + '\n' + run.record)
    return run


def _send_inputs(run, board, fuzzer, health, seconds, max_inputs):
    """The fuzzing itself; an error text where the node failed, else None."""
    error = health.check()
    start = time.monotonic()
    next_check = start + HEALTH_PERIOD
    while error is None and time.monotonic() - start < seconds and run.inputs < max_inputs:
        kind, data = fuzzer.run_one()
        run.inputs += 1
        run.counts[kind] += 1
        run.last_inputs.append((kind, data))
        if SANITIZER_REPORT.search(board.process.output()[-20000:]):
            error = 'a sanitizer report'
        elif time.monotonic() >= next_check:
            error = health.check()
            next_check = time.monotonic() + HEALTH_PERIOD
    run.minutes = (time.monotonic() - start) / 60
    return error or health.check()


def print_table(run, hardened):
    print('\nNetwork fuzzing of the mROS v1 library %s (PC target, native, ASan+UBSan), seed %d'
          % ('hardened' if hardened else 'as it is', run.seed))
    print('| inputs | minutes | slave calls | subscriber headers | hostile publishers | reports '
          '| threads (start/most) | sockets (start/most/end) | resident KiB (start/quarter/end) '
          '| relayed bytes | settled in |')
    print('|---:|---:|---:|---:|---:|---:|---|---|---|---:|---:|')
    print('| %d | %.1f | %d | %d | %d | %d | %s | %s | %s | %d | %.1f s |' % (
        run.inputs, run.minutes, run.counts['slave'], run.counts['subscriber header'],
        run.counts['hostile publisher'], len(run.reports),
        '/'.join(map(str, run.health.get('threads', ()))),
        '/'.join(map(str, run.health.get('sockets', ()))),
        '/'.join(map(str, run.health.get('resident_kib', ()))), run.relayed_bytes,
        run.settle_seconds))
    for line in run.reports[:5]:
        print('report: ' + line)
    for failure in run.failures:
        print('FAIL: ' + failure)
    if not run.failures:
        print('every type relayed byte-exact afterwards')


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    parser.add_argument('--seconds', type=float, default=600, help='how long to fuzz')
    parser.add_argument('--inputs', type=int, default=10 ** 9, help='at most this many inputs')
    parser.add_argument('--seed', type=int, default=None, help='repeat a run (default: random)')
    parser.add_argument('--as-it-is', action='store_true',
                        help='fuzz the library unpatched (it fails within a few hundred inputs)')
    parser.add_argument('--build-dir', help='keep the build and a failure\'s record here')
    args = parser.parse_args()
    mros_root = os.environ.get('MROS_V1_ROOT', '')
    if not os.path.isfile(os.path.join(mros_root, 'mros-lib', 'Makefile.m')):
        print("%s: needs an mROS v1 checkout: set MROS_V1_ROOT (no mros-lib/Makefile.m at '%s')"
              % (os.path.basename(sys.argv[0]), mros_root), file=sys.stderr)
        return 2
    seed = args.seed if args.seed is not None else random.randrange(2 ** 31)
    build_root = os.path.abspath(args.build_dir or tempfile.mkdtemp(prefix='network_fuzz_'))
    os.makedirs(build_root, exist_ok=True)
    program = build(mros_root, build_root, not args.as_it_is)
    run = fuzz(program, args.seconds, args.inputs, seed, build_root)
    print_table(run, not args.as_it_is)
    if run.failures:
        print('the node\'s log and the last inputs: %s' % build_root)
        return 1
    if not args.build_dir:
        shutil.rmtree(build_root)
    return 0


if __name__ == '__main__':
    sys.exit(main())
