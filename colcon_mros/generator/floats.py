"""ROS floating-point types as C++ holds them: their range, and a value
rounded to the type (a float32 constant is what a C++ float holds, not the
double genmsg parsed)."""

import struct

# The largest finite value of each type.
FLOAT_LIMITS = {'float32': 3.4028234663852886e+38, 'float64': 1.7976931348623157e+308}
# The smallest normal float32: below it a value is subnormal or zero.
FLOAT32_SMALLEST_NORMAL = 1.1754943508222875e-38


def round_to_type(ros_type, value):
    """value as ros_type holds it: rounded to the nearest float32 (infinity
    beyond the range), or unchanged for float64."""
    if ros_type == 'float64':
        return value
    try:
        return struct.unpack('<f', struct.pack('<f', value))[0]
    except OverflowError:
        return float('inf') if value > 0 else float('-inf')
