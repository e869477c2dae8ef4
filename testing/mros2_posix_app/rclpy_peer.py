# SPDX-License-Identifier: BSD-3-Clause
"""The ROS 2 side of the mros2-posix runs (tests/integrations/test_mros2_posix.py): an
rclpy node that publishes raw std_msgs/String requests and takes the app's answers raw.

Runs in the ROS 2 wheels' venv. stdin: JSON {"requests": [{"sample": hex of the
serialized String, "text": its text, "topic": the answer's topic, "type": "Image" or
"String"}], "first_timeout": s, "timeout": s}. A request is sent again every
RESEND_PERIOD until an answer whose text (Image header.frame_id, String data) is the
request's arrives: the app's writers are best-effort, and the first requests also wait
for discovery. stdout: JSON {"answers": [{"sample": hex of the answer as received, "sent":
how often the request went out} or null], "unmatched": hex of the answers no request was
waiting for}.
"""

import json
import sys
import time

import rclpy
from rclpy.qos import QoSProfile, ReliabilityPolicy
from rclpy.serialization import deserialize_message
from sensor_msgs.msg import Image
from std_msgs.msg import String

RESEND_PERIOD = 0.5
MESSAGE_TYPES = {'Image': Image, 'String': String}


def answer_text(raw, message_type):
    """The text an answer carries, or None if rclpy cannot read it."""
    try:
        message = deserialize_message(raw, message_type)
    except Exception:  # rclpy raises a bare RMWError for a sample Fast CDR cannot read
        return None
    return message.header.frame_id if message_type is Image else message.data


def main():
    job = json.load(sys.stdin)
    rclpy.init()
    node = rclpy.create_node('genmros_peer')
    # mros2's writers and readers are best-effort; a reliable reader would not match.
    qos = QoSProfile(depth=100, reliability=ReliabilityPolicy.BEST_EFFORT)
    received = []
    for topic, type_name in sorted({(request['topic'], request['type'])
                                    for request in job['requests']}):
        message_type = MESSAGE_TYPES[type_name]
        node.create_subscription(
            message_type, topic,
            lambda raw, t=message_type: received.append((answer_text(raw, t), bytes(raw))),
            qos, raw=True)
    publisher = node.create_publisher(String, 'requests', qos)
    answers, unmatched = [], []
    timeout = job['first_timeout']
    for request in job['requests']:
        deadline, answer, sent = time.monotonic() + timeout, None, 0
        while answer is None and time.monotonic() < deadline:
            publisher.publish(bytes.fromhex(request['sample']))
            sent += 1
            resend_at = min(deadline, time.monotonic() + RESEND_PERIOD)
            while answer is None and time.monotonic() < resend_at:
                rclpy.spin_once(node, timeout_sec=0.05)
                while received and answer is None:
                    text, raw = received.pop(0)
                    if text == request['text']:
                        answer = {'sample': raw.hex(), 'sent': sent}
                    else:
                        unmatched.append(raw.hex())
        answers.append(answer)
        timeout = job['timeout']
    json.dump({'answers': answers, 'unmatched': unmatched}, sys.stdout)
    node.destroy_node()
    rclpy.shutdown()


if __name__ == '__main__':
    main()
