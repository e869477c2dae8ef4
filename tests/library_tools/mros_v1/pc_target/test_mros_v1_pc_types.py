# SPDX-License-Identifier: BSD-3-Clause
"""Every message type of test_ws through the real mROS v1 library:
the aggregates (callCallback, getMD5Sum, the explicit instantiations) for
all of them in one app, with both storage kinds, on the library's wire and
on-board paths.

The app (tests/fixtures/mros_v1_pc_app/type_relay.cpp, in mROS v1 style)
relays src/<Type> to mid/<Type>, which only the board subscribes to, and
from there to back/<Type>: every sample of message_samples.py crosses
deserialize (from the wire), memCopy and deserialize (on the board) and
serialize (to the wire), and must come back byte-equal to genpy's bytes.
The library's subscription and publication slots (10 each in
custom_pubsub's mros_config) hold two types at a time: the board's switches
P6_0 and P6_1 pick the group.

The library reads a peer's TCPROS connection header into a 512-byte buffer
without a bound, and rospy and roscpp send the type's whole definition text
in theirs, so with real ROS nodes only short types work. The byte-exact
tests therefore use raw TCPROS peers (no message_definition) and build
without the fit check; with it, the build is refused with one line per
setting and the value it needs (in bounded storage the memory pools too);
on a copy of the library with those values, rospy and roscpp exchange
every type with the board in both directions, byte-exact; and the crash
with the unchanged sizes is pinned, the fit check overridden.
"""

import json
import os
import re
import select
import signal
import socket
import subprocess
import time

import pytest

from testing.ros_graph import (
    DELIVERY_TIMEOUT, PEER_IP, Board, RosGraph, sourced_environment)
from testing.tcpros_peer import (
    HostilePublisher, RawSubscriber, encode_header, frame)
from support.user_checkouts import MROS_V1_ROOT
from support.pc_target_apps import build_app, library_copy
from support.sanitizer_reports import sanitizer_reports

pytestmark = [pytest.mark.needs_mros_v1, pytest.mark.needs_qemu, pytest.mark.slow]

# The app's groups, in the order of its switch statement.
GROUPS = [['PersonalData', 'BuiltinTypes'], ['ArrayTypes', 'NestedTypes'], ['Constants', 'Empty'],
          ['Header']]
TYPES = ['mros_test/%s' % name for group in GROUPS[:3] for name in group] + ['std_msgs/Header']
# Room for every sample of message_samples.py.
BOUNDS = '* max_size:48 max_count:6\n'
# The library's connection-header buffers and the size the workaround gives
# them (NestedTypes' definition text alone is 3.7 KB).
PACKET_CONFIG = os.path.join('mros-lib', 'mros-src', 'packet', 'cimpl', 'version', 'kinetic',
                             'mros_packet_config.h')
# The library writes its reply header into the buffer the request came in,
# sized to the request (the AnyMsg limit, see test_mros_v1_pc.py): a raw
# subscriber's header must be as long as the reply. rospy's and roscpp's
# are, with their definition texts; this field, ignored by TCPROS, is.
REPLY_ROOM = {'padding': '.' * 200}

SAMPLES_CODE = '''
import io, json, sys
sys.path.insert(0, sys.argv[1])
from message_samples import samples

def wire(message):
    buffer = io.BytesIO()
    message.serialize(buffer)
    return buffer.getvalue().hex()

print(json.dumps({name: [messages[0]._type, messages[0]._md5sum, [wire(m) for m in messages]]
                  for name, messages in samples().items()}))
'''


@pytest.fixture(scope='module')
def genpy_samples(ros_workspace):
    """{name: (type, MD5 sum, [genpy's bytes of each sample])}."""
    output = subprocess.run(['/usr/bin/python3', '-c', SAMPLES_CODE, ros_workspace.scripts],
                            env=sourced_environment(ros_workspace.setup_bash), check=True,
                            capture_output=True, text=True).stdout
    return {name: (datatype, md5sum, [bytes.fromhex(sample) for sample in samples])
            for name, (datatype, md5sum, samples) in json.loads(output).items()}


def build_relay(mros_root, build_root, storage='heap', target='arm', sanitize=False,
                fit_check=True):
    """The relay app of every type; fit_check=False builds it for the
    unchanged library, whose settings the fit check finds too small for ROS
    nodes' connection headers: for raw peers, which send no definition text,
    and to show the overrun the check prevents."""
    flags = ['--storage', storage] + (['--sanitize'] if sanitize else [])
    flags += [] if fit_check else ['--no-fit-check']
    if storage == 'bounded':
        options = build_root / 'bounds.options'
        options.write_text(BOUNDS)
        flags += ['--options', str(options)]
    program = build_app(mros_root, str(build_root), 'type_relay.cpp', target=target,
                        types=TYPES, header_flags=flags)
    header = (build_root / 'build' / 'include' / 'mros_test' / 'PersonalData.h').read_text()
    assert ('mros::bounded_string<48> first_name;' if storage == 'bounded'
            else 'std::string first_name;') in header
    return program


@pytest.fixture(scope='module', params=['heap', 'bounded'])
def relay_program(request, tmp_path_factory):
    return build_relay(MROS_V1_ROOT, tmp_path_factory.mktemp('relay_' + request.param),
                       request.param, fit_check=False)


def start_relay(graph, program, directory, group):
    board = Board(graph, program, directory, inputs={'P6_0': group & 1, 'P6_1': group >> 1})
    board.process.wait_for('relay ready', timeout=DELIVERY_TIMEOUT)
    return board


def relay_through_board(graph, board, name, datatype, md5sum, samples):
    """Publishes each sample on src/name from a raw publisher, again every
    0.3 s until something comes back on back/name; returns what came back
    for each sample (the relay's queues hold one message and may drop)."""
    returned = []
    with HostilePublisher(graph, '/raw_publisher_' + name.lower(), '/src/' + name,
                          datatype) as publisher:
        back = RawSubscriber(board.slave_uri, '/back/' + name, datatype, md5sum,
                             extra_fields=REPLY_ROOM)
        assert back.header['md5sum'] == md5sum and back.header['type'] == datatype
        # The library may connect twice (it never answers publisherUpdate).
        connections = []
        for sample in samples:
            deadline = time.monotonic() + DELIVERY_TIMEOUT
            while True:
                assert time.monotonic() < deadline, 'sample %d of %s did not come back:\n%s' % (
                    len(returned), name, board.process.output())
                try:
                    connection, header = publisher.accept(timeout=0.05)
                    assert header['md5sum'] == md5sum, header
                    connection.sendall(encode_header({'callerid': publisher.node_name,
                                                      'md5sum': md5sum, 'type': datatype,
                                                      'topic': publisher.topic}))
                    connections.append(connection)
                except socket.timeout:
                    pass
                for connection in connections:
                    connection.sendall(frame(sample))
                if select.select([back.connection], [], [], 0.3)[0]:
                    body = back.next_body()
                    if body == sample or body not in samples[:len(returned)]:
                        returned.append(body)
                        break
        back.close()
        for connection in connections:
            connection.close()
    return returned


@pytest.mark.parametrize('group', range(len(GROUPS)), ids=['-'.join(g) for g in GROUPS])
def test_every_type_through_the_board_comes_back_byte_equal_to_genpy(
        ros_workspace, genpy_samples, relay_program, group, tmp_path):
    with RosGraph(sourced_environment(ros_workspace.setup_bash)) as graph:
        board = start_relay(graph, relay_program, str(tmp_path), group)
        for name in GROUPS[group]:
            datatype, md5sum, samples = genpy_samples[name]
            assert relay_through_board(graph, board, name, datatype, md5sum, samples) == samples
        assert board.process.alive(), board.process.output()


MISFIT = re.compile(r'^genmros: error: (.+):(\d+): (\S+): .* needs (\w+) >= (\d+) \(it is (\d+)')


def _misfits(output):
    """(path, line, type, setting, needed, value) of each misfit line."""
    return [(m.group(1), int(m.group(2)), m.group(3), m.group(4), int(m.group(5)),
             int(m.group(6))) for m in map(MISFIT.match, output.splitlines()) if m]


def refused_build(storage, build_root):
    """What building the relay for the unchanged library prints."""
    with pytest.raises(RuntimeError) as refused:
        build_relay(MROS_V1_ROOT, build_root, storage)
    return str(refused.value)


@pytest.fixture(scope='module')
def refused_relay(tmp_path_factory):
    return refused_build('heap', tmp_path_factory.mktemp('relay_refused'))


def test_the_relay_is_refused_with_the_samples_settings_one_line_per_misfit(
        refused_relay, ros_workspace):
    # The oracle: rospy's own definition text of each type; a header is
    # refused where it is too long even with the shortest topic and caller
    # id ('/a'), 115 (subscriber) or 112 (publisher) bytes besides.
    texts = json.loads(subprocess.run(
        ['/usr/bin/python3', '-c', 'import json, importlib; print(json.dumps({t: len(getattr('
         'importlib.import_module(t.split("/")[0] + ".msg"), t.split("/")[1])._full_text.encode())'
         ' for t in %r}))' % TYPES], capture_output=True, text=True, check=True,
        env=ros_workspace.environment()).stdout)
    expected = set()
    for type_name, text in texts.items():
        if 115 + text + len(type_name) + 4 + 1 > 512:
            expected.add((type_name, 'MROS_PACKET_MAXSIZE_REQ_TCPROS'))
        if 112 + text + len(type_name) + 4 > 512:
            expected.add((type_name, 'MROS_PACKET_MAXSIZE_RES_TCPROS'))
    misfits = _misfits(refused_relay)
    assert expected and {(m[2], m[3]) for m in misfits} == expected, refused_relay
    assert len(misfits) == len(expected)
    packet_config = os.path.join(MROS_V1_ROOT, PACKET_CONFIG)
    for path, line, _, setting, needed, value in misfits:
        with open(path) as stream:
            assert re.match(r'#define %s\s+%d\b' % (setting, value), stream.readlines()[line - 1])
        assert path == packet_config and needed > value == 512
    # Refused before make ran.
    assert 'the mROS v1 library of' not in refused_relay


@pytest.fixture(scope='module', params=['heap', 'bounded'])
def fitted_relay(request, refused_relay, tmp_path_factory):
    """The relay on a copy of the library with the values its refusal
    printed; in bounded storage they include the memory pools for the
    largest frames."""
    storage = request.param
    refusal = refused_relay if storage == 'heap' else refused_build(
        storage, tmp_path_factory.mktemp('relay_refused_' + storage))
    values = {}
    for path, _, _, setting, needed, _ in _misfits(refusal):
        # The app's mros_config is custom_pubsub's, linked.
        key = (os.path.relpath(os.path.realpath(path), os.path.realpath(MROS_V1_ROOT)), setting)
        values[key] = max(values.get(key, 0), needed)
    # NestedTypes and ArrayTypes, bounded, take frames over the 1024-byte pools.
    pools = {setting for _, setting in values if 'MEMPOOL' in setting}
    assert pools == (set() if storage == 'heap' else {'ROS_INNER_TOPIC_PUBLISHER_MEMPOOL3_SIZE',
                                                      'ROS_OUTER_TOPIC_PUBLISHER_MEMPOOL3_SIZE'})
    root = library_copy(MROS_V1_ROOT, str(tmp_path_factory.mktemp('mros_v1_fitted_' + storage)),
                        values)
    return build_relay(root, tmp_path_factory.mktemp('relay_fitted_' + storage), storage)


def round_trip(graph, ros_workspace, source, sink, names, board, *check_options):
    """roundtrip_check.py from source/<Type> to sink/<Type>: passes for every type."""
    check = graph.start('roundtrip_check', ros_workspace.rospy(
        'roundtrip_check.py', source, sink, '--types', ','.join(names),
        '--timeout', str(DELIVERY_TIMEOUT), *check_options), {'ROS_IP': PEER_IP})
    check.popen.wait(timeout=DELIVERY_TIMEOUT * (1 + len(names)))
    assert check.popen.returncode == 0, check.output() + '\n' + board.process.output()
    for name in names:
        check.wait_for(r'^PASS %s: \d+ samples' % name, timeout=0)
    assert board.process.alive(), board.process.output()


@pytest.mark.parametrize('group', range(len(GROUPS)), ids=['-'.join(g) for g in GROUPS])
def test_with_the_printed_settings_rospy_round_trips_every_type(
        ros_workspace, fitted_relay, group, tmp_path):
    # rospy publishes to the board and subscribes to it: both headers carry
    # the definition text.
    with RosGraph(sourced_environment(ros_workspace.setup_bash)) as graph:
        board = start_relay(graph, fitted_relay, str(tmp_path), group)
        round_trip(graph, ros_workspace, '/src', '/back', GROUPS[group], board)


@pytest.mark.parametrize('group', range(len(GROUPS)), ids=['-'.join(g) for g in GROUPS])
def test_with_the_printed_settings_roscpp_round_trips_every_type(
        ros_workspace, fitted_relay, group, tmp_path):
    # rospy -> roscpp -> the board -> roscpp -> rospy: roscpp's publisher
    # sends the board its definition text, roscpp's subscriber takes what
    # the board sends.
    with RosGraph(sourced_environment(ros_workspace.setup_bash)) as graph:
        board = start_relay(graph, fitted_relay, str(tmp_path), group)
        for source, sink in (('/to_board', '/src'), ('/back', '/from_board')):
            relay = graph.start('roscpp relay ' + source, ros_workspace.roscpp(
                'type_relay', source, sink, '__name:=roscpp_relay' + source.replace('/', '_')),
                {'ROS_IP': PEER_IP})
            relay.wait_for('relaying', timeout=DELIVERY_TIMEOUT)
        # roscpp's publishers number header.seq themselves.
        round_trip(graph, ros_workspace, '/to_board', '/from_board', GROUPS[group], board,
                   '--ignore-header-seq')


ROSPY_CONSTANTS_SUBSCRIBER = (
    'import rospy; from mros_test.msg import Constants; rospy.init_node("long_header"); '
    'rospy.Subscriber("/back/Constants", Constants, lambda m: None); rospy.spin()')


def test_limit_sanitized_a_subscriber_header_over_512_bytes_is_an_overflow_in_the_library(
        ros_workspace, tmp_path):
    # What the README shows: the same rospy subscriber as below, on the
    # sanitized native build; AddressSanitizer stops the app at the write
    # past the library's 512-byte header buffer.
    program = build_relay(MROS_V1_ROOT, tmp_path / 'relay', target='native', sanitize=True,
                          fit_check=False)
    with RosGraph(sourced_environment(ros_workspace.setup_bash)) as graph:
        board = Board(graph, program, str(tmp_path), runner=[], inputs={'P6_0': 0, 'P6_1': 1})
        board.process.wait_for('relay ready', timeout=DELIVERY_TIMEOUT)
        graph.start('rospy subscriber', ['/usr/bin/python3', '-c', ROSPY_CONSTANTS_SUBSCRIBER],
                    {'ROS_IP': PEER_IP})
        assert board.process.popen.wait(timeout=DELIVERY_TIMEOUT) != 0
    output = board.process.output()
    assert "0 bytes to the right of global variable 'mros_publish_packet_buffer'" in output, output
    assert 'of size 512' in output and 'in mros_proc_tcpros_receive ' in output, output
    assert sanitizer_reports(output) == {('mros_protocol_publish_cimpl.c', 13,
                                          'global-buffer-overflow')}


def test_limit_a_subscriber_header_over_512_bytes_overruns_the_library(
        ros_workspace, genpy_samples, relay_program, tmp_path):
    # rospy's header for Constants carries its 554-byte definition text.
    with RosGraph(sourced_environment(ros_workspace.setup_bash)) as graph:
        board = start_relay(graph, relay_program, str(tmp_path), 2)
        datatype, md5sum, _ = genpy_samples['Constants']
        RawSubscriber(board.slave_uri, '/back/Constants', datatype, md5sum,
                      extra_fields=REPLY_ROOM).close()
        graph.start('rospy subscriber', ['/usr/bin/python3', '-c', ROSPY_CONSTANTS_SUBSCRIBER],
                    {'ROS_IP': PEER_IP})
        # Only TCPROS subscribers make the board log 'pub accepted': the raw
        # one's line, then rospy's, whose header the library has read (and
        # overrun the buffer with) once it logs the new connector.
        board.process.wait_for('pub accepted', timeout=DELIVERY_TIMEOUT, count=2)
        rospy_accepted = [number for number, line in enumerate(board.process.lines())
                          if 'pub accepted' in line][1]
        board.process.wait_for('new connector', timeout=DELIVERY_TIMEOUT,
                               start=rospy_accepted + 1)
        # The overrun reaches past the buffer into the slave task's state (its
        # packet pointer, its sockets): the slave never answers again. If it
        # was back in accept, the next request writes through the pointer
        # (SIGSEGV, what every run here has shown); if rospy's header came
        # first, its accept fails on a socket number made of definition text.
        with pytest.raises(AssertionError, match='requestTopic /back/Constants'):
            RawSubscriber(board.slave_uri, '/back/Constants', datatype, md5sum, timeout=5,
                          extra_fields=REPLY_ROOM)
        outcome = board.process.wait_for(
            r'uncaught target signal 11|mros_comm_tcp_server_accept\(\)',
            timeout=DELIVERY_TIMEOUT, start=rospy_accepted)[0].group(0)
        if 'signal' in outcome:
            assert board.process.popen.wait(timeout=DELIVERY_TIMEOUT) == -signal.SIGSEGV
        else:
            assert board.process.alive(), board.process.output()
