# SPDX-License-Identifier: BSD-3-Clause
"""RTPS datagrams for the mros2 network fuzzer (bench/fuzz/rtps_fuzz.py): recorded from a
real exchange on the ROS side of a genmros mros2-pc board, read as RTPS (header and
submessages), and mutated the ways RTPS can be wrong.

``python3 -m testing.rtps_datagrams capture IFACE OUT`` (run on the ROS side, where the
user namespace's root may open a packet socket) writes every UDP datagram of the RTPS
ports (7400-7700) that crosses IFACE to OUT as JSON lines {"to_board": bool, "port":
destination port, "data": hex}, until SIGTERM. ``python3 -m testing.rtps_datagrams send
ADDRESS`` sends each line "PORT HEX" of its stdin to ADDRESS:PORT, one UDP datagram each,
and says "sent N" at the end.
"""

import json
import random
import signal
import socket
import struct
import sys

RTPS_PORTS = range(7400, 7700)
ETH_P_ALL, ETH_P_IP = 0x0003, 0x0800
HEADER_SIZE = 20
# Submessage ids (RTPS 2.x 9.4.5.1.1).
PAD, ACKNACK, HEARTBEAT, GAP, INFO_TS, INFO_SRC, INFO_DST, NACK_FRAG, HEARTBEAT_FRAG, DATA, \
    DATA_FRAG = 0x01, 0x06, 0x07, 0x08, 0x09, 0x0c, 0x0e, 0x12, 0x13, 0x15, 0x16
KIND_NAMES = {ACKNACK: 'ACKNACK', HEARTBEAT: 'HEARTBEAT', GAP: 'GAP', INFO_TS: 'INFO_TS',
              INFO_DST: 'INFO_DST', DATA: 'DATA', DATA_FRAG: 'DATA_FRAG',
              HEARTBEAT_FRAG: 'HEARTBEAT_FRAG', NACK_FRAG: 'NACK_FRAG'}
# Parameter ids of SPDP and SEDP samples whose values the board copies (9.6.2.2.2).
STRING_PIDS = (0x0005, 0x0007, 0x0062)  # topic name, type name, entity name
LOCATOR_PIDS = (0x002f, 0x0030, 0x0031, 0x0032, 0x0033, 0x0048)


def capture(interface, out_path):
    """Records RTPS datagrams crossing interface (see the module) until SIGTERM."""
    stopped = []
    signal.signal(signal.SIGTERM, lambda *_: stopped.append(True))
    # ETH_P_ALL: a socket of one protocol (ETH_P_IP) gets only what comes in, not what the
    # ROS side sends.
    sniffer = socket.socket(socket.AF_PACKET, socket.SOCK_DGRAM, socket.htons(ETH_P_ALL))
    sniffer.bind((interface, 0))
    sniffer.settimeout(0.2)
    with open(out_path, 'w') as out:
        print('capturing', file=sys.stderr, flush=True)
        while not stopped:
            try:
                packet, address = sniffer.recvfrom(65535)
            except socket.timeout:
                continue
            if address[1] != ETH_P_IP or len(packet) < 28 or packet[9] != 17:  # UDP, IPv4
                continue
            header_length = (packet[0] & 0x0f) * 4
            source_port, port, length = struct.unpack_from('!HHH', packet, header_length)
            payload = packet[header_length + 8:header_length + length]
            if port in RTPS_PORTS or source_port in RTPS_PORTS:
                # An outgoing packet (PACKET_OUTGOING, 4) came from the ROS side.
                out.write(json.dumps({'to_board': address[2] == socket.PACKET_OUTGOING,
                                      'port': port, 'data': payload.hex()}) + '\n')
                out.flush()


def read_capture(path):
    with open(path) as stream:
        return [json.loads(line) for line in stream if line.strip()]


class Submessage:
    """One submessage: id, flags, and its body (octetsToNextHeader bytes)."""

    def __init__(self, kind, flags, body):
        self.kind, self.flags, self.body = kind, flags, bytearray(body)

    def little_endian(self):
        return bool(self.flags & 1)

    def encode(self, length=None):
        endian = '<' if self.little_endian() else '>'
        return bytes([self.kind, self.flags]) + struct.pack(
            endian + 'H', len(self.body) if length is None else length) + bytes(self.body)


def rtps_header(guid_prefix):
    """An RTPS 2.3 message header, eProsima's vendor id (1.15), from guid_prefix (12 bytes)."""
    return b'RTPS\x02\x03\x01\x0f' + bytes(guid_prefix)


def data(reader_id, writer_id, sn, payload):
    """A little-endian DATA (flags E and D) of payload, from writer_id (4 bytes) to
    reader_id."""
    return Submessage(DATA, 0x05, struct.pack('<HH4s4siI', 0, 16, reader_id, writer_id,
                                              sn >> 32, sn & 0xffffffff) + payload)


def data_frag(reader_id, writer_id, sn, first_fragment, fragment_size, sample_size, payload,
              fragments=1):
    """A little-endian DATA_FRAG carrying payload as fragments first_fragment to
    first_fragment + fragments - 1 (numbered from 1) of a sample of sample_size bytes."""
    return Submessage(DATA_FRAG, 0x01, struct.pack(
        '<HH4s4siIIHHI', 0, 28, reader_id, writer_id, sn >> 32, sn & 0xffffffff,
        first_fragment, fragments, fragment_size, sample_size) + payload)


def parse(datagram):
    """(header, [Submessage]) of an RTPS datagram, or None."""
    if len(datagram) < HEADER_SIZE or datagram[:4] != b'RTPS':
        return None
    header, position, submessages = bytearray(datagram[:HEADER_SIZE]), HEADER_SIZE, []
    while position + 4 <= len(datagram):
        kind, flags = datagram[position], datagram[position + 1]
        length, = struct.unpack_from('<H' if flags & 1 else '>H', datagram, position + 2)
        body = datagram[position + 4:position + 4 + length]
        submessages.append(Submessage(kind, flags, body))
        position += 4 + length
    return header, submessages


def kinds(datagram):
    parsed = parse(datagram)
    return [KIND_NAMES.get(sub.kind, hex(sub.kind)) for sub in parsed[1]] if parsed else []


def _payload_offset(sub):
    """Where a DATA or DATA_FRAG submessage's serialized payload starts in its body."""
    if len(sub.body) < 4:
        return None
    to_inline_qos, = struct.unpack_from('<H' if sub.little_endian() else '>H', sub.body, 2)
    return 4 + to_inline_qos if 4 + to_inline_qos <= len(sub.body) else None


def _parameters(body, start):
    """(offset of each parameter's header, pid, length) of a PL_CDR_LE parameter list."""
    found, position = [], start
    while position + 4 <= len(body):
        pid, length = struct.unpack_from('<HH', body, position)
        found.append((position, pid, length))
        if pid == 1:  # PID_SENTINEL
            break
        position += 4 + length
    return found


class Mutator:
    """Mutations of recorded datagrams, each named for the part of RTPS it breaks."""

    def __init__(self, seed):
        self.random = random.Random(seed)
        # The sequence number of fragment_sequence's next sample: each newer than the last,
        # so that a board does not take them for late fragments of one it has.
        self.fragment_sn = 1 << 20

    def _number(self):
        return self.random.choice([0, 1, 2, 3, 4, 0x7f, 0x80, 0xff, 0x100, 0x7fff, 0xffff,
                                   0x7fffffff, 0x80000000, 0xffffffff,
                                   self.random.getrandbits(32)])

    def submessage_length(self, header, subs):
        sub = self.random.choice(subs)
        length = self.random.choice([0, 1, 3, len(sub.body) - 1, len(sub.body) + 1,
                                     len(sub.body) + 4, 0xffff, self.random.getrandbits(16)])
        return bytes(header) + b''.join(s.encode(max(0, length) if s is sub else None)
                                        for s in subs)

    def submessage_count(self, header, subs):
        subs = list(subs)
        choice = self.random.random()
        if choice < 0.4:
            subs = subs + [self.random.choice(subs)] * self.random.randint(1, 40)
        elif choice < 0.7 and len(subs) > 1:
            del subs[self.random.randrange(len(subs))]
        else:
            self.random.shuffle(subs)
        return bytes(header) + b''.join(s.encode() for s in subs)

    def submessage_kind(self, header, subs):
        sub = self.random.choice(subs)
        sub.kind = self.random.choice([DATA, DATA_FRAG, HEARTBEAT, ACKNACK, GAP, INFO_DST,
                                       INFO_TS, HEARTBEAT_FRAG, NACK_FRAG, PAD])
        return bytes(header) + b''.join(s.encode() for s in subs)

    def _data(self, subs):
        data = [s for s in subs if s.kind in (DATA, DATA_FRAG)]
        return self.random.choice(data) if data else None

    def parameter_list(self, header, subs):
        sub = self._data(subs)
        start = _payload_offset(sub) if sub else None
        if start is None or len(sub.body) < start + 4 or sub.body[start + 1] not in (2, 3):
            return self.bytes_flipped(header, subs)
        parameters = _parameters(sub.body, start + 4)
        if not parameters:
            return self.bytes_flipped(header, subs)
        position, pid, length = self.random.choice(parameters)
        choice = self.random.random()
        if choice < 0.3:  # a lying length
            struct.pack_into('<H', sub.body, position + 2, self._number() & 0xffff)
        elif choice < 0.6:  # a name longer than any board's field, or one with no end
            text = b'n' * self.random.choice([39, 40, 41, 64, 200, 1000])
            value = struct.pack('<I', self.random.choice([len(text) + 1, len(text), 0,
                                                          0xffffffff])) + text + b'\0'
            value += bytes(-len(value) % 4)
            new = struct.pack('<HH', self.random.choice(STRING_PIDS), len(value)) + value
            sub.body[position:position] = new
        elif choice < 0.85:  # a locator: kind, port, address
            locator = struct.pack('<iI', self.random.choice([1, 2, -1, 0, 16]),
                                  self._number()) + bytes(self.random.getrandbits(8)
                                                          for _ in range(16))
            new = struct.pack('<HH', self.random.choice(LOCATOR_PIDS), 24) + locator
            sub.body[position:position] = new
        else:  # a parameter removed (the sentinel among them)
            del sub.body[position:position + 4 + length]
        return bytes(header) + b''.join(s.encode() for s in subs)

    def inline_qos(self, header, subs):
        """A DATA or DATA_FRAG given an inline QoS (flag Q) before its payload: a related
        sample identity (PID_RELATED_SAMPLE_IDENTITY or Fast DDS' own id), a key hash (random,
        or the sender's participant or one of its endpoints) and a status info (disposed,
        unregistered), an unknown parameter; lengths short, lying or past the end, the
        sentinel there or not."""
        sub = self._data(subs)
        start = _payload_offset(sub) if sub else None
        if start is None:
            return self.bytes_flipped(header, subs)
        endian = '<' if sub.little_endian() else '>'
        prefix = bytes(header[8:20])
        parameters = []
        for _ in range(self.random.randint(1, 4)):
            pid = self.random.choice([0x0083, 0x800f, 0x0070, 0x0071, 0x0000, 0x4242])
            if pid in (0x0083, 0x800f):
                value = bytes(self.random.getrandbits(8) for _ in range(16)) + struct.pack(
                    endian + 'iI', self.random.choice([-1, 0, 1]), self._number())
            elif pid == 0x0070:
                value = prefix + self.random.choice(
                    [b'\0\0\1\xc1', bytes(sub.body[8:12]) if len(sub.body) >= 12 else b'',
                     bytes(self.random.getrandbits(8) for _ in range(4))])
            elif pid == 0x0071:
                value = bytes([0, 0, 0, self.random.choice([1, 2, 3, 0])])
            else:
                value = bytes(self.random.getrandbits(8) for _ in range(
                    self.random.choice([0, 4, 8])))
            length = len(value) if self.random.random() < 0.8 else self.random.choice(
                [0, 1, len(value) - 1, 0xffff, self._number() & 0xffff])
            parameters.append(struct.pack(endian + 'HH', pid, max(0, length)) + value)
        if self.random.random() < 0.85:
            parameters.append(struct.pack(endian + 'HH', 1, 0))  # PID_SENTINEL
        sub.body[start:start] = b''.join(parameters)
        sub.flags |= 0x02
        return bytes(header) + b''.join(s.encode() for s in subs)

    def sequence_numbers(self, header, subs):
        sub = self.random.choice(subs)
        endian = '<' if sub.little_endian() else '>'
        # writerSN of DATA/DATA_FRAG at 12; HEARTBEAT's first and last, ACKNACK's and GAP's
        # set bases at 8 and after.
        offsets = {DATA: [12, 16], DATA_FRAG: [12, 16, 20, 24, 26, 28], HEARTBEAT: [8, 12, 16, 20],
                   ACKNACK: [8, 12, 16, 20], GAP: [8, 12, 16, 20, 24]}.get(sub.kind, [0])
        offset = self.random.choice(offsets)
        if offset + 4 <= len(sub.body):
            struct.pack_into(endian + 'I', sub.body, offset, self._number())
        return bytes(header) + b''.join(s.encode() for s in subs)

    def encapsulation(self, header, subs):
        sub = self._data(subs)
        start = _payload_offset(sub) if sub else None
        if start is None or start + 4 > len(sub.body):
            return self.bytes_flipped(header, subs)
        sub.body[start:start + 4] = bytes(self.random.choice(
            [[0, 0, 0, 0], [0, 1, 0, 0], [0, 2, 0, 0], [0, 3, 0, 0], [0xff, 0xff, 0, 0],
             [0, 1, 0xff, 0xff]]))
        if self.random.random() < 0.5:
            del sub.body[start + 4 + self.random.randrange(max(1, len(sub.body) - start - 4)):]
        return bytes(header) + b''.join(s.encode() for s in subs)

    def truncated(self, header, subs):
        whole = bytes(header) + b''.join(s.encode() for s in subs)
        return whole[:self.random.randrange(len(whole))]

    def bytes_flipped(self, header, subs):
        whole = bytearray(bytes(header) + b''.join(s.encode() for s in subs))
        for _ in range(self.random.randint(1, 8)):
            position = self.random.randrange(len(whole))
            whole[position] = self.random.getrandbits(8)
        return bytes(whole)

    def fragment_sequence(self, datagram):
        """Datagrams of DATA_FRAGs cut from new samples, on the way of datagram's first
        DATA_FRAG (its writer, reader and the submessages before it; newer sequence
        numbers): sample and fragment sizes (at and over a board's buffer, fragments of 1
        byte), fragments per submessage, repeated and overlapping fragments (other bytes,
        other starts), sizes that disagree, out of order, and a second sample (a newer or
        older one of the same writer, or another writer's) interleaved. [] if datagram has
        no DATA_FRAG."""
        header, subs = parse(datagram)
        first = next((index for index, sub in enumerate(subs)
                      if sub.kind == DATA_FRAG and len(sub.body) >= 32), None)
        if first is None:
            return []
        reader, writer = bytes(subs[first].body[4:8]), bytes(subs[first].body[8:12])
        self.fragment_sn += 3
        sn = self.fragment_sn
        fragments = self._fragments(reader, writer, sn)
        if self.random.random() < 0.5:
            other = writer if self.random.random() < 0.5 else bytes(
                [0, 0, self.random.randrange(256), self.random.choice([2, 3, 7])])
            second = self._fragments(reader, other, sn + self.random.choice([-1, 1, 2]))
            merged = []
            while fragments or second:  # interleaved, each in its own order
                source = fragments if not second or (fragments and self.random.random() < 0.5) \
                    else second
                merged.append(source.pop(0))
            fragments = merged
        datagrams = []
        while fragments:
            count = self.random.choice([1, 1, 1, 2, 3])
            batch, fragments = fragments[:count], fragments[count:]
            datagrams.append(bytes(header) + b''.join(s.encode() for s in subs[:first] + batch))
        return datagrams

    def _fragments(self, reader, writer, sn):
        """The DATA_FRAG submessages of one sample (at most 60), mutated."""
        size = self.random.choice([self.random.randrange(1, 9000), self.random.randrange(1, 200),
                                   8192, 8193, 65000, 65536, 0, self._number()])
        fragment_size = self.random.choice([self.random.randrange(1, 1500), 1, 63, 64, 1224,
                                            0, 0xffff])
        count = -(-size // fragment_size) if fragment_size else 1
        sample = bytes([0, 1, 0, 0]) + bytes(self.random.getrandbits(8) for _ in range(
            min(size, 60 * max(fragment_size, 1), 70000)))
        numbers = list(range(1, min(count, 60) + 1))
        if self.random.random() < 0.5:
            self.random.shuffle(numbers)
        found = []
        for number in numbers:
            # a datagram's worth at most (a larger fragment size gives fragments cut short)
            start = (number - 1) * fragment_size
            payload = sample[start:start + min(fragment_size, 1400)]
            choice = self.random.random()
            if choice < 0.1:  # a repeat, the same bytes
                found.append(data_frag(reader, writer, sn, number, fragment_size, size, payload))
            elif choice < 0.15:  # the same place, other bytes
                found.append(data_frag(reader, writer, sn, number, fragment_size, size,
                                       bytes(len(payload))))
            elif choice < 0.2:  # another start, a number out of range, or two at once
                found.append(data_frag(reader, writer, sn, self._number(), fragment_size, size,
                                       payload, self.random.choice([1, 2, 0, 0xffff])))
            elif choice < 0.25:  # sizes that disagree
                found.append(data_frag(reader, writer, sn, number, self._number() & 0xffff,
                                       self._number(), payload))
            elif choice < 0.3:  # cut short
                payload = payload[:self.random.randrange(len(payload) + 1)]
            found.append(data_frag(reader, writer, sn, number, fragment_size, size, payload))
        return found

    MUTATIONS = ('submessage_length', 'submessage_count', 'submessage_kind', 'parameter_list',
                 'inline_qos', 'sequence_numbers', 'encapsulation', 'truncated', 'bytes_flipped')

    def mutate(self, datagram, unknown_source):
        """(mutation's name, the mutated datagram); unknown_source: from a participant the
        board has not discovered (a fresh GUID prefix)."""
        header, subs = parse(datagram)
        if unknown_source:
            header[8:20] = bytes(self.random.getrandbits(8) for _ in range(12))
        name = self.random.choice(self.MUTATIONS)
        return name, getattr(self, name)(header, [Submessage(s.kind, s.flags, s.body)
                                                  for s in subs])


def send(address):
    """Sends stdin's "PORT HEX" lines to address (see the module)."""
    sender = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
    count = 0
    for line in sys.stdin:
        port, _, data = line.partition(' ')
        try:
            sender.sendto(bytes.fromhex(data.strip()), (address, int(port)))
        except OSError:  # a datagram over 64 KB after mutation: not sendable
            continue
        count += 1
    print('sent %d' % count, flush=True)


if __name__ == '__main__':
    if sys.argv[1] == 'capture':
        capture(sys.argv[2], sys.argv[3])
    else:
        send(sys.argv[2])
