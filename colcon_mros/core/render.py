# SPDX-License-Identifier: BSD-3-Clause
"""Render empy templates, and read the static support headers.

Every back end keeps its templates and static headers in a directory of its
own; this renders one template with the context a back end's C++ view
gives it. Nothing is written here: writing is :mod:`.output`'s job.

A template renders one of two ways, with the same text out under empy 3
and empy 4 alike (tests/core/test_render.py holds them to it over every
template of the package and over a user's template directory, genmros -e):

- A logic-free template, one that holds nothing but text and these
  markups, as empy's documentation defines them in 3 and 4 alike: ``@@``,
  ``@#`` comments, ``@`` before a space or a newline, expansions of a name
  or attribute (``@(msg.name)``), ``@[for x in msg.fields]``,
  ``@[if msg.constants]`` (or ``not``) with ``@[elif ...]`` and
  ``@[else]``, and ``@[end for]``/``@[end if]``, is compiled once per
  process into one Python code object, which each render runs over the
  context. It does what empy does with those markups: write
  the text; write ``str()`` of an expression unless it is None; loop and
  branch, the loop variables among the template's globals. Every template
  of the package is one (tests/core/test_templates.py). empy keeps nothing
  of a template between two renders through its public API, and running
  its interpreter for each one took most of an export's time (an export
  renders msg.h.em once per type: bench/README.md).
- Any other template (a template directory of the user's may hold any
  markup) runs through empy's public ``Interpreter``, one per render: its
  output a StringIO, the context its globals, an error in the template
  raised, and shut down after. Its stdout proxy is on in both empys, so a
  template's print() goes to its text in both.
"""

import functools
import io
import os
import re

import em

# The static headers both back ends' exports hold: the containers of
# bounded storage (mros_message_containers.h).
SUPPORT_DIR = os.path.join(os.path.dirname(os.path.abspath(__file__)), 'support')

# The names the compiled code writes with; no template uses them, and a
# context may hold any other (str included).
_WRITE = '_genmros_write'
_VALUE = '_genmros_value'
_STR = '_genmros_str'
_INDENT = '    '

_NAME = r'[A-Za-z_]\w*'
_DOTTED = r'%s(?:\.%s)*' % (_NAME, _NAME)
# A markup of a logic-free template, at its prefix. Nothing in one can hold a
# closing parenthesis or bracket: where it ends is plain.
_MARKUP = re.compile(r'@(?:(?P<prefix>@)|#[^\n]*\n|[ \n]|\( *(?P<expansion>%s) *\)'
                     r'|\[(?P<control>[^\]\n]*)\])' % _DOTTED)
# Control markups as empy 3 reads them: the keyword, one space, the rest.
_FOR = re.compile(r'for (%s(?:, ?%s)*) in (%s)$' % (_NAME, _NAME, _DOTTED))
_BRANCH = re.compile(r'(if|elif) ((?:not )?%s)$' % _DOTTED)
_END = re.compile(r'end (for|if)$')


class _NotLogicFree(Exception):
    """The template holds more than the markups compiled here."""


class _Block:
    """An open @[for] or @[if] of a template being compiled."""

    def __init__(self, kind):
        self.kind = kind
        self.statements = 0  # in its current branch
        self.has_else = False


class _Compilation:
    """The Python source of one logic-free template."""

    def __init__(self):
        self.lines = []
        self.blocks = []  # innermost last

    def add(self, line):
        self.lines.append(_INDENT * len(self.blocks) + line)
        if self.blocks:
            self.blocks[-1].statements += 1

    def write(self, text):
        if text:
            self.add('%s(%r)' % (_WRITE, text))

    def expansion(self, expression):
        self.add('%s = (%s)' % (_VALUE, expression))
        self.add('if %s is not None: %s(%s(%s))' % (_VALUE, _WRITE, _STR, _VALUE))

    def control(self, contents):
        loop, branch, end = _FOR.match(contents), _BRANCH.match(contents), _END.match(contents)
        if loop:
            self.open('for', 'for %s in %s:' % loop.groups())
        elif branch and branch.group(1) == 'if':
            self.open('if', 'if %s:' % branch.group(2))
        elif branch or contents == 'else':
            if not self.blocks or self.blocks[-1].kind != 'if' or self.blocks[-1].has_else:
                raise _NotLogicFree()
            self.close()
            self.open('if', 'elif %s:' % branch.group(2) if branch else 'else:')
            self.blocks[-1].has_else = not branch
        elif end and self.blocks and self.blocks[-1].kind == end.group(1):
            self.close()
        else:
            raise _NotLogicFree()

    def open(self, kind, line):
        self.add(line)
        self.blocks.append(_Block(kind))

    def close(self):
        """Ends the innermost block's current branch, 'pass' where it
        writes nothing; an elif or else opens the next."""
        if not self.blocks[-1].statements:
            self.add('pass')
        self.blocks.pop()


def _compile(text, path):
    """One code object doing what empy does with the logic-free template
    text, or None where it holds more."""
    compilation = _Compilation()
    position = 0
    try:
        while True:
            prefix = text.find('@', position)
            compilation.write(text[position:] if prefix < 0 else text[position:prefix])
            if prefix < 0:
                break
            markup = _MARKUP.match(text, prefix)
            if not markup:
                raise _NotLogicFree()
            if markup.group('prefix'):
                compilation.write('@')
            elif markup.group('expansion'):
                compilation.expansion(markup.group('expansion'))
            elif markup.group('control') is not None:
                compilation.control(markup.group('control'))
            position = markup.end()
        if compilation.blocks:
            raise _NotLogicFree()
        return compile('\n'.join(compilation.lines) + '\n', path, 'exec')
    except (_NotLogicFree, SyntaxError):  # a keyword for a name: empy says what is wrong
        return None


@functools.lru_cache(maxsize=None)
def compiled_template(path):
    """The template at path compiled, once per process; None where it is
    not logic-free (empy's interpreter renders it)."""
    return _compile(_text(path), path)


@functools.lru_cache(maxsize=None)
def _text(path):
    with open(path) as template:
        return template.read()


def render_template(template_dir, template_name, **context):
    """The text of the empy template template_name in template_dir."""
    path = os.path.join(template_dir, template_name)
    code = compiled_template(path)
    if code is None:
        return render_with_empy(path, context)
    parts = []
    namespace = dict(context)
    namespace[_WRITE] = parts.append
    namespace[_STR] = str
    exec(code, namespace)
    return ''.join(parts)


def render_with_empy(path, context):
    """The template at path run by empy's public Interpreter over context."""
    output = io.StringIO()
    options = {'output': output, 'globals': dict(context)}
    if hasattr(em, 'Configuration'):  # empy 4
        # The proxy explicitly: the environment (EMPY_NO_PROXY) may not
        # choose. It is this interpreter's own and goes at its shutdown.
        config = em.Configuration(useProxy=True)
        if hasattr(config, 'supportModules'):  # empy >= 4.2: no finder in sys.meta_path
            config.supportModules = False
        # dispatcher=False: an error is raised, not printed with sys.exit().
        options.update(config=config, dispatcher=False)
    interpreter = em.Interpreter(**options)
    try:
        interpreter.string(_text(path))
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
