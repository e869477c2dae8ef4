# SPDX-License-Identifier: BSD-3-Clause
"""The paper's evaluation on the user's mROS v1 library (MROS_V1_ROOT), run
by the PC target as users run it (genmros mros-v1-pc) under qemu-arm,
against a real rosmaster and real ROS nodes. The app (evaluation/app/app.cpp)
is Fig. 6 and Fig. 7 written for mROS v1; the library also delivers what it
publishes on the board. Five directions: the board to a rospy and a roscpp
listener and to itself, a rospy and a roscpp talker to the board."""

import os
import re
import shutil
import subprocess

from testing.ros_graph import DELIVERY_TIMEOUT, Board, RosGraph

from paper import BOARD, ROS, ROS_HEARD, Direction, ros_heard, start_listeners

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
TEST_WS_SRC = os.path.join(REPO, 'test_ws', 'src')
APP = os.path.join(REPO, 'evaluation', 'app')
# What the app takes from a sample app, as a new app does: the library's
# tasks and memory pools, and the declarations of the user tasks.
SAMPLE_FILES = ('mros_config', 'app.h')

MROS_HEARD = re.compile(r'name:(.*)$')
MROS_AGE = re.compile(r'age:(\d+)$')
MROS_SCORE = re.compile(r'score:(-?\d+)$')


def checkout_found(mros_root):
    return bool(mros_root) and os.path.isfile(os.path.join(mros_root, 'mros-lib', 'Makefile.m'))


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
    with open(os.path.join(build_root, 'mros-v1-pc.log'), 'w') as log:
        result = subprocess.run(['genmros', 'mros-v1-pc', app, '--mros-v1-root', mros_root,
                                 '--workspace', TEST_WS_SRC, '-o', output,
                                 '--type', 'mros_test/PersonalData', '-j2', '--build-only'],
                                stdout=log, stderr=subprocess.STDOUT)
    if result.returncode != 0:
        raise RuntimeError('genmros mros-v1-pc failed: see %s' % log.name)
    return os.path.join(output, 'personal_data')


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
        listeners = start_listeners(graph, workspace, 'mROS v1')
        board = Board(graph, program, scratch)
        boards.append(board)
        for title, listener in listeners:
            _waited(listener, ROS_HEARD.pattern, count)
            directions.append(Direction(title, BOARD, ros_heard(listener.lines()), count))
        matches = _waited(board.process, r'on board: (\S+ \S+) (\d+) (-?\d+)', count)
        directions.append(Direction('mROS v1 -> mROS v1 on board', BOARD,
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
            directions.append(Direction('%s talker -> mROS v1' % talker, ROS,
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
