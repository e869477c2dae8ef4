# SPDX-License-Identifier: BSD-3-Clause
"""The reference serializer (testing/fastcdr.py on Debian's Fast-CDR 1.0.26)
held to the CDR rules the byte-exact tests rely on: XCDR1 little endian, the
encapsulation header 00 01 00 00, each value aligned to its size (8 at most)
relative to the first byte after that header. The expected bytes are written
out by hand from those rules, not produced by the tool, so a wrong op list,
a wrong build or a different Fast-CDR shows here first."""

import math
import struct

import pytest

from testing.fastcdr import FastCdrError, build, decode, encode

HEADER = bytes.fromhex('00010000')


@pytest.fixture(scope='module')
def program(tmp_path_factory):
    return build(str(tmp_path_factory.mktemp('fastcdr')))


def hand(*hex_parts):
    """The header and the data, written as hex parts (spaces ignored)."""
    return HEADER + bytes.fromhex(''.join(hex_parts))


def bits64(value):
    return struct.pack('<d', value)


def test_no_ops_is_the_encapsulation_header_alone(program):
    assert encode(program, []) == bytes([0x00, 0x01, 0x00, 0x00])


def test_float64_aligns_to_8_after_the_header(program):
    # The 8 bytes of 1.5 (0x3ff8000000000000) after 7 pad bytes: offset 8
    # after the header, offset 12 of the buffer. Aligning on the buffer's
    # start would have put them at 8 with 3 pad bytes.
    assert encode(program, [('uint8', 1), ('float64', 1.5)]) == hand(
        '01 00000000000000',
        '000000000000f83f')


def test_every_size_aligns_to_itself(program):
    ops = [('int8', -1), ('int16', -2), ('uint8', 3), ('int32', -4),
           ('octet', 5), ('uint64', 6), ('char', 0x41), ('float32', 1.0)]
    assert encode(program, ops) == hand(
        'ff 00 feff',             # int8 at 0, int16 at 2
        '03 000000 fcffffff',     # uint8 at 4, int32 at 8
        '05 000000',              # octet at 12
        '0600000000000000',       # uint64 at 16
        '41 000000 0000803f')     # char at 24 (one byte), float32 at 28


def test_string_is_length_with_nul_then_bytes_and_nul(program):
    assert encode(program, [('string', b'ab')]) == hand('03000000 616200')


def test_string_length_aligns_to_4_and_bytes_do_not(program):
    assert encode(program, [('uint8', 9), ('string', b'xyz'), ('string', b'')]) == hand(
        '09 000000',
        '04000000 78797a00',
        '01000000 00')


def test_string_ends_at_its_first_nul_byte(program):
    # Fast-CDR serializes std::string through c_str(): what follows a NUL is
    # not written.
    assert encode(program, [('string', b'a\0b')]) == hand('02000000 6100')


def test_sequence_is_count_then_elements(program):
    ops = [('uint8', 7), ('count', 2), ('int16', -2), ('int16', 3), ('count', 0), ('uint8', 8)]
    assert encode(program, ops) == hand(
        '07 000000',
        '02000000',
        'feff 0300',
        '00000000',
        '08')


def test_wstring_is_count_of_4_byte_units_without_terminator(program):
    # 'h', 'é' and U+1F600 (one unit: wchar_t is 4 bytes on Linux); the
    # count is of units, not bytes; "" is a count of 0 and nothing more.
    ops = [('uint8', 1), ('wstring', 'h\u00e9\U0001f600'), ('wstring', ''), ('uint8', 2)]
    assert encode(program, ops) == hand(
        '01 000000',
        '03000000 68000000 e9000000 00f60100',
        '00000000',
        '02')


def test_bool_is_one_byte(program):
    assert encode(program, [('bool', True), ('bool', False), ('int16', 1)]) == hand(
        '01 00 0100')


def test_nan_and_negative_zero_bytes(program):
    ops = [('float64', float('nan')), ('float64', -0.0), ('float32', float('-inf'))]
    assert encode(program, ops) == hand(
        '000000000000f87f',
        '0000000000000080',
        '000080ff')


def test_float32_is_rounded_as_struct_rounds(program):
    # 0.1 as float32 is 0x3dcccccd.
    data = encode(program, [('float32', 0.1)])
    assert data == hand('cdcccc3d')
    assert decode(program, data, ['float32']) == [struct.unpack('<f', struct.pack('<f', 0.1))[0]]


EXTREMES = [
    ('bool', True), ('bool', False),
    ('char', 0), ('char', 255), ('octet', 0), ('octet', 255),
    ('int8', -128), ('int8', 127), ('uint8', 0), ('uint8', 255),
    ('int16', -32768), ('int16', 32767), ('uint16', 0), ('uint16', 65535),
    ('int32', -2 ** 31), ('int32', 2 ** 31 - 1), ('uint32', 0), ('uint32', 2 ** 32 - 1),
    ('int64', -2 ** 63), ('int64', 2 ** 63 - 1), ('uint64', 0), ('uint64', 2 ** 64 - 1),
    ('count', 0), ('count', 2 ** 32 - 1),
    ('float32', -0.0), ('float32', 2.0 ** -149), ('float32', 3.4028234663852886e38),
    ('float32', float('inf')), ('float32', float('nan')),
    ('float64', -0.0), ('float64', 5e-324), ('float64', 1.7976931348623157e308),
    ('float64', -math.pi), ('float64', float('-inf')),
    # A signalling NaN with the sign set, and a quiet one with a payload.
    ('float64', struct.unpack('<d', struct.pack('<Q', 0xfff0000000000001))[0]),
    ('float64', struct.unpack('<d', struct.pack('<Q', 0x7ff80000deadbeef))[0]),
    ('float32', struct.unpack('<f', struct.pack('<I', 0xffc01234))[0]),
    ('string', b''), ('string', bytes(range(1, 256))),
    ('wstring', ''), ('wstring', 'h\u00e9llo \U0001f600 \ud800'),
]


def test_every_kind_round_trips_exactly(program):
    data = encode(program, EXTREMES)
    values = decode(program, data, [kind for kind, _ in EXTREMES])
    assert len(values) == len(EXTREMES)
    for (kind, sent), read in zip(EXTREMES, values):
        if kind == 'float32':
            assert struct.pack('<f', read) == struct.pack('<f', sent), kind
        elif kind == 'float64':
            assert bits64(read) == bits64(sent), kind
        else:
            assert type(read) is type(sent) and read == sent, (kind, sent, read)


def test_truncated_buffer_is_refused(program):
    data = encode(program, [('uint8', 1), ('float64', 2.0)])
    with pytest.raises(FastCdrError, match='Not enough memory') as refusal:
        decode(program, data[:-1], ['uint8', 'float64'])
    assert refusal.value.decoded == [1]


def test_string_longer_than_the_buffer_is_refused(program):
    with pytest.raises(FastCdrError, match='Not enough memory'):
        decode(program, hand('0a000000 616200'), ['string'])


def test_bool_other_than_0_or_1_is_refused(program):
    with pytest.raises(FastCdrError, match='bool'):
        decode(program, hand('02'), ['bool'])


def test_values_out_of_range_are_refused(program):
    with pytest.raises(ValueError):
        encode(program, [('uint8', 256)])
    with pytest.raises(ValueError):
        encode(program, [('int64', 2 ** 63)])
    with pytest.raises(ValueError):
        encode(program, [('uint32', -1)])
    with pytest.raises(ValueError):
        encode(program, [('vector', 1)])
