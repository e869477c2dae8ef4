# SPDX-License-Identifier: BSD-3-Clause
"""The records the board's Linux port (evaluation/firmware/port_linux.cpp)
and a bridge exchange over the board's standard input and output: uint8
kind, uint16 topic index and uint32 size, little-endian, then size bytes.
The board sends a 'T' record per topic first, then 'M' records (a
message); a bridge sends 'M' records. Used by board_bridge.py (ROS 1) and
ros2_bridge.py (ROS 2); the standard library only."""

import struct

RECORD_HEAD = struct.Struct('<cHI')


def _read_exactly(stream, size):
    data = stream.read(size)
    return data if len(data) == size else None


def read_records(stream):
    """(kind, topic index, body) of each record on stream, until it ends."""
    while True:
        head = _read_exactly(stream, RECORD_HEAD.size)
        if head is None:
            return
        kind, index, size = RECORD_HEAD.unpack(head)
        body = _read_exactly(stream, size)
        if body is None:
            return
        yield kind, index, body


def write_message(stream, index, body):
    """An 'M' record of body for topic index."""
    stream.write(RECORD_HEAD.pack(b'M', index, len(body)) + body)
    stream.flush()
