#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Sends every sample message of every test type to <from>/<Type> and checks
that exactly the same bytes come back on <to>/<Type> (through one or more
relays in between). Each sample is republished every 0.3 s until it comes
back, so connection set-up along the chain needs no extra waiting. Prints
one PASS/FAIL line per type and exits 0 only if every sample came back.

  roundtrip_check.py FROM_PREFIX TO_PREFIX [--types T,...] [--timeout S]
                     [--ignore-header-seq]
"""
import argparse
import io
import queue
import sys
import time

import rospy

from message_samples import samples


def wire_bytes(message, ignore_seq=False):
    """The serialized message; with ignore_seq, as if header.seq were 0."""
    seq = message.header.seq if ignore_seq and message._has_header else None
    if seq is not None:
        message.header.seq = 0
    buffer = io.BytesIO()
    message.serialize(buffer)
    if seq is not None:
        message.header.seq = seq
    return buffer.getvalue()


def check_type(name, messages, source, sink, timeout, ignore_seq):
    message_class = type(messages[0])
    received = queue.Queue()
    subscriber = rospy.Subscriber('%s/%s' % (sink, name), message_class,
                                  lambda m: received.put(wire_bytes(m, ignore_seq)), queue_size=100)
    publisher = rospy.Publisher('%s/%s' % (source, name), message_class, queue_size=100)
    confirmed = set()
    try:
        for index, message in enumerate(messages):
            # Bytes of every copy sent: rospy renumbers header.seq per publish.
            sent = set()
            deadline = time.monotonic() + timeout
            next_send = 0.0
            while True:
                now = time.monotonic()
                if now > deadline:
                    return 'FAIL %s: sample %d did not come back within %.0f s' % (
                        name, index, timeout)
                if now >= next_send:
                    publisher.publish(message)
                    sent.add(wire_bytes(message, ignore_seq))
                    next_send = now + 0.3
                try:
                    got = received.get(timeout=0.05)
                except queue.Empty:
                    continue
                if got in sent:
                    confirmed |= sent
                    break
                if got not in confirmed:
                    back = message_class()
                    back.deserialize(got)
                    return 'FAIL %s: sample %d came back changed\nsent:\n%s\nreceived:\n%s' % (
                        name, index, message, back)
        return 'PASS %s: %d samples' % (name, len(messages))
    finally:
        subscriber.unregister()
        publisher.unregister()


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument('source')
    parser.add_argument('sink')
    parser.add_argument('--types', default=None)
    parser.add_argument('--timeout', type=float, default=15.0)
    parser.add_argument('--ignore-header-seq', action='store_true',
                        help='a roscpp relay on the way renumbers header.seq, as roscpp does')
    args = parser.parse_args(rospy.myargv()[1:])
    rospy.init_node('roundtrip_check', anonymous=True)
    all_samples = samples()
    names = args.types.split(',') if args.types else sorted(all_samples)
    results = [check_type(name, all_samples[name], args.source, args.sink, args.timeout,
                          args.ignore_header_seq)
               for name in names]
    for line in results:
        print(line, flush=True)
    return 0 if all(line.startswith('PASS') for line in results) else 1


if __name__ == '__main__':
    sys.exit(main())
