#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""The ROS 2 node of the mros2 main job: real rclpy, against the board.

It takes the board's std_msgs/String and sensor_msgs/Image samples (the
Image over mros2's 100-byte buffer, written in fragments) as serialized
bytes and holds each against rosbags' serialization of the values the board
put in (evaluation/firmware_ros2/board_ros2.cpp), test_ws_ros2's Reading
too (rosbags reads its definition from the workspace's install), each with
mros2's zeros to a multiple of 4; and it publishes std_msgs/String,
geometry_msgs/Twist and Reading samples serialized by rclpy, which the
board decodes and publishes again on <topic>_echo: each must come back as
rosbags writes the values sent, padded as mros2 pads. (rclpy's own bytes
can differ from those in the padding between members, which its Fast-CDR
leaves as the buffer held it; the board writes zeros there, as rosbags.)
One line per topic; exits 0 only if every sample came and matched.

  ros2_peer.py [--count N] [--timeout SECONDS] [--best-effort] [--topics T,...]
               [--reliable-chatter]

With --best-effort (a board on mros2 itself, whose endpoints are best-effort) it is the
plain node (testing/mros2_pc_peer.py does the same with any samples): its endpoints are
best-effort too, and once the graph shows each of its publishers and subscriptions matched
with the board, it waits 3 s more, sends each sample once, 100 ms apart, and waits for the
replies; nothing is sent again. --topics checks only those topics. --reliable-chatter checks
chatter_reliable too (the board's reliable publisher of chatter's samples), with rclpy's
default QoS (reliable, keep last 10), as most nodes subscribe.

Runs with rclpy (the ROS 2 wheels' venv) and test_ws_ros2's Python
packages on the path; rosbags comes from the checkout's build/test-python.
"""

import argparse
import os
import sys
import threading
import time

import numpy
import rclpy
from geometry_msgs.msg import Twist, Vector3
from rclpy.node import Node
from rclpy.qos import QoSHistoryPolicy, QoSProfile, ReliabilityPolicy, qos_profile_default
from rclpy.serialization import serialize_message
from std_msgs.msg import String
from sensor_msgs.msg import Image
from mros2_base_msgs.msg import Stamp
from mros2_test_msgs.msg import Reading

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.append(os.path.join(REPO, 'build', 'test-python'))

from rosbags.typesys import Stores, get_types_from_msg, get_typestore  # noqa: E402

QOS = QoSProfile(depth=100, history=QoSHistoryPolicy.KEEP_LAST)
BEST_EFFORT = QoSProfile(depth=100, history=QoSHistoryPolicy.KEEP_LAST,
                         reliability=ReliabilityPolicy.BEST_EFFORT)

# The plain node's procedure (testing/mros2_pc.py): a wait once matched, and a sample's period.
SETTLE = 3.0
PERIOD = 0.1

TYPESTORE = get_typestore(Stores.ROS2_HUMBLE)
WORKSPACE_TYPES = (('mros2_base_msgs', 'Stamp'), ('mros2_test_msgs', 'Reading'))


def register_workspace_types():
    """rosbags learns test_ws_ros2's types from their installed definitions."""
    from ament_index_python.packages import get_package_share_directory
    types = {}
    for package, name in WORKSPACE_TYPES:
        path = os.path.join(get_package_share_directory(package), 'msg', name + '.msg')
        with open(path) as stream:
            types.update(get_types_from_msg(stream.read(), '%s/msg/%s' % (package, name)))
    TYPESTORE.register(types)


def rosbags_reading(reading):
    """The bytes rosbags writes for an rclpy Reading's values."""
    types = TYPESTORE.types
    value = types['mros2_test_msgs/msg/Reading'](
        stamp=types['mros2_base_msgs/msg/Stamp'](sec=reading.stamp.sec,
                                                 nanosec=reading.stamp.nanosec),
        sensor=reading.sensor, position=numpy.array(reading.position, dtype=numpy.float32),
        samples=numpy.array(reading.samples, dtype=numpy.int16), scale=reading.scale)
    return TYPESTORE.serialize_cdr(value, 'mros2_test_msgs/msg/Reading')


def padded(sample):
    """A sample as mros2 sends it: zeros to a multiple of 4."""
    return bytes(sample) + bytes(-len(sample) % 4)


def board_string(number):
    """What the board publishes on chatter, as rosbags serializes it."""
    String_ = TYPESTORE.types['std_msgs/msg/String']
    return TYPESTORE.serialize_cdr(String_(data='board sample %d' % number), 'std_msgs/msg/String')


def board_image(number):
    """What the board publishes on image, as rosbags serializes it."""
    types = TYPESTORE.types
    header = types['std_msgs/msg/Header'](
        stamp=types['builtin_interfaces/msg/Time'](sec=number, nanosec=1000 * number),
        frame_id='camera')
    data = numpy.array([(number + i) & 0xff for i in range(200)], dtype=numpy.uint8)
    image = types['sensor_msgs/msg/Image'](header=header, height=10, width=20, encoding='mono8',
                                           is_bigendian=0, step=20, data=data)
    return TYPESTORE.serialize_cdr(image, 'sensor_msgs/msg/Image')


def board_reading(number):
    """What the board publishes on reading, as rosbags serializes it."""
    return rosbags_reading(Reading(
        stamp=Stamp(sec=number, nanosec=7 * number), sensor='imu',
        position=[float(number), number + 0.5, -float(number)], samples=[number, -number]))


def reading_in(number):
    return Reading(stamp=Stamp(sec=-number, nanosec=number), sensor='lidar %d' % number,
                   position=[0.25, -0.5, 1e3], samples=list(range(number % 5)), scale=-2.0)


def command(number):
    return String(data='command %d for the board' % number)


def twist(number):
    return Twist(linear=Vector3(x=0.5 * number, y=-1.25, z=1e-3 * number),
                 angular=Vector3(x=0.0, y=float(number), z=-3.5))


class Topic:
    """Samples expected on one topic, and those that came."""

    def __init__(self, name, expected, what, qos=None):
        self.name = name
        self.expected = expected
        self.what = what
        self.qos = qos  # the peer's, where not its own
        self.received = []

    def receive(self, sample):
        self.received.append(bytes(sample))

    def done(self):
        return len(self.received) >= len(self.expected)

    def line(self):
        exact = sum(1 for got, want in zip(self.received, self.expected) if got == want)
        return '%s: %d of %d samples came, %d byte for byte %s' % (
            self.name, len(self.received), len(self.expected), exact, self.what), \
            exact == len(self.expected) == len(self.received)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    parser.add_argument('--count', type=int, default=20)
    parser.add_argument('--timeout', type=float, default=60)
    parser.add_argument('--best-effort', action='store_true')
    parser.add_argument('--topics', help='the topics to check (default: all)')
    parser.add_argument('--reliable-chatter', action='store_true')
    options = parser.parse_args()
    qos = BEST_EFFORT if options.best_effort else QOS
    count = options.count
    register_workspace_types()
    rclpy.init()
    node = Node('mros2_peer')
    sent_commands = [serialize_message(command(n)) for n in range(count)]
    sent_twists = [serialize_message(twist(n)) for n in range(count)]
    readings = [reading_in(n) for n in range(count)]
    sent_readings = [serialize_message(reading) for reading in readings]
    topics = [
        Topic('chatter', [padded(board_string(n)) for n in range(count)],
              "as rosbags writes the board's values"),
        Topic('image', [padded(board_image(n)) for n in range(count)],
              "as rosbags writes the board's values (in fragments from the board)"),
        Topic('reading', [padded(board_reading(n)) for n in range(count)],
              "as rosbags writes the board's values"),
        Topic('command_echo', [padded(sample) for sample in sent_commands],
              'as rclpy wrote them to command'),
        Topic('twist_echo', [padded(sample) for sample in sent_twists],
              'as rclpy wrote them to twist'),
        Topic('reading_in_echo', [padded(rosbags_reading(reading)) for reading in readings],
              'as rosbags writes the values rclpy sent to reading_in'),
    ]
    message_types = {'chatter': String, 'image': Image, 'reading': Reading,
                     'command_echo': String, 'twist_echo': Twist, 'reading_in_echo': Reading,
                     'chatter_reliable': String}
    if options.topics:
        topics = [topic for topic in topics if topic.name in options.topics.split(',')]
    if options.reliable_chatter:
        topics.append(Topic('chatter_reliable', [padded(board_string(n)) for n in range(count)],
                            "as rosbags writes the board's values (rclpy's default QoS)",
                            qos_profile_default))
    kept = [node.create_subscription(message_types[t.name], t.name, t.receive, t.qos or qos,
                                     raw=True)
            for t in topics]
    publishers = [(node.create_publisher(String, 'command', qos), sent_commands),
                  (node.create_publisher(Twist, 'twist', qos), sent_twists),
                  (node.create_publisher(Reading, 'reading_in', qos), sent_readings)]
    threading.Thread(target=rclpy.spin, args=(node,), daemon=True).start()
    deadline = time.monotonic() + options.timeout
    while (any(publisher.get_subscription_count() == 0 for publisher, _ in publishers) or
           options.best_effort and any(subscription.get_publisher_count() == 0
                                       for subscription in kept)) \
            and time.monotonic() < deadline:
        time.sleep(0.1)
    if options.best_effort:
        time.sleep(SETTLE)
    for number in range(count):
        for publisher, samples in publishers:
            publisher.publish(samples[number])
        time.sleep(PERIOD if options.best_effort else 0.05)
    while not all(topic.done() for topic in topics) and time.monotonic() < deadline:
        time.sleep(0.1)
    passed = True
    for topic in topics:
        line, matched = topic.line()
        print('peer: ' + line, flush=True)
        passed = passed and matched
    del kept
    return 0 if passed else 1


if __name__ == '__main__':
    sys.exit(main())
