# SPDX-License-Identifier: BSD-3-Clause
"""The graph watcher: an rclpy node that watches the ROS 2 graph for a board's node, as
``ros2 node list`` and ``ros2 node info`` ask it, on the ROS side of a genmros mros2-pc
board (testing/mros2_pc.py runs it in the ROS 2 wheels' venv).

stdin, a line of JSON: {"node", "namespace", "publishers": count, "subscribers": count,
"wait": seconds}. It spins until get_node_names_and_namespaces() lists the node and the
node's publishers and subscribers (get_publisher_names_and_types_by_node(),
get_subscriber_names_and_types_by_node()) number at least those counts, or the wait ends;
then writes a line of JSON to stdout: {"nodes": [[name, namespace], ...], "publishers":
[[topic, [types]], ...], "subscribers": [...], "seen_after": seconds from its start, or
null}. Then, at the next line on stdin (the board has stopped), it spins until the node is
no longer listed, or the wait ends, and writes {"gone_after": seconds from that line, or
null}. Writes "watcher ready" to stderr once its node exists. SIGTERM ends it at once.
"""

import json
import sys
import time

import rclpy
from rclpy.signals import SignalHandlerOptions


def spin_until(node, condition, wait):
    """Spins until condition() holds or wait seconds passed; the seconds it took, or None."""
    start = time.monotonic()
    while not condition():
        if time.monotonic() - start > wait:
            return None
        rclpy.spin_once(node, timeout_sec=0.05)
    return time.monotonic() - start


def main():
    job = json.loads(sys.stdin.readline())
    # rclpy's own handlers would leave it waiting on stdin with its context shut down.
    rclpy.init(signal_handler_options=SignalHandlerOptions.NO)
    node = rclpy.create_node('genmros_graph_watcher')
    print('watcher ready', file=sys.stderr, flush=True)
    watched = (job['node'], job['namespace'])

    def listed():
        return watched in node.get_node_names_and_namespaces()

    def endpoints():
        if not listed():
            return [], []
        return (node.get_publisher_names_and_types_by_node(*watched),
                node.get_subscriber_names_and_types_by_node(*watched))

    def complete():
        publishers, subscribers = endpoints()
        return len(publishers) >= job['publishers'] and len(subscribers) >= job['subscribers']

    seen_after = spin_until(node, complete, job['wait'])
    publishers, subscribers = endpoints()
    json.dump({'nodes': node.get_node_names_and_namespaces(), 'publishers': publishers,
               'subscribers': subscribers, 'seen_after': seen_after}, sys.stdout)
    print(flush=True)
    sys.stdin.readline()
    json.dump({'gone_after': spin_until(node, lambda: not listed(), job['wait'])}, sys.stdout)
    print(flush=True)
    node.destroy_node()
    rclpy.shutdown()


if __name__ == '__main__':
    main()
