#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""The main job's transport between the board's program and the ROS graph.

The board (evaluation/firmware, genmros headers and no ROS client) runs as a
child of this rospy node and speaks records over its standard input and
output (port_linux.cpp describes them). For every topic the board announces,
this node publishes or subscribes under the board's own identity: the type
name, MD5 sum and definition text come from the board's genmros headers and
go into the TCPROS connection headers as they are, so a rospy or roscpp peer
refuses the connection if the board's types are not its own. Message bodies
pass through unread, in both directions: what a ROS node receives is the
board's encoding, and what the board decodes is the ROS node's.

  board_bridge.py COMMAND...     (e.g. qemu-arm build/board)
"""

import subprocess
import sys
import threading

import rospy

from board_records import read_records, write_message


def board_message_class(type_name, md5sum, definition):
    """A rospy message class that carries a body as it is, under the
    identity the board announced."""
    return type('BoardMessage', (rospy.AnyMsg,),
                {'_type': type_name, '_md5sum': md5sum, '_full_text': definition,
                 '__slots__': []})


class Bridge:
    def __init__(self, command):
        self.board = subprocess.Popen(command, stdin=subprocess.PIPE, stdout=subprocess.PIPE)
        self.to_board = threading.Lock()
        self.classes = {}
        self.publishers = {}
        self.subscribers = []

    def forward_to_board(self, index):
        def callback(message):
            body = bytes(message._buff)
            with self.to_board:
                write_message(self.board.stdin, index, body)
        return callback

    def announce(self, index, body):
        name, type_name, md5sum, definition, role = body.decode().split('\0')
        message_class = board_message_class(type_name, md5sum, definition)
        self.classes[index] = message_class
        if role == 'P':
            self.publishers[index] = rospy.Publisher(name, message_class, queue_size=100)
        else:
            self.subscribers.append(rospy.Subscriber(name, message_class,
                                                     self.forward_to_board(index),
                                                     queue_size=100))
        print('bridge: the board %s %s (%s, md5 %s, definition %d bytes)' % (
            'publishes' if role == 'P' else 'subscribes to', name, type_name, md5sum,
            len(definition)), flush=True)

    def run(self):
        """Relays until the board stops; returns its exit status."""
        for kind, index, body in read_records(self.board.stdout):
            if kind == b'T':
                self.announce(index, body)
            elif kind == b'M' and index in self.publishers:
                message = self.classes[index]()
                message._buff = body
                self.publishers[index].publish(message)
            else:
                print('bridge: a record of kind %r for topic %d from the board' % (kind, index),
                      flush=True)
        return self.board.wait()


def main():
    command = rospy.myargv()[1:]
    if not command:
        print(__doc__.strip().splitlines()[-1], file=sys.stderr)
        return 2
    rospy.init_node('mros_board', disable_signals=False)
    status = Bridge(command).run()
    print('bridge: the board stopped (exit status %d)' % status, flush=True)
    rospy.signal_shutdown('the board stopped')
    return 0 if status == 0 else 1


if __name__ == '__main__':
    sys.exit(main())
