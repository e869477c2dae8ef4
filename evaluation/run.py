#!/usr/bin/env python3
"""The paper's evaluation (section 6.2) on the real mROS v1 library, run by
the PC target as users run it (genmros mros-v1-pc), against a real rosmaster
and real ROS nodes. The app (evaluation/app/app.cpp) is Fig. 6 and Fig. 7
written for mROS v1: it publishes mros_test/PersonalData ("Phil", "Woods",
83, score counting up), which a rospy and a roscpp node print and which the
library also delivers on the board; then a rospy and a roscpp node publish
("Charlie", "Parker", 32, ...) and the app prints it. Exits 0 only if every
direction delivered the right values in order.

  run.py [--messages N] [--build-dir DIR] [--workspace DIR]

Builds test_ws (catkin_make; --workspace: one built already) and the app
first, in DIR or in a temporary directory, with the installed genmros
(scripts/run-evaluation.sh installs it). The mROS v1 checkout is
MROS_V1_ROOT (run-evaluation.sh: default ../shared/mros_v1 beside this
repository).
"""

import argparse
import os
import re
import shutil
import subprocess
import sys
import tempfile

from colcon_mros.mros_v1.pc_target.ros_graph import (DELIVERY_TIMEOUT, Board, CatkinWorkspace,
                                                      RosGraph)

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
TEST_WS_SRC = os.path.join(REPO, 'test_ws', 'src')
APP = os.path.join(REPO, 'evaluation', 'app')
NODES_PACKAGE = 'mros_test_nodes'
# What the app takes from a sample app, as a new app does: the library's
# tasks and memory pools, and the declarations of the user tasks.
SAMPLE_FILES = ('mros_config', 'app.h')


def build_workspace(root):
    """test_ws's packages copied to root and built: the ROS nodes."""
    shutil.copytree(TEST_WS_SRC, os.path.join(root, 'src'), dirs_exist_ok=True)
    return CatkinWorkspace(root, NODES_PACKAGE).build(
        os.path.join(root, 'catkin_make.log'), '-DCMAKE_BUILD_TYPE=Release', '-j2')


def build_app(mros_root, build_root):
    """The app in build_root/app, with custom_pubsub's mros_config/ and
    app.h (the user tasks' declarations) linked in, built for qemu-arm;
    returns the program."""
    app = os.path.join(build_root, 'app')
    shutil.copytree(APP, app, dirs_exist_ok=True)
    for name in SAMPLE_FILES:
        if not os.path.lexists(os.path.join(app, name)):
            os.symlink(os.path.join(mros_root, 'mros_ws', 'custom_pubsub', name),
                       os.path.join(app, name))
    output = os.path.join(build_root, 'build')
    subprocess.run(['genmros', 'mros-v1-pc', app, '--mros-root', mros_root, '--msg-path',
                    TEST_WS_SRC, '-o', output, '--type', 'mros_test/PersonalData', '-j2'],
                   check=True)
    return os.path.join(output, 'personal_data')


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
    """Every direction of the evaluation: a list of Direction, and the
    boards that ran them."""
    environment = workspace.environment()
    directions = []
    boards = []
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
        boards.append(board)
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
            boards.append(board)
            graph.wait_for_graph(subscribers=[('/test_msg', '/mros_node2')])
            start = len(board.process.lines())
            graph.start('%s talker' % talker, argv)
            _waited(board.process, r'\] score:', count, start)
            directions.append(Direction('%s talker -> mROS' % talker, 'Charlie Parker', 32, 100100,
                                        parse_mros_listener(board.process.lines()[start:]),
                                        count))
    return directions, boards


def stack_peaks(boards):
    """{task: (the largest peak of its stack over the boards' last reports,
    its size)}: the reports each board prints when it is stopped."""
    peaks = {}
    for board in boards:
        reports = board.stack_reports()
        for task, (peak, size) in (reports[-1] if reports else {}).items():
            known = peaks.get(task, (None, size))[0]
            peaks[task] = (max(p for p in (known, peak, 0) if p is not None), size)
    return peaks


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[1])
    parser.add_argument('--messages', type=int, default=5,
                        help='messages each receiver must print (default 5)')
    parser.add_argument('--build-dir', help='keep the builds here (default: a temporary dir)')
    parser.add_argument('--workspace', metavar='DIR',
                        help='a copy of test_ws built already with catkin_make (default: build one)')
    args = parser.parse_args()
    mros_root = os.environ.get('MROS_V1_ROOT', '')
    if not os.path.isfile(os.path.join(mros_root, 'mros-lib', 'Makefile.m')):
        print("evaluation: no mROS v1 checkout at '%s' (mros-lib/Makefile.m): set "
              'MROS_V1_ROOT=<checkout of mROS-base/mROS>' % mros_root, file=sys.stderr)
        return 1
    with tempfile.TemporaryDirectory(prefix='mros_evaluation_') as scratch:
        build_root = os.path.abspath(args.build_dir or scratch)
        if args.workspace:
            workspace = CatkinWorkspace(os.path.abspath(args.workspace), NODES_PACKAGE)
        else:
            print('building test_ws with catkin_make (genmros beside gencpp and genpy) ...',
                  flush=True)
            workspace = build_workspace(os.path.join(build_root, 'test_ws'))
        print('building the evaluation app with the mROS v1 library of %s (genmros mros-v1-pc) ...'
              % mros_root, flush=True)
        program = build_app(mros_root, os.path.join(build_root, 'app'))
        directions, boards = run(workspace, program, args.messages, build_root)
    print("\nthe board's task stacks, the deepest of its runs (bytes):")
    for task, (peak, size) in stack_peaks(boards).items():
        print('  %-14s %5d of %5d' % (task, peak, size))
    print("\n==== the paper's evaluation on the real mROS v1 library (PC target, qemu-arm) ====")
    for direction in directions:
        print(direction.summary())
    passed = all(direction.problem is None for direction in directions)
    print('RESULT: %s' % ('PASS' if passed else 'FAIL'))
    return 0 if passed else 1


if __name__ == '__main__':
    sys.exit(main())
