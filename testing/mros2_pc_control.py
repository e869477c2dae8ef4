# SPDX-License-Identifier: BSD-3-Clause
"""The control: an rclpy node in the board's place, doing what the soak's app does
(testing/mros2_pc_apps), so that the plain node (testing/mros2_pc_peer.py) meets a ROS 2 node
where it would meet the board. Whatever the board needs that the control does not (a longer
wait, a resend) is the board's defect.

stdin: JSON {"echo": [{"from": topic, "to": topic, "type": pkg/msg/Type, "change": "text",
"twist", "pose" or null}]}: each sample taken on "from" is changed as three_echoes changes it
(text: "echo: " before it; twist: linear.x + 1, angular.z doubled; pose: position.z + 1; null:
as it came, as fragment_echo echoes) and published on "to", best-effort as mros2's endpoints
are. Writes "app ready" to stdout once its endpoints exist, and runs until SIGINT or
SIGTERM.
"""

import json
import signal
import sys

import rclpy
from rclpy.signals import SignalHandlerOptions

# The plain node's, beside this script.
from mros2_pc_peer import BEST_EFFORT, message_class


def changed_text(message):
    message.data = 'echo: ' + message.data


def changed_twist(message):
    message.linear.x += 1
    message.angular.z *= 2


def changed_pose(message):
    message.position.z += 1


CHANGES = {'text': changed_text, 'twist': changed_twist, 'pose': changed_pose,
           None: lambda message: None}


def main():
    job = json.load(sys.stdin)
    stopped = []
    rclpy.init(signal_handler_options=SignalHandlerOptions.NO)
    for stop in (signal.SIGINT, signal.SIGTERM):
        signal.signal(stop, lambda *_: stopped.append(True))
    node = rclpy.create_node('genmros_control')
    for entry in job['echo']:
        kind = message_class(entry['type'])
        publisher = node.create_publisher(kind, entry['to'], BEST_EFFORT)
        change = CHANGES[entry['change']]

        def echo(message, publisher=publisher, change=change):
            change(message)
            publisher.publish(message)
        node.create_subscription(kind, entry['from'], echo, BEST_EFFORT)
    print('app ready', flush=True)
    while not stopped:
        rclpy.spin_once(node, timeout_sec=0.05)
    node.destroy_node()
    rclpy.shutdown()


if __name__ == '__main__':
    main()
