# SPDX-License-Identifier: BSD-3-Clause
"""The main job's board: test_ws's messages on a firmware that has the
genmros headers and nothing of ROS or mROS, exchanged with real ROS nodes.

- build_firmware: evaluation/firmware, a CMake project, on the export dir of
  the catkin build (find_package(genmros), mros_import_messages()), for
  32-bit ARM Linux and bare-metal Cortex-M0 and M4.
- exchange: the ARM Linux program under qemu-arm, carried to the ROS graph by
  evaluation/board_bridge.py, against a real rosmaster and rospy and roscpp
  nodes: the paper's four ROS directions, and five types sent back byte for
  byte (rospy's roundtrip_check, roscpp's type_relay).
- in_sync: a field added to a message in the workspace reaches the firmware
  through catkin_make and the firmware's own rebuild.
"""

import json
import os
import subprocess
import time
import xmlrpc.client

from testing.ros_graph import DELIVERY_TIMEOUT, PYTHON, RosGraph
from testing.tcpros_peer import RawSubscriber

from paper import BOARD, ROS, ROS_HEARD, Direction, ros_heard, start_listeners

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
FIRMWARE = os.path.join(REPO, 'evaluation', 'firmware')
BRIDGE = os.path.join(REPO, 'evaluation', 'board_bridge.py')
RELAYED = ('PersonalData', 'BuiltinTypes', 'ArrayTypes', 'NestedTypes', 'Header')
RELAYED_TYPES = ('mros_test/PersonalData', 'mros_test/BuiltinTypes', 'mros_test/ArrayTypes',
                 'mros_test/NestedTypes', 'std_msgs/Header')
BOARD_NODE = '/mros_board'
BOARD_HEARD = r'board: heard: (\S+ \S+) age:(\d+) score:(-?\d+)'


class Target:
    """A CPU the firmware is built for: its toolchain file, port and size tool."""

    def __init__(self, name, title, port, size_tool):
        self.name, self.title, self.port, self.size_tool = name, title, port, size_tool


TARGETS = (
    Target('arm-linux-gnueabihf', '32-bit ARM Linux (arm-linux-gnueabihf-g++, static)', 'linux',
           'arm-linux-gnueabihf-size'),
    Target('cortex-m0', 'Cortex-M0 (arm-none-eabi-g++, newlib nano)', 'bare_metal',
           'arm-none-eabi-size'),
    Target('cortex-m4', 'Cortex-M4F (arm-none-eabi-g++, newlib nano)', 'bare_metal',
           'arm-none-eabi-size'),
)


class Failure(Exception):
    """A step that did not do what it shows; the message says what happened."""


def run_logged(argv, log_path, cwd=None, env=None):
    """Runs argv with its output in log_path; Failure naming the log if it fails."""
    with open(log_path, 'w') as log:
        result = subprocess.run(argv, stdout=log, stderr=subprocess.STDOUT, cwd=cwd, env=env)
    if result.returncode != 0:
        raise Failure('%s failed (exit %d): see %s' % (os.path.basename(argv[0]),
                                                       result.returncode, log_path))
    with open(log_path) as log:
        return log.read()


def build_firmware(export_dir, build_dir, target):
    """The firmware for target in build_dir; returns (program, its sizes)."""
    os.makedirs(os.path.dirname(build_dir), exist_ok=True)
    configure = ['cmake', '-S', FIRMWARE, '-B', build_dir, '-DMROS_EXPORT_DIR=' + export_dir,
                 '-DBOARD_PORT=' + target.port,
                 '-DCMAKE_TOOLCHAIN_FILE=%s/toolchains/%s.cmake' % (FIRMWARE, target.name),
                 '-Dgenmros_DIR=' + subprocess.run(['genmros', 'cmake-dir'], check=True,
                                                   capture_output=True,
                                                   text=True).stdout.strip()]
    run_logged(configure, build_dir + '.configure.log')
    run_logged(['cmake', '--build', build_dir, '-j2'], build_dir + '.build.log')
    program = os.path.join(build_dir, 'board')
    return program, sizes(target, program)


def sizes(target, program):
    """'flash N B, RAM N B (static)' of program, from the target's size tool."""
    text, data, bss = map(int, subprocess.run([target.size_tool, program], check=True,
                                              capture_output=True, text=True)
                          .stdout.splitlines()[1].split()[:3])
    return 'flash %d B (text %d + data %d), static RAM %d B (data %d + bss %d)' % (
        text + data, text, data, data + bss, data, bss)


def rospy_identity(workspace, types):
    """{pkg/Type: (md5sum, definition text)} of genpy's classes in workspace."""
    script = ('import importlib, json, sys\n'
              'classes = [getattr(importlib.import_module(t.split("/")[0] + ".msg"),'
              ' t.split("/")[1]) for t in sys.argv[1:]]\n'
              'print(json.dumps({t: [c._md5sum, c._full_text]'
              ' for t, c in zip(sys.argv[1:], classes)}))\n')
    output = subprocess.run([PYTHON, '-c', script] + list(types), env=workspace.environment(),
                            check=True, capture_output=True, text=True).stdout
    return {name: tuple(value) for name, value in json.loads(output).items()}


def board_identity(program):
    """{pkg/Type: md5sum} as the firmware's headers give them (board --describe)."""
    output = subprocess.run(['qemu-arm', program, '--describe'], check=True,
                            capture_output=True, text=True).stdout
    return {fields[1]: fields[2] for fields in map(str.split, output.splitlines())}


def _wait_for(process, pattern, count, start=0):
    try:
        return process.wait_for(pattern, timeout=DELIVERY_TIMEOUT, start=start, count=count)
    except AssertionError:
        return []


class Check:
    """One result of the exchange: a title, a detail, and None or a problem."""

    def __init__(self, title, detail, problem=None):
        self.title, self.detail, self.problem = title, detail, problem


def _direction(direction):
    return Check(direction.title, direction.detail(), direction.problem)


def _connection_header(graph, identity):
    """What a TCPROS subscriber gets from the board's publisher of /mros_str,
    held against rospy's PersonalData."""
    code, message, slave_uri = xmlrpc.client.ServerProxy(
        graph.uri).lookupNode('/check', BOARD_NODE)
    if code != 1:
        return Check('TCPROS connection header', '', 'lookupNode: %s' % message)
    md5sum, definition = identity['mros_test/PersonalData']
    subscriber = RawSubscriber(slave_uri, '/mros_str', 'mros_test/PersonalData', md5sum)
    try:
        header = subscriber.header
    finally:
        subscriber.close()
    problem = None
    if header.get('md5sum') != md5sum or header.get('type') != 'mros_test/PersonalData':
        problem = 'type %r md5sum %r' % (header.get('type'), header.get('md5sum'))
    elif header.get('message_definition') != definition:
        problem = "message_definition is not rospy's"
    return Check('TCPROS connection header of the board',
                 'type mros_test/PersonalData, md5sum %s, message_definition %d bytes, '
                 "both rospy's" % (header.get('md5sum'), len(
                     header.get('message_definition', ''))),
                 problem)


def _roundtrip(graph, workspace, title, sink, *flags):
    check = graph.start('roundtrip_check %s' % sink, workspace.rospy(
        'roundtrip_check.py', '/rospy_out', sink, '--types', ','.join(RELAYED), *flags))
    try:
        status = check.popen.wait(len(RELAYED) * 2 * 20 + 30)
    except subprocess.TimeoutExpired:
        status = None
    results = [line for line in check.lines() if line.startswith(('PASS ', 'FAIL '))]
    passed = status == 0 and len(results) == len(RELAYED)
    return Check(title, '; '.join(line.split(':')[0][5:] + ':' + line.split(':')[1]
                                  for line in results if line.startswith('PASS')),
                 None if passed else ' / '.join(results) or check.output()[-500:])


def exchange(workspace, program, count):
    """The board against real ROS nodes: a list of Check."""
    identity = rospy_identity(workspace, RELAYED_TYPES)
    checks = []
    with RosGraph(workspace.environment()) as graph:
        listeners = start_listeners(graph, workspace, 'board')
        bridge = graph.start('board_bridge.py', [PYTHON, BRIDGE, 'qemu-arm', program])
        try:
            graph.wait_for_graph(publishers=[('/mros_str', BOARD_NODE)],
                                 subscribers=[('/test_msg', BOARD_NODE)],
                                 timeout=DELIVERY_TIMEOUT)
        except AssertionError as error:
            return [Check('the board in the ROS graph', '', '%s; the bridge printed: %s' % (
                error, ' | '.join(bridge.lines()[-5:])))]
        checks.append(_connection_header(graph, identity))
        for title, listener in listeners:
            _wait_for(listener, ROS_HEARD.pattern, count)
            checks.append(_direction(Direction(title, BOARD, ros_heard(listener.lines()), count)))
        for talker, argv in (('rospy', workspace.rospy('personal_data_talker.py')),
                             ('roscpp', workspace.roscpp('personal_data_talker'))):
            start = len(bridge.lines())
            process = graph.start('%s talker' % talker, argv)
            matches = _wait_for(bridge, BOARD_HEARD, count, start)
            process.stop()
            checks.append(_direction(Direction(
                '%s talker -> board' % talker, ROS,
                [(m.group(1), int(m.group(2)), int(m.group(3))) for m in matches], count)))
        checks.append(_roundtrip(graph, workspace, 'rospy -> board -> rospy, byte for byte',
                                 '/board_out'))
        graph.start('roscpp type_relay', workspace.roscpp('type_relay', '/board_out',
                                                          '/roscpp_out'))
        checks.append(_roundtrip(
            graph, workspace, 'rospy -> board -> roscpp -> board -> rospy, byte for byte',
            '/board_back', '--ignore-header-seq'))
        refused = [line for line in bridge.lines() if 'refused' in line]
        if refused:
            checks.append(Check('the board refused nothing', '', refused[0]))
    return checks


ADDED_FIELD = 'float32 height_m  # added by the main job: the firmware must follow'


def in_sync(workspace, firmware_build, program, log_path):
    """Adds a field to mros_test/PersonalData in workspace, builds it again
    with catkin_make and then the firmware: returns what it showed."""
    before = board_identity(program)['mros_test/PersonalData']
    definition = os.path.join(workspace.root, 'src', 'mros_test', 'msg', 'PersonalData.msg')
    with open(definition, 'a') as stream:
        stream.write(ADDED_FIELD + '\n')
    started = time.monotonic()
    workspace.build(log_path + '.catkin_make', '-DCMAKE_BUILD_TYPE=Release', '-j2')
    rebuilt = run_logged(['cmake', '--build', firmware_build, '-j2'], log_path + '.firmware')
    seconds = time.monotonic() - started
    if 'board.cpp.o' not in rebuilt:
        raise Failure('the firmware was not rebuilt after catkin_make: see %s.firmware'
                      % log_path)
    board = board_identity(program)
    rospy = {name: md5sum for name, (md5sum, _) in rospy_identity(
        workspace, sorted(set(board))).items()}
    if board != rospy:
        raise Failure('MD5 sums of the firmware %s, of rospy %s' % (board, rospy))
    after = board['mros_test/PersonalData']
    if after == before:
        raise Failure('the MD5 sum of mros_test/PersonalData did not change (%s)' % after)
    return ("field 'float32 height_m' added: PersonalData's MD5 %s -> %s in the firmware, equal "
            "to rospy's, as are the other %d types' (catkin_make + firmware rebuild %.0f s)"
            % (before[:8], after[:8], len(board) - 1, seconds))
