# SPDX-License-Identifier: BSD-3-Clause
"""The rclpy side of bench/mros2/pc_round_trip.py: round trips and throughput against an
echo of std_msgs/String (to_stm -> to_linux unless named), best-effort as mros2's endpoints
are, or reliable and keeping all (--reliable).

    round_trip_peer.py TRIPS BURST [--to TOPIC] [--back TOPIC] [--reliable]

Sends "warm N" until an echo comes (discovery on both sides done), then TRIPS round trips
one at a time (each waits for its own echo; a lost one is sent again after 1 s and not
timed), then BURST strings as fast as rclpy publishes them, and counts the echoes that come
until 2 s after the last one. Prints JSON: {"round_trips_us": [...], "burst": BURST,
"echoed": n, "burst_seconds": first send to last echo}.
"""

import argparse
import json
import sys
import time

import rclpy
from rclpy.qos import HistoryPolicy, QoSProfile, ReliabilityPolicy
from std_msgs.msg import String

BEST_EFFORT = QoSProfile(depth=1000, reliability=ReliabilityPolicy.BEST_EFFORT)
RELIABLE = QoSProfile(history=HistoryPolicy.KEEP_ALL, reliability=ReliabilityPolicy.RELIABLE)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    parser.add_argument('trips', type=int)
    parser.add_argument('burst', type=int)
    parser.add_argument('--to', default='to_stm')
    parser.add_argument('--back', default='to_linux')
    parser.add_argument('--reliable', action='store_true')
    options = parser.parse_args()
    trips, burst = options.trips, options.burst
    qos = RELIABLE if options.reliable else BEST_EFFORT
    rclpy.init()
    node = rclpy.create_node('round_trip_peer')
    echoes = []
    node.create_subscription(String, options.back,
                             lambda message: echoes.append((time.monotonic(), message.data)), qos)
    publisher = node.create_publisher(String, options.to, qos)

    def wait_for(text, seconds):
        deadline = time.monotonic() + seconds
        while time.monotonic() < deadline:
            rclpy.spin_once(node, timeout_sec=0.001)
            for arrived, data in echoes:
                if data == text:
                    return arrived
        return None

    warm = 0
    while wait_for('warm %d' % (warm - 1), 0.5) is None:
        publisher.publish(String(data='warm %d' % warm))
        warm += 1
    round_trips = []
    for trip in range(trips):
        text = 'trip %d' % trip
        while True:
            sent = time.monotonic()
            publisher.publish(String(data=text))
            arrived = wait_for(text, 1.0)
            if arrived is not None:
                round_trips.append((arrived - sent) * 1e6)
                break
    del echoes[:]
    started = time.monotonic()
    for index in range(burst):
        publisher.publish(String(data='burst %d' % index))
        rclpy.spin_once(node, timeout_sec=0)
    last = time.monotonic()
    while time.monotonic() < last + 2.0:
        count = len(echoes)
        rclpy.spin_once(node, timeout_sec=0.01)
        if len(echoes) > count:
            last = time.monotonic()
    burst_echoes = [arrived for arrived, data in echoes if data.startswith('burst ')]
    json.dump({'round_trips_us': round_trips, 'burst': burst, 'echoed': len(burst_echoes),
               'burst_seconds': (max(burst_echoes) - started) if burst_echoes else None},
              sys.stdout)
    node.destroy_node()
    rclpy.shutdown()


if __name__ == '__main__':
    main()
