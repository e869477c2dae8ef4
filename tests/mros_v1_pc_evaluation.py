"""The real mROS v1 library on the PC target, shared by its tests and the
evaluation script: where the checkout is, an app running in a ROS graph
(Board), and the paper's evaluation (section 6.2) as an mROS v1 app
(tests/fixtures/mros_v1_pc_app/personal_data.cpp) with the same directions and checks as the
POSIX runtime's, plus on-board delivery.

The library ignores publishers at its own address, and roscpp with a
loopback ROS_IP takes TCPROS connections on 127.0.0.1 only: apps run with
ROS_IP=127.0.0.2, ROS nodes with 127.0.0.1.
"""

import os
import re
import subprocess
import sys
import time

from posix_evaluation import (ROS_HEARD, Direction, parse_mros_listener, ros_heard,
                              start_ros_listeners)
from ros_processes import RosGraph, free_port, sourced_environment

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
TEST_WS = os.path.join(REPO, 'test_ws')
MROS_V1_ROOT = os.environ.get('MROS_V1_ROOT') or os.path.join(os.path.dirname(REPO), 'shared',
                                                              'mros_v1')
BOARD_IP = '127.0.0.2'
PEER_IP = '127.0.0.1'
# How long a message may take through qemu, the library's 100 ms polling
# and a loaded machine.
DELIVERY_TIMEOUT = 30
APP_FIXTURE = os.path.join(REPO, 'tests', 'fixtures', 'mros_v1_pc_app')


def checkout_found(root=MROS_V1_ROOT):
    return os.path.isfile(os.path.join(root, 'mros-lib', 'Makefile.m'))


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


def _direction(title, name, age, first_score, received, count):
    direction = Direction(title, name, age, first_score)
    direction.received = received[:count]
    direction.check(count)
    return direction


def _waited(process, pattern, count, start=0):
    """The matches of pattern once count are there, or what came in time."""
    try:
        return process.wait_for(pattern, timeout=DELIVERY_TIMEOUT, start=start, count=count)
    except AssertionError:
        return [m for m in map(re.compile(pattern).search, process.lines()[start:]) if m]


def run(workspace, program, count, scratch):
    """The evaluation's directions, each a posix_evaluation.Direction."""
    environment = sourced_environment(workspace.setup_bash)
    directions = []
    with RosGraph(environment) as graph:
        listeners = start_ros_listeners(graph, workspace)
        board = Board(graph, program, scratch)
        for title, listener in listeners:
            directions.append(_direction(title, 'Phil Woods', 83, 100000,
                                         ros_heard(_waited(listener, ROS_HEARD.pattern, count)),
                                         count))
        matches = _waited(board.process, r'on board: (\S+ \S+) (\d+) (-?\d+)', count)
        directions.append(_direction('mROS -> mROS on board', 'Phil Woods', 83, 100000,
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
            directions.append(_direction('%s talker -> mROS' % talker, 'Charlie Parker', 32, 100100,
                                         parse_mros_listener(board.process.lines()[start:]),
                                         count))
    return directions
