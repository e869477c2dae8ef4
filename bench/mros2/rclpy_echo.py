# SPDX-License-Identifier: BSD-3-Clause
"""An rclpy node that does what mros2-posix' echoreply_string does: every std_msgs/String
on to_stm published again on to_linux, best-effort. bench/mros2/pc_round_trip.py runs it
for the rclpy <-> rclpy round trip it shows for orientation; stops on SIGTERM."""

import signal

import rclpy
from rclpy.qos import QoSProfile, ReliabilityPolicy
from rclpy.signals import SignalHandlerOptions
from std_msgs.msg import String

QOS = QoSProfile(depth=1000, reliability=ReliabilityPolicy.BEST_EFFORT)


def main():
    rclpy.init(signal_handler_options=SignalHandlerOptions.NO)
    stopped = []
    signal.signal(signal.SIGTERM, lambda *_: stopped.append(True))
    node = rclpy.create_node('rclpy_echo')
    publisher = node.create_publisher(String, 'to_linux', QOS)
    node.create_subscription(String, 'to_stm', publisher.publish, QOS)
    while not stopped:
        rclpy.spin_once(node, timeout_sec=0.1)
    node.destroy_node()
    rclpy.shutdown()


if __name__ == '__main__':
    main()
