#!/usr/bin/env python3
"""The paper's evaluation (section 6.2) on Linux, against a real rosmaster and
real ROS nodes: the mROS node of Fig. 6 publishes mros_test/PersonalData
("Phil", "Woods", 83, score counting up) and a rospy and a roscpp node print
what they receive; then a rospy and a roscpp node publish ("Charlie",
"Parker", 32, ...) and the mROS node of Fig. 7 prints it. Exits 0 only if
every direction delivered the right values in order.

  posix_evaluation.py [--messages N] [--build-dir DIR]

Builds test_ws (catkin_make) and the sample firmware (CMake) first, in
DIR or in a temporary directory. With an mROS v1 checkout (MROS_V1_ROOT,
default ../shared/mros_v1) it also runs the evaluation as an mROS v1 app on
the real library (tests/mros_v1_pc_evaluation.py) and prints both tables."""

import argparse
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

import posix_builds  # noqa: E402
from ros_processes import RosGraph, sourced_environment  # noqa: E402

ROS_HEARD = re.compile(r'I heard from mROS: (\S*) (\S*) age:(\d+) score:(-?\d+)')
MROS_HEARD = re.compile(r'name:(.*)$')
MROS_AGE = re.compile(r'age:(\d+)$')
MROS_SCORE = re.compile(r'score:(-?\d+)$')


class Direction:
    """One sender -> receiver run and what the receiver printed."""

    def __init__(self, title, expected_name, expected_age, first_score):
        self.title = title
        self.expected = (expected_name, expected_age)
        self.first_score = first_score
        self.received = []  # (name, age, score)
        self.problem = None

    def check(self, count):
        if len(self.received) < count:
            self.problem = 'received %d of %d messages' % (len(self.received), count)
            return
        scores = [score for _, _, score in self.received]
        for name, age, score in self.received:
            if (name, age) != self.expected or score < self.first_score:
                self.problem = 'wrong values: %s age:%d score:%d' % (name, age, score)
                return
        if any(later != earlier + 1 for earlier, later in zip(scores, scores[1:])):
            self.problem = 'scores not counting up by one: %s' % scores

    def summary(self):
        name, age = self.expected
        scores = [score for _, _, score in self.received]
        values = '%s, age %d, score %s..%s' % (name, age, scores[0] if scores else '-',
                                               scores[-1] if scores else '-')
        return '%-26s %2d messages  %-40s %s' % (
            self.title, len(self.received), values,
            'PASS' if self.problem is None else 'FAIL: ' + self.problem)


def show(process, last=12):
    print('---- %s (last lines) ----' % process.name)
    for line in process.lines()[-last:]:
        print('  ' + line)


def start_ros_listeners(graph, workspace):
    """The rospy and roscpp listeners of mros_str, registered at the master:
    [(direction title, process)]."""
    listeners = [
        ('mROS -> rospy listener', graph.start('rospy personal_data_listener.py',
                                               workspace.rospy('personal_data_listener.py'))),
        ('mROS -> roscpp listener', graph.start('roscpp personal_data_listener',
                                                workspace.roscpp('personal_data_listener'))),
    ]
    graph.wait_for_graph(subscribers=[('/mros_str', '/rospy_personal_listener'),
                                      ('/mros_str', '/ros_personal_listener')])
    return listeners


def ros_heard(matches):
    """(name, age, score) of each ROS_HEARD match."""
    return [('%s %s' % (m.group(1), m.group(2)), int(m.group(3)), int(m.group(4)))
            for m in matches]


def mros_to_ros(graph, workspace, firmware, count):
    directions = []
    listeners = start_ros_listeners(graph, workspace)
    talker = graph.start('mROS talker (Fig. 6)', firmware.node('mros_personal_talker'))
    for title, listener in listeners:
        direction = Direction(title, 'Phil Woods', 83, 100000)
        try:
            matches = listener.wait_for(ROS_HEARD.pattern, timeout=20, count=count)
            direction.received = ros_heard(matches)
        except AssertionError:
            pass
        direction.check(count)
        directions.append(direction)
    talker.stop()
    for _, listener in listeners:
        listener.stop()
        show(listener)
    show(talker, last=4)
    return directions


def ros_to_mros(graph, workspace, firmware, count):
    directions = []
    listener = graph.start('mROS listener (Fig. 7)', firmware.node('mros_personal_listener'))
    graph.wait_for_graph(subscribers=[('/test_msg', '/mros_node2')])
    talkers = [
        ('rospy talker -> mROS', 'rospy personal_data_talker.py',
         workspace.rospy('personal_data_talker.py')),
        ('roscpp talker -> mROS', 'roscpp personal_data_talker',
         workspace.roscpp('personal_data_talker')),
    ]
    for title, name, argv in talkers:
        start = len(listener.lines())
        talker = graph.start(name, argv)
        direction = Direction(title, 'Charlie Parker', 32, 100100)
        try:
            listener.wait_for(MROS_SCORE.pattern, timeout=20, start=start, count=count)
        except AssertionError:
            pass
        talker.stop()
        direction.received = parse_mros_listener(listener.lines()[start:])[:count]
        direction.check(count)
        directions.append(direction)
        show(talker, last=3)
    listener.stop()
    show(listener, last=8)
    return directions


def parse_mros_listener(lines):
    """(name, age, score) of every complete name/age/score group."""
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


def run(workspace, firmware, count):
    """Both directions; returns the Direction results."""
    env = sourced_environment(workspace.setup_bash)
    with RosGraph(env) as graph:
        print('rosmaster at %s' % graph.uri)
        directions = mros_to_ros(graph, workspace, firmware, count)
        directions += ros_to_mros(graph, workspace, firmware, count)
    return directions


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    parser.add_argument('--messages', type=int, default=5,
                        help='messages each receiver must print (default 5)')
    parser.add_argument('--build-dir', help='keep the builds here (default: a temporary dir)')
    args = parser.parse_args()
    ws_root = fw_root = None
    if args.build_dir:
        ws_root = os.path.join(os.path.abspath(args.build_dir), 'test_ws')
        fw_root = os.path.join(os.path.abspath(args.build_dir), 'firmware')
        os.makedirs(ws_root, exist_ok=True)
        os.makedirs(fw_root, exist_ok=True)
    print('building test_ws with catkin_make (genmros exporting to mros_export/) ...', flush=True)
    workspace = posix_builds.workspace(ws_root)
    print('building the sample firmware (POSIX target) with CMake and '
          'cmake/mros_generate.cmake ...', flush=True)
    firmware = posix_builds.firmware(workspace.mros_export, fw_root)
    tables = [('mROS POSIX evaluation (paper section 6.2)',
               run(workspace, firmware, args.messages))]
    # Imported here: it imports this module's checks.
    import mros_v1_pc_evaluation
    if mros_v1_pc_evaluation.checkout_found():
        print('building the evaluation as an mROS v1 app with the real library of %s '
              '(genmros mros-v1-pc) ...' % mros_v1_pc_evaluation.MROS_V1_ROOT, flush=True)
        scratch = posix_builds.scratch('mros_v1_pc_')
        program = mros_v1_pc_evaluation.build_app(mros_v1_pc_evaluation.MROS_V1_ROOT, scratch)
        tables.append(('the real mROS v1 library on the PC target (qemu-arm)',
                       mros_v1_pc_evaluation.run(workspace, program, args.messages, scratch)))
    else:
        print('\nno mROS v1 checkout at %s: set MROS_V1_ROOT=<checkout> to also run the '
              'evaluation on the real mROS v1 library' % mros_v1_pc_evaluation.MROS_V1_ROOT)
    passed = True
    for title, directions in tables:
        print('\n==== %s ====' % title)
        for direction in directions:
            print(direction.summary())
        passed = passed and all(direction.problem is None for direction in directions)
    print('RESULT: %s' % ('PASS' if passed else 'FAIL'))
    return 0 if passed else 1


if __name__ == '__main__':
    sys.exit(main())
