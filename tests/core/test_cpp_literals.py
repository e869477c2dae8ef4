# SPDX-License-Identifier: BSD-3-Clause
"""colcon_mros.core.cpp_literals: the C++ text and number literals both back
ends write (each back end's constants are tested with its own type names:
tests/mros_v1/test_cpp.py, tests/mros2)."""

import pytest

from colcon_mros.core.cpp_literals import (comment_lines, cpp_number_literal,
                                           cpp_string_literal_lines)


@pytest.mark.parametrize('text, pieces', [
    ('', ['""']),
    ('a "b" \\ c\n', ['"a \\"b\\" \\\\ c\\n"']),
    ('x\ty\nz', ['"x\\ty\\n"', '"z"']),
    ('??=??/???', ['"?\\?=?\\?/?\\?\\?"']),
    ('Zo\u00eb 1', ['"Zo\\303\\253 1"']),
])
def test_string_literals_escape_what_cpp_would_read_otherwise(text, pieces):
    assert cpp_string_literal_lines(text) == pieces


@pytest.mark.parametrize('cpp_type, value, literal', [
    ('int64_t', -(1 << 63),
     '(-static_cast<int64_t>(static_cast<uint64_t>(0x7fffffffu) << 32 | 0xffffffffu) - 1)'),
    ('uint8_t', 255, '255u'),
    ('float', 1e-40, '9.99994610111476e-41f'),
    ('double', float('nan'), 'std::numeric_limits<double>::quiet_NaN()'),
])
def test_number_literals_are_named_by_their_cpp_type(cpp_type, value, literal):
    assert cpp_number_literal(cpp_type, value) == literal


def test_comment_lines_end_in_no_backslash_and_start_no_trigraph():
    assert comment_lines(['ends in \\', '', 'what??!', '  ']) == ['ends in', 'what? ?!']
