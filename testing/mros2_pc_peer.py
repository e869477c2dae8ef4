# SPDX-License-Identifier: BSD-3-Clause
"""An rclpy node on the ROS side of a genmros mros2-pc board, for the tests, the main job
and the bench (testing/mros2_pc.py runs it in the ROS 2 wheels' venv).

stdin: JSON {"publish": [{"topic", "type" (pkg/msg/Type), "samples": [hex of serialized
messages]}], "subscribe": [{"topic", "type"}], "want": {topic: samples},
"period": seconds between publishes, "timeout": seconds}. Publishes the samples in turn,
best-effort as mros2's endpoints are, until each topic of "want" has taken its samples,
the time-out passes or SIGTERM comes. Writes "peer ready" to stderr once its endpoints
exist. stdout: JSON {"received": {topic: [hex of each sample as it came]}, "sent": count}.
"""

import importlib
import json
import signal
import sys
import time

import rclpy
from rclpy.qos import QoSProfile, ReliabilityPolicy
from rclpy.signals import SignalHandlerOptions


def message_class(type_name):
    package, _, name = type_name.split('/')
    return getattr(importlib.import_module('%s.msg' % package), name)


def main():
    job = json.load(sys.stdin)
    stopped = []
    # rclpy's own handlers would shut its context down under the loop.
    rclpy.init(signal_handler_options=SignalHandlerOptions.NO)
    signal.signal(signal.SIGTERM, lambda *_: stopped.append(True))
    node = rclpy.create_node('genmros_pc_peer')
    qos = QoSProfile(depth=100, reliability=ReliabilityPolicy.BEST_EFFORT)
    received = {entry['topic']: [] for entry in job['subscribe']}
    for entry in job['subscribe']:
        node.create_subscription(message_class(entry['type']), entry['topic'],
                                 lambda raw, topic=entry['topic']: received[topic].append(
                                     bytes(raw).hex()), qos, raw=True)
    # One publisher (one writer) per topic, as a node has.
    publishers = [node.create_publisher(message_class(entry['type']), entry['topic'], qos)
                  for entry in job['publish']]
    outgoing = [(publisher, bytes.fromhex(sample))
                for publisher, entry in zip(publishers, job['publish'])
                for sample in entry['samples']]
    print('peer ready', file=sys.stderr, flush=True)
    deadline = time.monotonic() + job['timeout']
    sent = 0
    while not stopped and time.monotonic() < deadline:
        if job['want'] and all(len(received[topic]) >= count
                               for topic, count in job['want'].items()):
            break
        if outgoing:
            publisher, sample = outgoing[sent % len(outgoing)]
            publisher.publish(sample)
            sent += 1
        publish_at = time.monotonic() + job['period']
        while not stopped and time.monotonic() < publish_at:
            rclpy.spin_once(node, timeout_sec=0.02)
    json.dump({'received': received, 'sent': sent}, sys.stdout)
    node.destroy_node()
    rclpy.shutdown()


if __name__ == '__main__':
    main()
