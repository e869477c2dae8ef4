# SPDX-License-Identifier: BSD-3-Clause
"""The paper's evaluation (section 6.2, Fig. 6, 7 and 9) as both runs of the
main job check it: the board publishes mros_test/PersonalData ("Phil Woods",
83, score counting up from 100000) to rospy and roscpp listeners, and rospy
and roscpp talkers publish ("Charlie Parker", 32, score counting up from
100100) to the board. A Direction is one sender -> receiver run."""

import re

ROS_HEARD = re.compile(r'I heard from mROS: (\S*) (\S*) age:(\d+) score:(-?\d+)')
BOARD = ('Phil Woods', 83, 100000)
ROS = ('Charlie Parker', 32, 100100)


class Direction:
    """One sender -> receiver run and what the receiver printed:
    received is [(name, age, score)]."""

    def __init__(self, title, sender, received, count):
        self.title = title
        self.expected_name, self.expected_age, first_score = sender
        self.received = received[:count]
        self.problem = self._problem(first_score, count)

    def _problem(self, first_score, count):
        if len(self.received) < count:
            return 'received %d of %d messages' % (len(self.received), count)
        for name, age, score in self.received:
            if (name, age) != (self.expected_name, self.expected_age) or score < first_score:
                return 'wrong values: %s age:%d score:%d' % (name, age, score)
        scores = [score for _, _, score in self.received]
        if any(later != earlier + 1 for earlier, later in zip(scores, scores[1:])):
            return 'scores not counting up by one: %s' % scores
        return None

    def detail(self):
        scores = [score for _, _, score in self.received]
        return '%d messages: %s, age %d, score %s..%s' % (
            len(self.received), self.expected_name, self.expected_age,
            scores[0] if scores else '-', scores[-1] if scores else '-')


def ros_heard(lines):
    """(name, age, score) of every message a personal_data_listener printed."""
    return [('%s %s' % (m.group(1), m.group(2)), int(m.group(3)), int(m.group(4)))
            for m in map(ROS_HEARD.search, lines) if m]


def start_listeners(graph, workspace, sender):
    """The rospy and roscpp personal_data_listeners in graph, registered at
    its master: [(the direction's title, the node)], sender naming the board."""
    listeners = [
        ('%s -> rospy listener' % sender, graph.start(
            'rospy personal_data_listener.py', workspace.rospy('personal_data_listener.py'))),
        ('%s -> roscpp listener' % sender, graph.start(
            'roscpp personal_data_listener', workspace.roscpp('personal_data_listener'))),
    ]
    graph.wait_for_graph(subscribers=[('/mros_str', '/rospy_personal_listener'),
                                      ('/mros_str', '/ros_personal_listener')])
    return listeners
