# SPDX-License-Identifier: BSD-3-Clause
"""colcon_mros.mros_v1.names: the reserved names are an explicit list, held equal
here to what the support headers declare."""

import os
import re

from colcon_mros.mros_v1.aggregates import DELIVERY_HEADER, firmware_files
from colcon_mros.mros_v1.names import SUPPORT_HEADER_NAMES, SUPPORT_MACROS, member_identifier
from support.checkout import REPO

PACKAGE = os.path.join(REPO, 'colcon_mros')
# The static support headers (the back end's and the core's containers
# header) and the template of their version header.
SUPPORT_FILES = [os.path.join(PACKAGE, directory, 'support', name)
                 for directory in ('mros_v1', 'core')
                 for name in sorted(os.listdir(os.path.join(PACKAGE, directory, 'support')))] + [
    os.path.join(PACKAGE, 'mros_v1', 'templates', 'mros_message_support_version.h.em')]


def _support_texts():
    """The texts of SUPPORT_FILES and of the delivery header the mROS v1
    aggregates put beside them, as an export writes it."""
    texts = []
    for path in SUPPORT_FILES:
        with open(path) as stream:
            texts.append(stream.read())
    return texts + [firmware_files([])[DELIVERY_HEADER]]


# A template's parameter list, nested template arguments included.
_TEMPLATE_HEAD = re.compile(r'template\s*<(?:[^<>]|<[^<>]*>)*>')
_DECLARATION = re.compile(r'\b(?:struct|class|union|namespace|using)\s+([A-Za-z_]\w*)')


def _declared(text):
    return set(_DECLARATION.findall(_TEMPLATE_HEAD.sub('template <>', text)))


def test_reserved_names_are_what_the_support_headers_declare():
    declared = set().union(*(_declared(text) for text in _support_texts()))
    assert declared == SUPPORT_HEADER_NAMES


def test_the_macros_are_what_the_support_headers_define_and_read():
    macros = set()
    for text in _support_texts():
        macros.update(re.findall(r'#\s*(?:define|ifndef)\s+(MROS_\w+)', text))
        macros.update(re.findall(r'defined\((MROS_\w+)\)', text))
    assert macros == SUPPORT_MACROS
    assert member_identifier('MROS_BOUNDED_OVERFLOW', 'Limits') == 'MROS_BOUNDED_OVERFLOW_'


def test_template_parameters_are_not_reserved():
    assert not {'T', 'Word', 'Text', 'Number', 'Bits', 'Sequence', 'Byte'} & SUPPORT_HEADER_NAMES


def test_members_are_escaped_until_free():
    assert member_identifier('class', 'Thing') == 'class_'
    assert member_identifier('EOF', 'Thing') == 'EOF_'
    assert member_identifier('Thing', 'Thing') == 'Thing_'
    assert member_identifier('value', 'Thing') == 'value'
