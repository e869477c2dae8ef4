#!/usr/bin/env python3
"""The paper's evaluation (section 6.2) on the real mROS v1 library, run by
the PC target as users run it (genmros mros-v1-pc), against a real rosmaster
and real ROS nodes. The app (tests/fixtures/mros_v1_pc_app/personal_data.cpp)
is Fig. 6 and Fig. 7 written for mROS v1: it publishes mros_test/PersonalData
("Phil", "Woods", 83, score counting up), which a rospy and a roscpp node
print and which the library also delivers on the board; then a rospy and a
roscpp node publish ("Charlie", "Parker", 32, ...) and the app prints it.
Exits 0 only if every direction delivered the right values in order.

  evaluation.py [--messages N] [--build-dir DIR]

Builds test_ws (catkin_make) and the app first, in DIR or in a temporary
directory. The mROS v1 checkout is MROS_V1_ROOT (default ../shared/mros_v1
beside this repository). The tests import Board, build_app and run.

The library ignores publishers at its own address, and roscpp with a
loopback ROS_IP takes TCPROS connections on 127.0.0.1 only: apps run with
ROS_IP=127.0.0.2, ROS nodes with 127.0.0.1.
"""

import argparse
import os
import re
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

import built_workspace  # noqa: E402
from mros_v1_checkout import MROS_V1_ROOT, checkout_found  # noqa: E402
from ros_processes import RosGraph, free_port, sourced_environment  # noqa: E402

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
TEST_WS = os.path.join(REPO, 'test_ws')
BOARD_IP = '127.0.0.2'
PEER_IP = '127.0.0.1'
# How long a message may take through qemu, the library's 100 ms polling
# and a loaded machine.
DELIVERY_TIMEOUT = 30
APP_FIXTURE = os.path.join(REPO, 'tests', 'fixtures', 'mros_v1_pc_app')


def board_environment():
    """The environment of an app on the PC target beside this machine's ROS
    nodes: its own address and free slave and publisher ports."""
    return {'ROS_IP': BOARD_IP, 'MROS_V1_SLAVE_PORT': str(free_port()),
            'MROS_V1_PUBLISHER_PORT': str(free_port())}


class Board:
    """An app on the PC target in a ROS graph: its log, its pins."""

    def __init__(self, graph, program, directory, runner=('qemu-arm',), inputs=None):
        self.inputs = os.path.join(directory, 'inputs')
        self.outputs = os.path.join(directory, 'outputs')
        self.set_inputs(**(inputs or {'P6_0': 1}))
        environment = board_environment()
        self.slave_port = int(environment['MROS_V1_SLAVE_PORT'])
        self.publisher_port = int(environment['MROS_V1_PUBLISHER_PORT'])
        environment.update(MROS_PC_INPUTS=self.inputs, MROS_PC_OUTPUT_LOG=self.outputs)
        self.process = graph.start(os.path.basename(program), list(runner) + [program],
                                   environment)

    def set_inputs(self, **pins):
        with open(self.inputs + '.new', 'w') as stream:
            stream.writelines('%s %d\n' % item for item in sorted(pins.items()))
        os.replace(self.inputs + '.new', self.inputs)

    def output_lines(self):
        if not os.path.exists(self.outputs):
            return []
        with open(self.outputs) as stream:
            return stream.read().splitlines()

    def wait_for_output(self, line, timeout=DELIVERY_TIMEOUT):
        deadline = time.monotonic() + timeout
        while line not in self.output_lines():
            assert time.monotonic() < deadline, 'no output %r; outputs: %s; log:\n%s' % (
                line, self.output_lines()[-20:], self.process.output())
            time.sleep(0.1)

    @property
    def slave_uri(self):
        return 'http://%s:%d/' % (BOARD_IP, self.slave_port)


def build_app(mros_root, build_root, source='personal_data.cpp', target='arm',
              types=('mros_test/PersonalData',), header_flags=()):
    """A test app: source (a name in tests/fixtures/mros_v1_pc_app, or a
    path) as its app.cpp beside that dir's Makefile, app.cfg and app.h, with
    custom_pubsub's mros_config/ linked in (the library's tasks and memory
    pools, as a new app takes them from a sample), built by genmros
    mros-v1-pc for target with the headers of types (header_flags: more
    options of mros-v1-pc, such as --storage); returns the program."""
    app = os.path.join(build_root, 'app')
    os.makedirs(app, exist_ok=True)
    links = {name: os.path.join(APP_FIXTURE, name) for name in ('Makefile', 'app.cfg', 'app.h')}
    links['app.cpp'] = os.path.join(APP_FIXTURE, source)
    links['mros_config'] = os.path.join(mros_root, 'mros_ws', 'custom_pubsub', 'mros_config')
    for name, origin in links.items():
        if not os.path.lexists(os.path.join(app, name)):
            os.symlink(origin, os.path.join(app, name))
    output = os.path.join(build_root, 'build')
    type_args = [argument for name in types for argument in ('--type', name)]
    result = subprocess.run(
        [sys.executable, '-m', 'colcon_mros', 'mros-v1-pc', app, '--mros-root', mros_root,
         '--msg-path', os.path.join(TEST_WS, 'src'), '-o', output, '--target', target, '-j2']
        + type_args + list(header_flags), cwd=REPO, capture_output=True, text=True)
    if result.returncode != 0:
        raise RuntimeError('genmros mros-v1-pc failed:\n' + result.stdout[-3000:]
                           + result.stderr[-3000:])
    return os.path.join(output, 'test_app')


ROS_HEARD = re.compile(r'I heard from mROS: (\S*) (\S*) age:(\d+) score:(-?\d+)')
MROS_HEARD = re.compile(r'name:(.*)$')
MROS_AGE = re.compile(r'age:(\d+)$')
MROS_SCORE = re.compile(r'score:(-?\d+)$')


class Direction:
    """One sender -> receiver run and what the receiver printed."""

    def __init__(self, title, expected_name, expected_age, first_score, received, count):
        self.title = title
        self.expected = (expected_name, expected_age)
        self.received = received[:count]  # (name, age, score)
        self.problem = self._problem(first_score, count)

    def _problem(self, first_score, count):
        if len(self.received) < count:
            return 'received %d of %d messages' % (len(self.received), count)
        for name, age, score in self.received:
            if (name, age) != self.expected or score < first_score:
                return 'wrong values: %s age:%d score:%d' % (name, age, score)
        scores = [score for _, _, score in self.received]
        if any(later != earlier + 1 for earlier, later in zip(scores, scores[1:])):
            return 'scores not counting up by one: %s' % scores
        return None

    def summary(self):
        name, age = self.expected
        scores = [score for _, _, score in self.received]
        values = '%s, age %d, score %s..%s' % (name, age, scores[0] if scores else '-',
                                               scores[-1] if scores else '-')
        return '%-26s %2d messages  %-40s %s' % (
            self.title, len(self.received), values,
            'PASS' if self.problem is None else 'FAIL: ' + self.problem)


def parse_mros_listener(lines):
    """(name, age, score) of every complete name/age/score group the app logged."""
    received = []
    name = age = None
    for line in lines:
        for regex, kind in ((MROS_HEARD, 'name'), (MROS_AGE, 'age'), (MROS_SCORE, 'score')):
            match = regex.search(line)
            if not match:
                continue
            if kind == 'name':
                name, age = match.group(1), None
            elif kind == 'age':
                age = int(match.group(1))
            elif name is not None and age is not None:
                received.append((name, age, int(match.group(1))))
                name = age = None
    return received


def _waited(process, pattern, count, start=0):
    """The matches of pattern once count are there, or what came in time."""
    try:
        return process.wait_for(pattern, timeout=DELIVERY_TIMEOUT, start=start, count=count)
    except AssertionError:
        return [m for m in map(re.compile(pattern).search, process.lines()[start:]) if m]


def run(workspace, program, count, scratch):
    """Every direction of the evaluation: a list of Direction."""
    environment = sourced_environment(workspace.setup_bash)
    directions = []
    with RosGraph(environment) as graph:
        listeners = [
            ('mROS -> rospy listener', graph.start('rospy personal_data_listener.py',
                                                   workspace.rospy('personal_data_listener.py'))),
            ('mROS -> roscpp listener', graph.start('roscpp personal_data_listener',
                                                    workspace.roscpp('personal_data_listener'))),
        ]
        graph.wait_for_graph(subscribers=[('/mros_str', '/rospy_personal_listener'),
                                          ('/mros_str', '/ros_personal_listener')])
        board = Board(graph, program, scratch)
        for title, listener in listeners:
            heard = [('%s %s' % (m.group(1), m.group(2)), int(m.group(3)), int(m.group(4)))
                     for m in _waited(listener, ROS_HEARD.pattern, count)]
            directions.append(Direction(title, 'Phil Woods', 83, 100000, heard, count))
        matches = _waited(board.process, r'on board: (\S+ \S+) (\d+) (-?\d+)', count)
        directions.append(Direction('mROS -> mROS on board', 'Phil Woods', 83, 100000,
                                    [(m.group(1), int(m.group(2)), int(m.group(3)))
                                     for m in matches], count))
    # One talker per graph: the library reads one publisher per topic.
    for talker, argv in (('rospy', workspace.rospy('personal_data_talker.py')),
                         ('roscpp', workspace.roscpp('personal_data_talker'))):
        with RosGraph(environment) as graph:
            board = Board(graph, program, scratch)
            graph.wait_for_graph(subscribers=[('/test_msg', '/mros_node2')])
            start = len(board.process.lines())
            graph.start('%s talker' % talker, argv)
            _waited(board.process, r'\] score:', count, start)
            directions.append(Direction('%s talker -> mROS' % talker, 'Charlie Parker', 32, 100100,
                                        parse_mros_listener(board.process.lines()[start:]),
                                        count))
    return directions


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[1])
    parser.add_argument('--messages', type=int, default=5,
                        help='messages each receiver must print (default 5)')
    parser.add_argument('--build-dir', help='keep the builds here (default: a temporary dir)')
    args = parser.parse_args()
    if not checkout_found():
        print('evaluation: no mROS v1 checkout at %s (mros-lib/Makefile.m): set '
              'MROS_V1_ROOT=<checkout of mROS-base/mROS>' % MROS_V1_ROOT, file=sys.stderr)
        return 1
    build_root = os.path.abspath(args.build_dir) if args.build_dir else \
        built_workspace.scratch('mros_evaluation_')
    ws_root = os.path.join(build_root, 'test_ws')
    os.makedirs(ws_root, exist_ok=True)
    print('building test_ws with catkin_make (genmros beside gencpp and genpy) ...', flush=True)
    workspace = built_workspace.workspace(ws_root)
    print('building the evaluation app with the mROS v1 library of %s (genmros mros-v1-pc) ...'
          % MROS_V1_ROOT, flush=True)
    app_root = os.path.join(build_root, 'app')
    program = build_app(MROS_V1_ROOT, app_root)
    directions = run(workspace, program, args.messages, app_root)
    print('\n==== the paper\'s evaluation on the real mROS v1 library (PC target, qemu-arm) ====')
    for direction in directions:
        print(direction.summary())
    passed = all(direction.problem is None for direction in directions)
    print('RESULT: %s' % ('PASS' if passed else 'FAIL'))
    return 0 if passed else 1


if __name__ == '__main__':
    sys.exit(main())
