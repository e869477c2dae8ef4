# SPDX-License-Identifier: BSD-3-Clause
"""rclpy's side of bench/mros2/service_round_trip.py (the ROS 2 wheels' venv).

    service_call_peer.py call CALLS   calls parameter_types (rcl_interfaces/srv/
                                      GetParameterTypes) CALLS times, one at a time, and
                                      prints JSON: {"round_trips_us": [...], "right": count}
    service_call_peer.py serve        serves parameter_types as testing/mros2_pc_apps/
                                      service_pair does (a name's type is its length), the
                                      rclpy <-> rclpy orientation; stops on SIGTERM

Call i asks for the names "call i" and i % 100 times "x"; a reply is right when its types
are those names' lengths. rclpy's default services QoS (reliable) throughout."""

import json
import signal
import sys
import time

import rclpy
from rcl_interfaces.srv import GetParameterTypes
from rclpy.signals import SignalHandlerOptions

SERVICE = 'parameter_types'
WAIT_SECONDS = 180


def name_lengths(request, response):
    response.types = [len(name) for name in request.names]
    return response


def call(node, calls):
    client = node.create_client(GetParameterTypes, SERVICE)
    if not client.wait_for_service(timeout_sec=WAIT_SECONDS):
        raise SystemExit('no %s service' % SERVICE)
    round_trips, right = [], 0
    for i in range(calls):
        request = GetParameterTypes.Request()
        request.names = ['call %d' % i, 'x' * (i % 100)]
        start = time.perf_counter()
        future = client.call_async(request)
        rclpy.spin_until_future_complete(node, future, timeout_sec=WAIT_SECONDS)
        round_trips.append((time.perf_counter() - start) * 1e6)
        lengths = [len(name) for name in request.names]
        if future.done() and list(future.result().types) == lengths:
            right += 1
    json.dump({'round_trips_us': round_trips, 'right': right}, sys.stdout)
    print(flush=True)


def serve(node):
    stopped = []
    signal.signal(signal.SIGTERM, lambda *_: stopped.append(True))
    node.create_service(GetParameterTypes, SERVICE, name_lengths)
    while not stopped:
        rclpy.spin_once(node, timeout_sec=0.1)


def main():
    rclpy.init(signal_handler_options=SignalHandlerOptions.NO)
    node = rclpy.create_node('service_call_peer')
    if sys.argv[1] == 'call':
        call(node, int(sys.argv[2]))
    else:
        serve(node)
    node.destroy_node()
    rclpy.shutdown()


if __name__ == '__main__':
    main()
