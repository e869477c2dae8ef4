# SPDX-License-Identifier: BSD-3-Clause
"""Floating-point types as C++ holds them: their range, and a value rounded
to the type (a 32-bit constant is what a C++ float holds, not the double a
parser read). Types are named as C++ names them: 'float', 'double'."""

import struct

# The largest finite value of each type.
FLOAT_LIMITS = {'float': 3.4028234663852886e+38, 'double': 1.7976931348623157e+308}
# The smallest normal float: below it a value is subnormal or zero.
FLOAT32_SMALLEST_NORMAL = 1.1754943508222875e-38


def round_to_type(cpp_type, value):
    """value as cpp_type holds it: rounded to the nearest float (infinity
    beyond the range), or unchanged for double."""
    if cpp_type == 'double':
        return value
    try:
        return struct.unpack('<f', struct.pack('<f', value))[0]
    except OverflowError:
        return float('inf') if value > 0 else float('-inf')
