# SPDX-License-Identifier: BSD-3-Clause
"""The plain node: an rclpy node that does what an ordinary ROS 2 user's node does, on the
ROS side of a genmros mros2-pc board (or of its control, testing/mros2_pc_control.py), for
the tests, the main job and the bench (testing/mros2_pc.py runs it in the ROS 2 wheels' venv).

It makes one publisher and one subscription per topic, each with its QoS: best-effort as
mros2's endpoints are unless told (``qos``: ``best_effort``; ``default``, rclpy's default QoS,
reliable and keeping the last 10; ``keep_all``, reliable and keeping all), and waits through
the graph API until every one of them sees the other side (``get_subscription_count()``,
``count_publishers()``); then waits ``settle`` seconds more; then publishes each sample once,
``period`` seconds apart (one sample of each topic in turn); then waits up to ``reply_wait``
seconds for what comes back, ending that wait early once each topic of ``expect`` has taken
its count. Nothing is sent again: a sample lost is lost.

stdin: JSON {"publish": [{"topic", "type" (pkg/msg/Type), "qos", "samples": [hex of serialized
messages]}], "subscribe": [{"topic", "type", "qos"}], "expect": {topic: count}, "period",
"settle", "reply_wait", "match_wait": seconds}. Writes "peer ready" to stderr once its
endpoints exist, and "peer matched" once the graph shows them matched. stdout: JSON
{"received": {topic: [hex of each sample as it came]}, "sent": count, "matched": whether the
graph showed every endpoint matched, "matched_after": seconds from the node's start until it
did}. SIGTERM ends any wait, and it reports.
"""

import importlib
import json
import signal
import sys
import time

import rclpy
from rclpy.qos import HistoryPolicy, QoSProfile, ReliabilityPolicy, qos_profile_default
from rclpy.signals import SignalHandlerOptions


# mros2's endpoints as they are.
BEST_EFFORT = QoSProfile(depth=100, reliability=ReliabilityPolicy.BEST_EFFORT)
QOS = {
    'best_effort': BEST_EFFORT,
    # What a node gets that names a depth alone, as most do.
    'default': qos_profile_default,
    'keep_all': QoSProfile(history=HistoryPolicy.KEEP_ALL,
                           reliability=ReliabilityPolicy.RELIABLE),
}


def message_class(type_name):
    package, _, name = type_name.split('/')
    return getattr(importlib.import_module('%s.msg' % package), name)


class PlainNode:
    """The node and what it has received."""

    def __init__(self, job, stopped):
        self.job = job
        self.stopped = stopped
        self.node = rclpy.create_node('genmros_plain_node')
        self.received = {entry['topic']: [] for entry in job['subscribe']}
        for entry in job['subscribe']:
            self.node.create_subscription(
                message_class(entry['type']), entry['topic'],
                lambda raw, topic=entry['topic']: self.received[topic].append(bytes(raw).hex()),
                QOS[entry['qos']], raw=True)
        self.publishers = [self.node.create_publisher(message_class(entry['type']),
                                                      entry['topic'], QOS[entry['qos']])
                           for entry in job['publish']]

    def spin_until(self, deadline, done=lambda: False):
        """Spins until done() holds, the deadline (monotonic) passes or SIGTERM comes; says
        whether done() held."""
        while not self.stopped and time.monotonic() < deadline:
            if done():
                return True
            rclpy.spin_once(self.node, timeout_sec=0.02)
        return done()

    def all_matched(self):
        return all(publisher.get_subscription_count() > 0 for publisher in self.publishers) \
            and all(self.node.count_publishers(topic) > 0 for topic in self.received)

    def all_expected(self):
        return all(len(self.received[topic]) >= count
                   for topic, count in self.job['expect'].items())


def main():
    job = json.load(sys.stdin)
    started = time.monotonic()
    stopped = []
    # rclpy's own handlers would shut its context down under the waits.
    rclpy.init(signal_handler_options=SignalHandlerOptions.NO)
    signal.signal(signal.SIGTERM, lambda *_: stopped.append(True))
    plain = PlainNode(job, stopped)
    print('peer ready', file=sys.stderr, flush=True)
    matched = plain.spin_until(time.monotonic() + job['match_wait'], plain.all_matched)
    matched_after = time.monotonic() - started
    if matched:
        print('peer matched', file=sys.stderr, flush=True)
    sent = 0
    if matched:
        plain.spin_until(time.monotonic() + job['settle'])
        rounds = max((len(entry['samples']) for entry in job['publish']), default=0)
        for index in range(rounds):
            for publisher, entry in zip(plain.publishers, job['publish']):
                if index < len(entry['samples']) and not stopped:
                    publisher.publish(bytes.fromhex(entry['samples'][index]))
                    sent += 1
            plain.spin_until(time.monotonic() + job['period'])
        plain.spin_until(time.monotonic() + job['reply_wait'], plain.all_expected)
    json.dump({'received': plain.received, 'sent': sent, 'matched': matched,
               'matched_after': matched_after}, sys.stdout)
    plain.node.destroy_node()
    rclpy.shutdown()


if __name__ == '__main__':
    main()
