# SPDX-License-Identifier: BSD-3-Clause
"""How genmros' messages count things: '1 service', '2 services'."""


def counted(number, noun, plural=None):
    """'<number> <noun>', the noun in its plural (noun + 's' unless given)
    for any number but 1."""
    return '%d %s' % (number, noun if number == 1 else plural or noun + 's')
