# SPDX-License-Identifier: BSD-3-Clause
"""Read one interface file into rosidl's IDL definitions.

``.msg`` and ``.srv`` files go through rosidl_adapter into IDL text, and
every file through rosidl_parser, the two steps rosidl_generate_interfaces
takes: whatever ROS 2 accepts is read the same way here. rosidl reports a
bad definition without its line; the line is found again here (the first
line at which the file stops parsing), so every error reads
``FILE:LINE: problem``.
"""

import contextlib
import io
import os
import re

from colcon_mros.errors import GenmrosError


class Parsed:
    """An interface file's rosidl definitions: the messages (a service's
    request and response among them) and the services, and where each
    member and constant is declared."""

    def __init__(self, path, content, lines):
        from rosidl_parser import definition
        self.path = path
        self.messages = content.get_elements_of_type(definition.Message)
        self.services = content.get_elements_of_type(definition.Service)
        self._lines = lines

    def line_of(self, name, section=0):
        """The line declaring a member or constant (in a .srv, of the
        request (section 0) or the response (1)); None where not known."""
        return self._lines.get((section, name))


# A member or constant declaration in a .msg/.srv: TYPE NAME[ default] or TYPE NAME=VALUE.
_DECLARATION = re.compile(r'^\s*\S+\s+([A-Za-z][A-Za-z0-9_]*)\s*(?:=|\s|$)')
_IDL_MEMBER = re.compile(r'\b([A-Za-z][A-Za-z0-9_]*)\s*(?:\[[^\]]*\]\s*)?;')
_SECTION_SEPARATOR = '---'


def _declaration_lines(text, is_idl):
    """{(section, name): line} of the declarations in a file's text."""
    lines = {}
    section = 0
    for number, line in enumerate(text.split('\n'), 1):
        code = line.split('//')[0] if is_idl else line.split('#')[0]
        if not is_idl and code.strip() == _SECTION_SEPARATOR:
            section += 1
            continue
        match = (_IDL_MEMBER.search(code) if is_idl else _DECLARATION.match(code))
        if match:
            lines.setdefault((section, match.group(1)), number)
    return lines


# mros2's own generator wants nested types as pkg/msg/Type; rosidl takes pkg/Type.
_MSG_PATH_FORM = re.compile(r'^([A-Za-z]\w*)/msg/([A-Za-z]\w*)$')


def _problem(error):
    text = str(error).strip().splitlines()
    text = text[0] if text else ''
    match = _MSG_PATH_FORM.match(text)
    if match:
        return ("'%s' is no type name ROS 2 takes: write '%s/%s' (mros2's own generator wants "
                'the other form)' % (text, match.group(1), match.group(2)))
    if ' ' not in text:
        # rosidl_adapter says little more than the offending word.
        return '%s: %s' % (type(error).__name__, text)
    return text


def _quietly(function, *arguments):
    """function(*arguments) with rosidl_adapter's own report of a bad line
    (printed to stderr before it raises) held back: genmros says it once."""
    with contextlib.redirect_stderr(io.StringIO()):
        return function(*arguments)


def _adapt(package, kind, name, text):
    """The IDL text rosidl_adapter makes of a .msg or .srv."""
    from rosidl_adapter.parser import parse_message_string, parse_service_string
    from rosidl_adapter.resource import evaluate_template
    if kind == 'msg':
        return evaluate_template('msg.idl.em', {
            'pkg_name': package, 'relative_input_file': 'msg/%s.msg' % name,
            'msg': parse_message_string(package, name, text)})
    return evaluate_template('srv.idl.em', {
        'pkg_name': package, 'relative_input_file': 'srv/%s.srv' % name,
        'srv': parse_service_string(package, name, text)})


def require_an_adapter_for_this_empy():
    """Raise a one-line GenmrosError where rosidl_adapter cannot render even
    a message without fields under an empy other than 3: it was written for
    empy 3 (Debian 12's, rosidl 3.3), and no .msg or .srv is at fault."""
    import em
    import rosidl_adapter
    try:
        _quietly(_adapt, 'genmros', 'msg', 'Empty', '')
    except Exception:  # whatever this rosidl_adapter makes of this empy
        if not em.__version__.startswith('3.'):
            raise GenmrosError(
                "rosidl_adapter (%s) renders .msg and .srv files with empy 3 only, and empy %s "
                "is installed (%s): install empy 3 in its place (pip install 'empy<4'), or a "
                'rosidl_adapter that renders with empy 4'
                % (os.path.dirname(rosidl_adapter.__file__), em.__version__, em.__file__))


def _first_bad_line(package, kind, name, text):
    """The first line at which a .msg or .srv no longer parses, or None."""
    from rosidl_adapter.parser import parse_message_string, parse_service_string
    parse = parse_message_string if kind == 'msg' else parse_service_string
    lines = text.split('\n')
    for count in range(1, len(lines) + 1):
        prefix = '\n'.join(lines[:count])
        if kind == 'srv' and _SECTION_SEPARATOR not in [line.strip() for line in lines[:count]]:
            prefix += '\n' + _SECTION_SEPARATOR
        try:
            _quietly(parse, package, name, prefix)
        except Exception:  # rosidl_adapter raises many types for bad input
            return count
    return None


def parse_interface(interface):
    """The :class:`Parsed` definitions of an :class:`~colcon_mros.ros2.interfaces.Interface`."""
    from rosidl_parser.parser import parse_idl_string
    path = interface.path
    try:
        with open(path, encoding='utf-8') as stream:
            text = stream.read()
    except (OSError, UnicodeDecodeError) as error:
        raise GenmrosError('cannot read: %s' % (getattr(error, 'strerror', None) or error), path)
    is_idl = path.endswith('.idl')
    if is_idl:
        idl = text
    else:
        try:
            idl = _quietly(_adapt, interface.package, interface.kind, interface.name, text)
        except Exception as error:  # rosidl_adapter's errors, ValueError and more
            require_an_adapter_for_this_empy()
            raise GenmrosError(_problem(error), path,
                               _first_bad_line(interface.package, interface.kind,
                                               interface.name, text))
    try:
        content = parse_idl_string(idl)
    except Exception as error:  # lark's errors carry the IDL line
        line = getattr(error, 'line', None) if is_idl else None
        raise GenmrosError(_problem(error), path, line)
    return Parsed(path, content, _declaration_lines(text, is_idl))
