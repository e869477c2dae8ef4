# SPDX-License-Identifier: BSD-3-Clause
"""A library's settings, read from its configuration headers, and the one
line a fit check writes for a setting too small.

The settings are numbers a header sets: ``#define``s (mROS v1's
``mros_usr_config.h`` and ``mros_packet_config.h``), read as the
preprocessor reads a number, and C++ constants (embeddedRTPS'
``rtps/config.h``: ``const uint8_t MAX_TYPENAME_LENGTH = 20;``), each with
the file and line that set it. A value may add, subtract or multiply
numbers and other settings (``MAX_NUM_PARTICIPANTS + 1``); anything else
is not a number here and is left out. A back end's fit check names which
settings a type needs; :func:`misfit_line` is the line every fit check
writes for one that is too small, so the build's lines read alike for every
library.
"""

import ast
import re

from colcon_mros.errors import GenmrosError

_DEFINE = re.compile(r'^\s*#\s*define\s+([A-Za-z_]\w*)\s+(.*?)\s*(?://.*|/\*.*)?$')
# A constant, its value possibly on the next lines: [static] const|constexpr TYPE NAME = VALUE;
_CONSTANT = re.compile(r'^[ \t]*(?:static\s+)?(?:constexpr|const)\s+[\w:]+(?:\s+[\w:]+)*?\s+'
                       r'([A-Za-z_]\w*)\s*=\s*([^;{]*?)\s*;', re.M)
_COMMENT = re.compile(r'//[^\n]*|/\*.*?\*/', re.S)
_INTEGER_SUFFIX = re.compile(r'\b(\d+)[uUlL]+\b')
_OPERATORS = {ast.Add: lambda a, b: a + b, ast.Sub: lambda a, b: a - b,
              ast.Mult: lambda a, b: a * b}


class Setting:
    """One setting: its name, value, and where it is."""

    def __init__(self, name, value, path, line):
        self.name = name
        self.value = value
        self.path = path
        self.line = line

    def where(self):
        return '%s:%d' % (self.path, self.line)


class GivenSetting(Setting):
    """A setting given where genmros is run (a command-line option), not
    read from a header: where() names the option."""

    def __init__(self, name, value, option):
        super().__init__(name, value, None, None)
        self.option = option

    def where(self):
        return self.option


def _evaluate(node, raw, seen):
    """The integer value of an expression node, or None: numbers, settings
    in raw (followed, cycles refused), +, - and *, parentheses."""
    if isinstance(node, ast.Expression):
        return _evaluate(node.body, raw, seen)
    if isinstance(node, ast.Constant) and type(node.value) is int:
        return node.value
    if isinstance(node, ast.Name) and node.id in raw and node.id not in seen:
        return _value(node.id, raw, seen | {node.id})
    if isinstance(node, ast.UnaryOp) and isinstance(node.op, ast.USub):
        operand = _evaluate(node.operand, raw, seen)
        return None if operand is None else -operand
    if isinstance(node, ast.BinOp) and type(node.op) in _OPERATORS:
        left, right = _evaluate(node.left, raw, seen), _evaluate(node.right, raw, seen)
        if left is not None and right is not None:
            return _OPERATORS[type(node.op)](left, right)
    return None


def _value(name, raw, seen):
    text = _INTEGER_SUFFIX.sub(r'\1', raw[name][0])
    try:
        return _evaluate(ast.parse(text, mode='eval'), raw, seen)
    except SyntaxError:
        return None


def read_settings(paths, role='the library settings', fix=None):
    """{name: Setting} of the numeric #defines and constants in paths (a
    later file's setting of a name does not replace an earlier one's: list
    the file the build includes first first). role names the files in the
    error a missing one gives, fix says what to do about it."""
    raw = {}
    for path in paths:
        try:
            with open(path, encoding='utf-8', errors='replace') as stream:
                text = stream.read()
        except OSError as error:
            raise GenmrosError('cannot read %s: %s%s' % (role, error.strerror,
                                                         '; ' + fix if fix else ''), path)
        found = [(number, match.group(1), match.group(2))
                 for number, match in enumerate(map(_DEFINE.match, text.splitlines()), 1)
                 if match]
        found += [(text.count('\n', 0, match.start(1)) + 1, match.group(1),
                   _COMMENT.sub(' ', match.group(2))) for match in _CONSTANT.finditer(text)]
        for number, name, value in sorted(found):
            raw.setdefault(name, (value, path, number))
    settings = {}
    for name, (_, path, line) in raw.items():
        value = _value(name, raw, {name})
        if value is not None:
            settings[name] = Setting(name, value, path, line)
    return settings


def misfit_line(setting, subject, what, needed, note=''):
    """FILE:LINE of setting, then the subject (a type), what needs the
    setting, the value it needs and the value it has (and a note)."""
    return ('%s: %s: %s needs %s >= %d (it is %d%s)'
            % (setting.where(), subject, what, setting.name, needed, setting.value, note))
