# SPDX-License-Identifier: BSD-3-Clause
"""The reference CDR serializer the byte-exact tests hold generated C++
message code to: Debian's real Fast-CDR 1.0.26 (libfastcdr-dev), the library
ROS 2's Fast DDS type support serializes with, driven by a type-agnostic op
list.

A message is described by its ops, one Fast-CDR call each, in wire order:
``('uint8', 5)``, ``('float64', 1.5)``, ``('string', b'abc')``,
``('wstring', 'héllo')``, ``('count', 3)`` (a sequence's length),
``('bool', True)``. A fixed array is its elements' ops, a sequence is a
``count`` op and its elements' ops, a nested message is its fields' ops
inline: Fast-CDR aligns every value relative to the stream, and that is what
the tests check generated code against.

- :func:`build`: compile testing/fastcdr_ops.cpp (once per directory and
  process) against -lfastcdr.
- :func:`encode`: the bytes Fast-CDR writes for ops: XCDR1 little endian,
  the encapsulation header ``00 01 00 00`` first, alignment relative to the
  byte after it.
- :func:`decode`: the values Fast-CDR reads from bytes for a list of kinds;
  :class:`FastCdrError` with Fast-CDR's own message when it refuses them.

What Fast-CDR 1.0.26 writes for each kind (a string ends at its first NUL
byte, a wstring is a count of 4-byte units without a terminator, ...) is
described at the top of fastcdr_ops.cpp. Floats cross the text interface as
hex floats and NaNs as their bits, so every value goes both ways exactly.
Only the standard library, g++ and libfastcdr-dev are used.
"""

import math
import os
import struct
import subprocess

SOURCE = os.path.join(os.path.dirname(os.path.abspath(__file__)), 'fastcdr_ops.cpp')
COMPILE_FLAGS = ['-std=c++11', '-O1', '-Wall', '-Wextra']

INTEGER_KINDS = ('char', 'octet', 'int8', 'uint8', 'int16', 'uint16', 'int32',
                 'uint32', 'int64', 'uint64', 'count')
FLOAT_KINDS = ('float32', 'float64')
KINDS = ('bool',) + INTEGER_KINDS + FLOAT_KINDS + ('string', 'wstring')

# A float kind's struct formats (the value, its bits) and mantissa width:
# NaNs are written as their sign and mantissa field, which printf's "nan"
# would drop.
_FLOAT_LAYOUT = {
    'float32': ('<f', '<I', 23),
    'float64': ('<d', '<Q', 52),
}

# The program built in each directory by this process.
_programs = {}


class FastCdrError(Exception):
    """Fast-CDR refused the buffer (NotEnoughMemoryException,
    BadParamException): the message is Fast-CDR's own. ``decoded`` holds the
    values it read before refusing."""

    def __init__(self, message, decoded=()):
        super().__init__(message)
        self.decoded = list(decoded)


def build(out_dir):
    """The path of fastcdr_ops compiled into out_dir; compiled the first time
    this process asks for that directory."""
    out_dir = os.path.abspath(out_dir)
    if out_dir not in _programs:
        os.makedirs(out_dir, exist_ok=True)
        program = os.path.join(out_dir, 'fastcdr_ops')
        result = subprocess.run(['g++'] + COMPILE_FLAGS + [SOURCE, '-o', program, '-lfastcdr'],
                                capture_output=True, text=True)
        if result.returncode != 0:
            raise RuntimeError('building %s failed (is libfastcdr-dev installed?):\n%s'
                               % (SOURCE, result.stderr))
        _programs[out_dir] = program
    return _programs[out_dir]


def encode(program, ops):
    """The serialized buffer, encapsulation header included, of ops (a list
    of (kind, value) tuples)."""
    lines = ['%s %s' % (kind, _value_text(kind, value)) for kind, value in ops]
    output = _run(program, 'encode', lines)
    return bytes.fromhex(output[0])


def encode_many(program, messages):
    """encode() of each op list in messages, in one run of the program."""
    lines = []
    for ops in messages:
        lines += ['%s %s' % (kind, _value_text(kind, value)) for kind, value in ops] + ['---']
    output = _run(program, 'encode', lines)
    assert len(output) == len(messages), output[-3:]
    return [bytes.fromhex(line) for line in output]


def decode(program, data, kinds):
    """The values Fast-CDR reads from data (a buffer with its encapsulation
    header) for kinds: int, float, bool, bytes for a string, str for a
    wstring. Bytes after the last kind are not looked at."""
    for kind in kinds:
        _check_kind(kind)
    output = _run(program, 'decode', [bytes(data).hex()] + list(kinds))
    return [_parse_value(line) for line in output]


def _check_kind(kind):
    if kind not in KINDS:
        raise ValueError('unknown op kind %r (one of %s)' % (kind, ', '.join(KINDS)))


def _value_text(kind, value):
    """value as the program's text for kind."""
    _check_kind(kind)
    if kind == 'bool':
        if value not in (0, 1):
            raise ValueError('a bool op takes True or False, not %r' % (value,))
        return '1' if value else '0'
    if kind in INTEGER_KINDS:
        # index() refuses floats and other non-integers.
        return '%d' % value.__index__()
    if kind in FLOAT_KINDS:
        return _float_text(kind, value)
    if kind == 'string':
        return bytes(value).hex()
    # A lone surrogate is a code unit like any other on the wire.
    return value.encode('utf-32-le', 'surrogatepass').hex()


def _float_text(kind, value):
    """The exact text of value as kind: float32 values are first rounded to
    float32 as struct does (refusing those out of its range)."""
    value_format, bits_format, mantissa_bits = _FLOAT_LAYOUT[kind]
    packed = struct.pack(value_format, value)
    rounded, = struct.unpack(value_format, packed)
    if not math.isnan(rounded):
        # float.hex gives "inf", "-inf" and "-0x0.0p+0" as strtod takes them.
        return rounded.hex()
    bits, = struct.unpack(bits_format, packed)
    sign = '-' if bits >> (8 * len(packed) - 1) else ''
    return '%snan(0x%x)' % (sign, bits & ((1 << mantissa_bits) - 1))


def _parse_value(line):
    """The Python value of one "kind value" line the program printed."""
    kind, _, text = line.partition(' ')
    if kind == 'bool':
        return text == '1'
    if kind in INTEGER_KINDS:
        return int(text)
    if kind in FLOAT_KINDS:
        return _parse_float(kind, text)
    if kind == 'string':
        return bytes.fromhex(text)
    if kind == 'wstring':
        return bytes.fromhex(text).decode('utf-32-le', 'surrogatepass')
    raise RuntimeError('fastcdr_ops printed an unknown kind: %r' % line)


def _parse_float(kind, text):
    value_format, bits_format, mantissa_bits = _FLOAT_LAYOUT[kind]
    negative = text.startswith('-')
    unsigned_text = text[1:] if negative else text
    if not unsigned_text.startswith('nan('):
        # A float32 is exact as a Python float: no rounding here.
        return float.fromhex(text)
    sign_bit = 1 << (8 * struct.calcsize(bits_format) - 1)
    exponent_bits = (sign_bit - 1) & ~((1 << mantissa_bits) - 1)
    bits = (sign_bit if negative else 0) | exponent_bits | int(unsigned_text[4:-1], 16)
    return struct.unpack(value_format, struct.pack(bits_format, bits))[0]


def _run(program, mode, lines):
    """The lines the program printed for the input lines; FastCdrError when
    Fast-CDR refused."""
    result = subprocess.run([program, mode], input=''.join(line + '\n' for line in lines),
                            capture_output=True, text=True)
    output = result.stdout.splitlines()
    if result.returncode == 1 and output and output[-1].startswith('error '):
        decoded = [_parse_value(line) for line in output[:-1]] if mode == 'decode' else []
        raise FastCdrError(output[-1][len('error '):], decoded)
    if result.returncode == 2:
        raise ValueError('fastcdr_ops %s refused its input: %s' % (mode, result.stderr.strip()))
    if result.returncode != 0:
        raise RuntimeError('fastcdr_ops %s failed (status %d):\n%s%s'
                           % (mode, result.returncode, result.stdout, result.stderr))
    return output
