# SPDX-License-Identifier: BSD-3-Clause
"""C++ literals and comments both back ends write: text, numbers and
comment lines that compile without a warning from gnu++98 to C++17.

Numbers are named by their C++ type (``int8_t`` ... ``uint64_t``, ``float``,
``double``); each back end maps its front end's type names onto these.
"""

import math
import re

from colcon_mros.core.floats import FLOAT32_SMALLEST_NORMAL, round_to_type

_NAMED_ESCAPES = {'\n': '\\n', '\t': '\\t'}


def _literal_byte(byte):
    """One byte of UTF-8 text inside a C++ string literal."""
    char = chr(byte)
    if char in '\\"':
        return '\\' + char
    if char in _NAMED_ESCAPES:
        return _NAMED_ESCAPES[char]
    return char if 32 <= byte < 127 else '\\%03o' % byte


_LITERAL_BYTES = [_literal_byte(byte) for byte in range(256)]
_SECOND_QUESTION_MARK = re.compile(r'(?<=\?)\?')


def cpp_string_literal_lines(text):
    """text as C++ string literal pieces, one per line of text.

    Non-ASCII bytes become octal escapes (never followed by a digit that
    could extend them, unlike hex escapes), and '?' after '?' is escaped so
    no trigraph can form.
    """
    pieces = []
    for line in text.splitlines(True):
        escaped = ''.join([_LITERAL_BYTES[byte] for byte in line.encode('utf-8')])
        pieces.append('"%s"' % _SECOND_QUESTION_MARK.sub(r'\\?', escaped))
    return pieces or ['""']


def _integer_literal(cpp_type, value):
    """value as a C++98 constant expression of cpp_type.

    C++98 has no long long literals (and -pedantic warns about them), so a
    64-bit value beyond 32 bits is built from two 32-bit halves. No literal
    exceeds its type: the minimum of a signed type is written as -MAX - 1.
    """
    unsigned = cpp_type.startswith('u')
    if cpp_type.endswith('64_t'):
        magnitude = abs(value)
        if magnitude < (1 << 31):
            body = 'static_cast<%s>(%d%s)' % (cpp_type, magnitude, 'u' if unsigned else '')
        elif value == -(1 << 63):
            return '(-%s - 1)' % _integer_literal(cpp_type, (1 << 63) - 1)
        else:
            body = '(static_cast<uint64_t>(0x%08xu) << 32 | 0x%08xu)' % (
                magnitude >> 32, magnitude & 0xffffffff)
            if not unsigned:
                body = 'static_cast<int64_t>%s' % body
        return '(-%s)' % body if value < 0 else body
    if cpp_type == 'int32_t' and value == -(1 << 31):
        return '(-2147483647 - 1)'
    return '%du' % value if unsigned else '%d' % value


def _float_literal(cpp_type, value):
    if math.isnan(value):
        return 'std::numeric_limits<%s>::quiet_NaN()' % cpp_type
    if math.isinf(value):
        sign = '-' if value < 0 else ''
        return '%sstd::numeric_limits<%s>::infinity()' % (sign, cpp_type)
    held = round_to_type(cpp_type, value)
    # A literal that rounds to zero or to a subnormal float draws a warning
    # from C++ compilers: such a constant is written as the value the float
    # holds, exactly. Other literals keep the definition's digits.
    if cpp_type == 'float' and abs(held) < FLOAT32_SMALLEST_NORMAL:
        value = held
    text = repr(float(value))
    text = text if ('.' in text or 'e' in text) else text + '.0'
    return text + 'f' if cpp_type == 'float' else text


def cpp_number_literal(cpp_type, value):
    """A C++98 expression of the number type cpp_type holding value."""
    if cpp_type in ('float', 'double'):
        return _float_literal(cpp_type, value)
    return _integer_literal(cpp_type, value)


def comment_lines(comment):
    """Comment lines as the text of C++ // lines: no line may end in a
    backslash (it would continue the comment onto the next line of code),
    and no '??' may start a trigraph."""
    lines = [re.sub(r'\?(?=\?)', '? ', text.rstrip('\\ \t')) for text in comment]
    return [text for text in lines if text]
