#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""The mros2 board's transport to the ROS 2 graph: an rclpy node.

The board (evaluation/firmware_ros2, genmros' mros2 headers and no DDS) runs
as a child of this node and speaks the records of evaluation/firmware's
ports over its standard input and output. For every topic the board
announces, this node publishes or subscribes on it with rclpy, under the
board's own DDS type name: it takes the rclpy message type that has that
name and refuses to relay a topic whose name no installed type has. Samples
pass through as serialized bytes, unread, both ways (rclpy's raw publish and
raw subscription): what a ROS 2 node receives is the board's encoding, and
what the board decodes is the ROS 2 node's. A sample the board publishes
before a ROS 2 subscriber matched waits here until one has.

  ros2_bridge.py COMMAND...     (e.g. qemu-arm build/board)

Runs with rclpy (the ROS 2 wheels' venv build/ros2-wheels).
"""

import importlib
import subprocess
import sys
import threading

import rclpy
from rclpy.node import Node
from rclpy.qos import QoSHistoryPolicy, QoSProfile

from board_records import read_records, write_message

QOS = QoSProfile(depth=100, history=QoSHistoryPolicy.KEEP_LAST)


def message_type(dds_type_name):
    """The rclpy type a DDS type name (pkg::msg::dds_::Name_) belongs to, or None."""
    parts = dds_type_name.split('::')
    if len(parts) != 4 or parts[2] != 'dds_' or not parts[3].endswith('_'):
        return None
    try:
        module = importlib.import_module('%s.%s' % (parts[0], parts[1]))
    except ImportError:
        return None
    return getattr(module, parts[3][:-1], None)


class Bridge(Node):
    def __init__(self, command):
        super().__init__('mros2_board')
        self.board = subprocess.Popen(command, stdin=subprocess.PIPE, stdout=subprocess.PIPE)
        self.to_board = threading.Lock()
        self.publishers_by_topic = {}
        self.waiting = {}
        self.waiting_lock = threading.Lock()
        self.subscriptions_kept = []
        self.create_timer(0.1, self.flush_waiting)

    def forward_to_board(self, index):
        def callback(sample):
            with self.to_board:
                write_message(self.board.stdin, index, sample)
        return callback

    def announce(self, index, body):
        name, type_name, _, _, role = body.decode().split('\0')
        rclpy_type = message_type(type_name)
        if rclpy_type is None:
            print('bridge: %s (%s): no installed ROS 2 type has this name: not relayed'
                  % (name, type_name), flush=True)
            return
        if role == 'P':
            self.publishers_by_topic[index] = self.create_publisher(rclpy_type, name, QOS)
            self.waiting[index] = []
        else:
            self.subscriptions_kept.append(self.create_subscription(
                rclpy_type, name, self.forward_to_board(index), QOS, raw=True))
        print('bridge: the board %s %s (%s)' % ('publishes' if role == 'P' else 'subscribes to',
                                                name, type_name), flush=True)

    def publish(self, index, sample):
        """Publish, or keep the sample until the topic has a subscriber."""
        with self.waiting_lock:
            self.waiting[index].append(sample)
            self.flush(index)

    def flush(self, index):
        publisher = self.publishers_by_topic[index]
        if self.waiting[index] and publisher.get_subscription_count() > 0:
            for sample in self.waiting[index]:
                publisher.publish(sample)
            self.waiting[index] = []

    def flush_waiting(self):
        with self.waiting_lock:
            for index in self.waiting:
                self.flush(index)

    def relay(self):
        """Relays the board's records until it stops; returns its exit status."""
        for kind, index, body in read_records(self.board.stdout):
            if kind == b'T':
                self.announce(index, body)
            elif kind == b'M' and index in self.publishers_by_topic:
                self.publish(index, body)
        return self.board.wait()


def main():
    command = sys.argv[1:]
    if not command:
        print(__doc__.strip().splitlines()[-3], file=sys.stderr)
        return 2
    rclpy.init()
    bridge = Bridge(command)
    threading.Thread(target=rclpy.spin, args=(bridge,), daemon=True).start()
    status = bridge.relay()
    print('bridge: the board stopped (exit status %d)' % status, flush=True)
    return 0 if status == 0 else 1


if __name__ == '__main__':
    sys.exit(main())
