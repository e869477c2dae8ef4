# SPDX-License-Identifier: BSD-3-Clause
"""The service peer: an rclpy node that serves a board's client and calls a board's service,
rcl_interfaces/srv/GetParameterTypes both (a name's type is its length), on the ROS side of a
genmros mros2-pc board (testing/mros2_pc.py runs it in the ROS 2 wheels' venv).

stdin, a line of JSON: {"serve": name, "call": name, "node": the board's node, "calls": count,
"clients": count, "board_calls": count, "wait": seconds}. It serves "serve" at once, recording
each request's names. Once its client of "call" sees the service (wait_for_service), it:
- calls it "calls" times, one after another, call i asking for ["peer i", "y" * i];
- calls it from "clients" clients at once, 10 calls each in flight together, client k asking
  for k + 1 names;
- sends one request from a client it destroys before the reply, then calls "calls" times more;
- once the board's node is listed (get_node_names_and_namespaces(), until "wait" ends), reads
  get_service_names_and_types() and get_service_names_and_types_by_node(node, "/") (none
  when the node never came).
A reply counts as right when its types are its own request's names' lengths. Then it waits
until "board_calls" requests came or the wait ended, and writes a line of JSON to stdout:
{"calls": [right, of], "clients": [[right, of], ...], "after_gone": [right, of],
"services": [[name, [types]], ...], "services_by_node": [...], "requests": [[names], ...]}.
Writes "peer ready" to stderr once its service exists. SIGTERM ends it at once.
"""

import json
import sys
import time

import rclpy
from rcl_interfaces.srv import GetParameterTypes
from rclpy.signals import SignalHandlerOptions

# The calls each client has in flight together.
CONCURRENT_CALLS = 10


def right(request, response):
    return list(response.types) == [len(name) for name in request.names]


def calls_in_flight(node, client, requests, wait):
    """Sends every request before any reply is taken; how many replies were right."""
    futures = [client.call_async(request) for request in requests]
    deadline = time.monotonic() + wait
    while not all(future.done() for future in futures) and time.monotonic() < deadline:
        rclpy.spin_once(node, timeout_sec=0.05)
    return sum(1 for request, future in zip(requests, futures)
               if future.done() and right(request, future.result()))


def request_of(names):
    request = GetParameterTypes.Request()
    request.names = names
    return request


def main():
    job = json.loads(sys.stdin.readline())
    rclpy.init(signal_handler_options=SignalHandlerOptions.NO)
    node = rclpy.create_node('genmros_service_peer')
    requests = []

    def name_lengths(request, response):
        requests.append(list(request.names))
        response.types = [len(name) for name in request.names]
        return response

    node.create_service(GetParameterTypes, job['serve'], name_lengths)
    print('peer ready', file=sys.stderr, flush=True)
    client = node.create_client(GetParameterTypes, job['call'])
    report = {}
    if client.wait_for_service(timeout_sec=job['wait']):
        one_by_one = [request_of(['peer %d' % i, 'y' * i]) for i in range(job['calls'])]
        report['calls'] = [sum(calls_in_flight(node, client, [request], job['wait'])
                               for request in one_by_one), len(one_by_one)]
        clients = [node.create_client(GetParameterTypes, job['call'])
                   for _ in range(job['clients'])]
        for each in clients:
            each.wait_for_service(timeout_sec=job['wait'])
        futures = []
        for k, each in enumerate(clients):
            for i in range(CONCURRENT_CALLS):
                names = ['client %d call %d' % (k, i)] + ['z' * (k + i)] * k
                futures.append((k, request_of(names), each.call_async(request_of(names))))
        deadline = time.monotonic() + job['wait']
        while (not all(future.done() for _, _, future in futures) and
               time.monotonic() < deadline):
            rclpy.spin_once(node, timeout_sec=0.05)
        report['clients'] = [[sum(1 for k, request, future in futures
                                  if k == client_index and future.done() and
                                  right(request, future.result())), CONCURRENT_CALLS]
                             for client_index in range(job['clients'])]
        gone = node.create_client(GetParameterTypes, job['call'])
        gone.wait_for_service(timeout_sec=job['wait'])
        gone.call_async(request_of(['never taken']))
        node.destroy_client(gone)
        report['after_gone'] = [sum(calls_in_flight(node, client, [request], job['wait'])
                                    for request in one_by_one), len(one_by_one)]
    # Services are matched through SEDP, nodes learnt from ros_discovery_info: the board's
    # node may come into the graph after its service.
    deadline = time.monotonic() + job['wait']
    while ((job['node'], '/') not in node.get_node_names_and_namespaces() and
           time.monotonic() < deadline):
        rclpy.spin_once(node, timeout_sec=0.05)
    report['services'] = node.get_service_names_and_types()
    report['services_by_node'] = (
        node.get_service_names_and_types_by_node(job['node'], '/')
        if (job['node'], '/') in node.get_node_names_and_namespaces() else [])
    deadline = time.monotonic() + job['wait']
    while len(requests) < job['board_calls'] and time.monotonic() < deadline:
        rclpy.spin_once(node, timeout_sec=0.05)
    report['requests'] = requests
    json.dump(report, sys.stdout)
    print(flush=True)
    node.destroy_node()
    rclpy.shutdown()


if __name__ == '__main__':
    main()
