# SPDX-License-Identifier: BSD-3-Clause
"""Render logic-free empy templates, and read the static support headers.

Every back end keeps its templates and static headers in a directory of its
own; this renders one template with the context a back end's C++ view
gives it. Nothing is written here: writing is :mod:`.output`'s job.

The templates are empy 3 templates, scanned by empy's own ``Scanner``, and
hold no logic (tests/core/test_templates.py): text, expansions of
expressions, ``for`` and ``if``/``elif``/``else``, comments. Running
empy's interpreter over them took most of an export's time (an export
renders msg.h.em once per type: bench/README.md), so each template is
translated once per process into one Python code object that does what the
interpreter does with those markups (write the text; write ``str()`` of an
expression unless it is None; loop and branch, the loop variables among the
template's globals), and each render runs that code over the context. A
markup outside that set is refused when the template is read.
tests/core/test_render.py holds the output equal to empy's interpreter.
"""

import functools
import os

import em

# The static headers both back ends' exports hold: the containers of
# bounded storage (mros_message_containers.h).
SUPPORT_DIR = os.path.join(os.path.dirname(os.path.abspath(__file__)), 'support')
# The names the translated code writes with; no template uses them, and a
# context may hold any other (str included).
_WRITE = '_genmros_write'
_VALUE = '_genmros_value'
_STR = '_genmros_str'
_INDENT = '    '


class _Translation:
    """The Python source of one template, built from empy's tokens."""

    def __init__(self, path):
        self.path = path
        self.lines = []

    def add(self, depth, line):
        self.lines.append(_INDENT * depth + line)

    def tokens(self, tokens, depth):
        start = len(self.lines)
        for token in tokens:
            self.token(token, depth)
        if len(self.lines) == start:
            self.add(depth, 'pass')

    def token(self, token, depth):
        if isinstance(token, em.NullToken):
            self.add(depth, '%s(%r)' % (_WRITE, token.data))
        elif isinstance(token, em.LiteralToken):
            self.add(depth, '%s(%r)' % (_WRITE, token.first))
        elif isinstance(token, em.PrefixToken):  # @@: the prefix itself
            self.add(depth, '%s(%r)' % (_WRITE, token.prefix))
        elif isinstance(token, (em.WhitespaceToken, em.CommentToken)):
            pass
        elif isinstance(token, em.ExpressionToken) and not (
                token.thenCode or token.elseCode or token.exceptCode):
            self.expansion(token.testCode, depth)
        elif isinstance(token, em.SimpleExpressionToken):
            self.expansion(token.code, depth)
        elif isinstance(token, em.ControlToken) and token.type in ('for', 'if'):
            self.control(token, depth)
        else:
            raise ValueError('%s: %s is more than a logic-free template holds'
                             % (self.path, token.string().strip()))

    def expansion(self, code, depth):
        self.add(depth, '%s = (%s)' % (_VALUE, code.strip()))
        self.add(depth, 'if %s is not None: %s(%s(%s))' % (_VALUE, _WRITE, _STR, _VALUE))

    def control(self, token, depth):
        branches = token.build(['elif', 'else'] if token.type == 'if' else ['else'])
        for marker, subtokens in branches:
            if marker.type == 'else':
                self.add(depth, 'else:')
            else:
                self.add(depth, '%s %s:' % (marker.type, marker.rest.strip()))
            self.tokens(subtokens, depth + 1)


@functools.lru_cache(maxsize=None)
def _compiled(path):
    """The template at path as one code object, once per process."""
    with open(path) as template:
        scanner = em.Scanner(em.DEFAULT_PREFIX, template.read())
    translation = _Translation(path)
    translation.tokens(iter(scanner.one, None), 0)
    return compile('\n'.join(translation.lines) + '\n', path, 'exec')


def render_template(template_dir, template_name, **context):
    """The text of the empy template template_name in template_dir."""
    parts = []
    namespace = dict(context)
    namespace[_WRITE] = parts.append
    namespace[_STR] = str
    exec(_compiled(os.path.join(template_dir, template_name)), namespace)
    return ''.join(parts)


@functools.lru_cache(maxsize=None)
def static_text(directory, name):
    """The text of a static header: directory's, else the core's SUPPORT_DIR."""
    for where in (directory, SUPPORT_DIR):
        path = os.path.join(where, name)
        if os.path.isfile(path):
            with open(path) as source:
                return source.read()
    raise FileNotFoundError(os.path.join(directory, name))
