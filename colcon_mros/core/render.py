# SPDX-License-Identifier: BSD-3-Clause
"""Render logic-free empy templates, and read the static support headers.

Every back end keeps its templates and static headers in a directory of its
own; this renders one template with the context a back end's C++ view
gives it. Nothing is written here: writing is :mod:`.output`'s job.

The templates hold no logic (tests/core/test_templates.py): text,
expansions of expressions, ``for`` and ``if``/``elif``/``else``, comments.
They render one of two ways, with the same text out
(tests/core/test_render.py holds both to it over every template):

- Where empy 3's scanner is (``em.Scanner(prefix, data)`` and its token
  classes: Debian's python3-empy, the empy catkin needs), each template is
  translated once per process into one Python code object that does what
  empy's interpreter does with those markups (write the text; write
  ``str()`` of an expression unless it is None; loop and branch, the loop
  variables among the template's globals), and each render runs that code
  over the context. Running empy's interpreter took most of an export's
  time (an export renders msg.h.em once per type: bench/README.md). A
  markup outside that set is refused when the template is read.
- Elsewhere (empy 4, which rosidl >= 4 runs on, or any empy whose
  internals are not empy 3's), each render runs empy's public
  ``Interpreter`` over the template's text, its output a StringIO, the
  context its globals, and shuts it down. On empy 4 its stdout proxy lives
  only as long as that interpreter (sys.stdout is the same object after),
  it installs no import finder, and an error in a template is raised, not
  reported and exited on. This path refuses no markup: the package's own
  templates are held logic-free by the test above, and a template
  directory of the user's (genmros -e) is read as it is.
"""

import functools
import io
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
# What the translation reads of empy 3's scanner; empy 4 has none of
# NullToken and DEFAULT_PREFIX, and a Scanner that takes other arguments.
_EMPY3_SCANNER = ('Scanner', 'DEFAULT_PREFIX', 'NullToken', 'LiteralToken', 'PrefixToken',
                  'WhitespaceToken', 'CommentToken', 'ExpressionToken',
                  'SimpleExpressionToken', 'ControlToken')
# Whether templates are translated (empy 3's scanner is there) or run by
# empy's interpreter.
TRANSLATES = all(hasattr(em, name) for name in _EMPY3_SCANNER)


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
    scanner = em.Scanner(em.DEFAULT_PREFIX, _text(path))
    translation = _Translation(path)
    translation.tokens(iter(scanner.one, None), 0)
    return compile('\n'.join(translation.lines) + '\n', path, 'exec')


def render_template(template_dir, template_name, **context):
    """The text of the empy template template_name in template_dir."""
    path = os.path.join(template_dir, template_name)
    if not TRANSLATES:
        return _interpreted(path, _text(path), context)
    parts = []
    namespace = dict(context)
    namespace[_WRITE] = parts.append
    namespace[_STR] = str
    exec(_compiled(path), namespace)
    return ''.join(parts)


@functools.lru_cache(maxsize=None)
def _text(path):
    """The text of the template at path, read once per process as
    _compiled reads it."""
    with open(path) as template:
        return template.read()


def _interpreted(path, text, context):
    """text (the template at path) run by empy's public interpreter over
    context."""
    output = io.StringIO()
    options = {'output': output, 'globals': dict(context)}
    if hasattr(em, 'Configuration'):  # empy 4
        # The proxy explicitly (EMPY_NO_PROXY may not choose): empy 4.2's
        # interpreter without one writes to sys.stdout, not to output.
        # It is the interpreter's own and goes at its shutdown.
        config = em.Configuration(prefix='@', useProxy=True)
        if hasattr(config, 'supportModules'):  # empy >= 4.2: no finder in sys.meta_path
            config.supportModules = False
        # dispatcher=False: an error is raised, not printed with sys.exit().
        options.update(config=config, dispatcher=False)
    interpreter = em.Interpreter(**options)
    try:
        interpreter.string(text)
        interpreter.flush()
        # Before shutdown: empy 3 closes the output there.
        return output.getvalue()
    finally:
        interpreter.shutdown()


@functools.lru_cache(maxsize=None)
def static_text(directory, name):
    """The text of a static header: directory's, else the core's SUPPORT_DIR."""
    for where in (directory, SUPPORT_DIR):
        path = os.path.join(where, name)
        if os.path.isfile(path):
            with open(path) as source:
                return source.read()
    raise FileNotFoundError(os.path.join(directory, name))
