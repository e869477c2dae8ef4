# SPDX-License-Identifier: BSD-3-Clause
"""colcon_mros.core.render: logic-free templates, compiled once into Python,
render as empy's own interpreter renders them, under empy 3 and empy 4,
in the process a real run has (no test runner's stdout) too; any other
template (a user's, genmros -e) renders through empy's interpreter, the
same under both."""

import glob
import json
import os
import re
import shutil
import subprocess
import sys

import pytest

from support.checkout import REPO
from testing import ros_paths

# Two compiled renders, one through empy's interpreter, then rosidl_adapter's own
# template, in one process, as genmros mros2-export and colcon's --mros-export run them.
RENDERS_IN_ONE_PROCESS = '''
import os, sys
sys.path.insert(0, %r)
from colcon_mros.core.render import compiled_template, render_template
directory = sys.argv[1]
for name, text in [('t.em', '@(greeting), @(name)!\\n'),
                   ('logic.em', '@{total = 1 + 2}@total\\n')]:
    with open(os.path.join(directory, name), 'w') as stream:
        stream.write(text)
print(render_template(directory, 't.em', greeting='Hello', name='board'), end='')
print(render_template(directory, 't.em', greeting='Bye', name='PC'), end='')
print(compiled_template(os.path.join(directory, 'logic.em')),
      render_template(directory, 'logic.em'), end='')
from rosidl_adapter.parser import parse_message_string
from rosidl_adapter.resource import evaluate_template
idl = evaluate_template('msg.idl.em', {'pkg_name': 'demo', 'relative_input_file': 'msg/A.msg',
                                       'msg': parse_message_string('demo', 'A', 'int32 x')})
print('int32 x;' in idl)
''' % REPO


def _skip_where_rosidl_adapter_takes_not_this_empy():
    """rosidl_adapter renders .msg files with this python's empy, or the test
    skips saying why (Debian's rosidl_adapter under empy 4)."""
    from colcon_mros.errors import GenmrosError
    from colcon_mros.ros2.parse import require_an_adapter_for_this_empy
    try:
        require_an_adapter_for_this_empy()
    except GenmrosError as error:
        pytest.skip(str(error))


def test_a_process_renders_many_templates_with_its_own_stdout(tmp_path):
    _skip_where_rosidl_adapter_takes_not_this_empy()
    result = subprocess.run([sys.executable, '-c', RENDERS_IN_ONE_PROCESS, str(tmp_path)],
                            capture_output=True, text=True)
    assert (result.stdout, result.stderr) == ('Hello, board!\nBye, PC!\nNone 3\nTrue\n', '')


# Every markup the package's templates use, and some they may: comments,
# expressions (None writes nothing), for, if/elif/else, nesting, escapes.
MARKUPS = '''@# a comment line
@(greeting), @( name )! @@ and @(count) items@(nothing):
@[for item, label in items]@
  - @(item)@[if item.second] (second)@[elif item.third] (third)@[else]@[end if] @(label)
@[end for]@
@[if not items]@
none
@[end if]@
'''


class Item:
    def __init__(self, name, second=False, third=False):
        self.name, self.second, self.third = name, second, third

    def __str__(self):
        return self.name


def test_a_logic_free_template_renders_as_empys_interpreter_renders_it(tmp_path):
    from colcon_mros.core.render import compiled_template, render_template, render_with_empy
    path = tmp_path / 'markups.em'
    path.write_text(MARKUPS)
    assert compiled_template(str(path)) is not None
    items = [(Item('a'), 1), (Item('b', second=True), 2), (Item('c', third=True), None)]
    for context in ({'name': 'board', 'items': items}, {'name': 'PC', 'items': []},
                    {'name': 'board', 'items': items[2:]}):
        context.update(greeting='Hello', nothing=None, count=len(context['items']))
        assert render_template(str(tmp_path), 'markups.em', **context) == \
            render_with_empy(str(path), context)
    assert render_template(str(tmp_path), 'markups.em', greeting='Hi', name='x', count=1,
                           items=items[1:2], nothing=None) == \
        'Hi, x! @ and 1 items:\n  - b (second) 2\n'


def test_every_template_of_the_package_renders_as_empys_interpreter_renders_it():
    """With a context that answers every name and attribute: each real
    template compiled, against empy running it."""
    from colcon_mros.core.render import compiled_template, render_template, render_with_empy

    class Anything:
        def __getattr__(self, name):
            return Anything()

        def __iter__(self):
            return iter([Anything(), Anything()])

        def __str__(self):
            return 'value'

    for path in sorted(glob.glob(os.path.join(REPO, 'colcon_mros', '*', 'templates', '*.em'))):
        with open(path) as stream:
            names = {name: Anything() for name in re.findall(r'[A-Za-z_]\w*', stream.read())}
        assert compiled_template(path) is not None, path
        assert render_template(os.path.dirname(path), os.path.basename(path), **names) == \
            render_with_empy(path, names), path


# Run by each empy's python: templates made at random of every logic-free
# markup, nested, with text that looks like markup; each rendered compiled and
# through empy's interpreter (an error counts as its type). Prints the
# templates whose two texts differ, as JSON.
RANDOM_TEMPLATES = '''
import json, os, random, sys, tempfile
from colcon_mros.core import render

TEXT = ['text ', '\\n', '  ', '@@', '@# comment\\n', '@ ', '@\\n', ')', ']', '(', '[', '#',
        '@(a)', '@( a )', '@(a.b)', '@(a.none)', '@(none)', '@(i)', '@(j)', '@(flag)']
LOOPS = ['@[for i in items]', '@[for i, j in pairs]', '@[for i,j in pairs]', '@[for i in empty]']
TESTS = ['a', 'not a', 'flag', 'not flag', 'none', 'empty', 'a.b']
random = random.Random(59)


def block(depth):
    parts = []
    for _ in range(random.randint(0, 4)):
        choice = random.random()
        if choice < 0.6 or depth > 3:
            parts.append(random.choice(TEXT))
            continue
        if choice < 0.8:
            part = random.choice(LOOPS) + block(depth + 1) + '@[end for]'
        else:
            part = '@[if %s]' % random.choice(TESTS) + block(depth + 1)
            for _ in range(random.randint(0, 2)):
                part += '@[elif %s]' % random.choice(TESTS) + block(depth + 1)
            if random.random() < 0.5:
                part += '@[else]' + block(depth + 1)
            part += '@[end if]'
        parts.append(part + random.choice(['', '@\\n', '\\n']))
    return ''.join(parts)


class Thing:
    b = 'B'
    none = None

    def __str__(self):
        return 'thing'


def text(render_it):
    try:
        return render_it()
    except Exception as error:
        return type(error).__name__


directory = tempfile.mkdtemp()
differ = []
for count in range(int(sys.argv[1])):
    template = block(0)
    path = os.path.join(directory, '%d.em' % count)
    with open(path, 'w') as stream:
        stream.write(template)
    context = {'a': Thing(), 'flag': False, 'none': None, 'items': [1, 2],
               'pairs': [(1, 2), (3, 4)], 'empty': [], 'i': 'i', 'j': 'j'}
    compiled = text(lambda: render.render_template(directory, '%d.em' % count, **context))
    interpreted = text(lambda: render.render_with_empy(path, context))
    if render.compiled_template(path) is None or compiled != interpreted:
        differ.append([template, compiled, interpreted])
print(json.dumps(differ))
'''


def test_random_logic_free_templates_render_as_empy_3_and_4_render_them(request):
    for python in ('/usr/bin/python3', request.getfixturevalue('empy4_python')):
        result = subprocess.run([python, '-c', RANDOM_TEMPLATES, '500'], capture_output=True,
                                text=True, env=dict(os.environ, PYTHONPATH=REPO))
        assert (result.returncode, result.stderr) == (0, ''), python
        assert json.loads(result.stdout) == [], python


# Markups beyond the logic-free ones (a statement, a simple expression, a call, a
# conditional expression, for over a call, while, a control markup left open, a
# comment at the end without a newline), each rendered by empy's interpreter.
NOT_LOGIC_FREE = [
    ('@{total = 1 + 2}@(total)\n', {}, '3\n'),
    ('@name!\n', {'name': 'board'}, 'board!\n'),
    ('@(len(items))\n', {'items': [1, 2]}, '2\n'),
    ('@(flag ? "yes" ! "no")\n', {'flag': False}, 'no\n'),
    ('@[for i in range(3)]@(i)@[end for]\n', {}, '012\n'),
    ('@{n = 2}@[while n]@{n -= 1}@(n)@[end while]\n', {}, '10\n'),
    ('@[if flag]yes@[end for]\n', {'flag': True}, None),
    ('text @# no newline', {}, 'text '),
]


@pytest.mark.parametrize('text, context, expected', NOT_LOGIC_FREE)
def test_any_other_template_renders_through_empys_interpreter(tmp_path, text, context, expected):
    from colcon_mros.core.render import compiled_template, render_template
    (tmp_path / 'logic.em').write_text(text)
    assert compiled_template(str(tmp_path / 'logic.em')) is None
    if expected is None:  # empy's own error
        with pytest.raises(Exception):
            render_template(str(tmp_path), 'logic.em', **context)
    else:
        assert render_template(str(tmp_path), 'logic.em', **context) == expected


# Both ways over real contexts: every template of the package, with the
# contexts genmros' own runs give it (an mROS v1 export of Debian's std_msgs,
# std_srvs and geometry_msgs with its aggregates, an export dir's cmake
# table, the mros2 headers and templates.hpp of ROS 2's test interface
# files), rendered compiled and through empy 3's interpreter here, and so in
# a venv with empy 4 from PyPI (tests/conftest.py). What crosses to the venv
# is each context as the template saw it: a traced render records, of every
# object it reaches, the attributes read, the items iterated, str() and
# truth, and the venv rebuilds those answers.

PLAIN = (type(None), bool, int, float, str)


class _Traced:
    """An object of a context, answering as it does and recording what the
    template asked of it."""

    def __init__(self, value):
        self._value = value
        self._node = {'attributes': {}}

    def __getattr__(self, name):
        attributes = self._node['attributes']
        if name not in attributes:
            attributes[name] = _traced(getattr(self._value, name))
        return attributes[name]

    def __iter__(self):
        if 'items' not in self._node:
            self._node['items'] = [_traced(item) for item in self._value]
        return iter(self._node['items'])

    def __str__(self):
        self._node['str'] = str(self._value)
        return self._node['str']

    def __bool__(self):
        self._node['bool'] = bool(self._value)
        return self._node['bool']


def _traced(value):
    return value if isinstance(value, PLAIN) else _Traced(value)


def _recorded(value):
    """What the template saw of value, as JSON."""
    if isinstance(value, PLAIN):
        return {'value': value}
    node = {key: part for key, part in value._node.items() if key != 'attributes'}
    node['attributes'] = {name: _recorded(child)
                          for name, child in value._node['attributes'].items()}
    if 'items' in node:
        node['items'] = [_recorded(item) for item in node['items']]
    return {'object': node}


# Run in the venv: renders each recorded context (JSON on stdin) through
# colcon_mros.core.render, compiled and through empy's interpreter, the
# checkout on PYTHONPATH, and writes the texts and what it found to the
# file argv[1].
EMPY4_RENDERS = '''
import json, os, sys
import em
from colcon_mros.core import render


class Recorded:
    def __init__(self, node):
        self._node = node

    def __getattr__(self, name):
        if name.startswith('__') or name not in self._node['attributes']:
            raise AttributeError(name)
        return decoded(self._node['attributes'][name])

    def __iter__(self):
        return iter([decoded(item) for item in self._node['items']])

    def __str__(self):
        return self._node['str']

    def __bool__(self):
        return self._node['bool']


def decoded(node):
    return node['value'] if 'value' in node else Recorded(node['object'])


renders = json.load(sys.stdin)
before = (sys.stdout, list(sys.meta_path))
texts = []
for r in renders:
    context = {k: decoded(v) for k, v in r['context'].items()}
    texts.append([render.render_template(r['dir'], r['name'], **context),
                  render.render_with_empy(os.path.join(r['dir'], r['name']), context)])
with open(sys.argv[1], 'w') as stream:
    json.dump({'version': em.__version__, 'texts': texts,
               'stdout_and_meta_path_kept': (sys.stdout, list(sys.meta_path)) == before}, stream)
'''


def _real_renders(tmp_path, monkeypatch):
    """[(template_dir, template_name, context, text)] of genmros' own runs,
    contexts traced: each render done the fast way with the traced context
    and with the real one, the same text."""
    from colcon_mros import cli
    from colcon_mros.core import render
    from colcon_mros.core.storage import HeapStorage
    from colcon_mros.mros2 import render as mros2_render
    from colcon_mros.mros2.endpoints import parse_endpoints
    from colcon_mros.mros_v1 import aggregates, fit_check_header
    from colcon_mros.mros_v1 import render as mros_v1_render
    from colcon_mros.ros2.interfaces import all_packages
    from colcon_mros.ros2.model import ModelBuilder
    renders = []
    fast = render.render_template

    def recording(template_dir, template_name, **context):
        traced = {name: _traced(value) for name, value in context.items()}
        text = fast(template_dir, template_name, **traced)
        assert text == fast(template_dir, template_name, **context), template_name
        renders.append((template_dir, template_name, traced, text))
        return text

    for module in (render, mros_v1_render, aggregates, fit_check_header, mros2_render):
        monkeypatch.setattr(module, 'render_template', recording)
    std_msgs = ros_paths.ros1_package_dir('std_msgs')
    assert cli.main(['mros-v1-export', '-o', str(tmp_path / 'v1'), '--package', 'std_msgs',
                     '--package', 'std_srvs', '--package', 'geometry_msgs']
                    + ros_paths.prefix_arguments(ros_paths.ros1_prefixes())) == 0
    assert cli.main(['generate', os.path.join(std_msgs, 'Header.msg'), '-p', 'std_msgs',
                     '-o', str(tmp_path / 'generated'), '-I', 'std_msgs:%s' % std_msgs,
                     '--add-to-export-dir', str(tmp_path / 'export_dir')]) == 0
    package = 'test_interface_files'
    builder = ModelBuilder(all_packages((), ros_paths.ros2_prefixes()), HeapStorage())
    interfaces = sorted(builder.packages[package].interfaces)
    messages = [builder.message('%s/msg/%s' % (package, n)) for k, n in interfaces if k == 'msg']
    for message in messages:
        mros2_render.message_header(message)
    for kind, name in interfaces:
        if kind == 'srv':
            mros2_render.service_header(builder.service('%s/srv/%s' % (package, name)))
    endpoints, _ = parse_endpoints(['%s/msg/%s' % (package, n) for k, n in interfaces
                                    if k == 'msg'][:3], ['topic:%s/msg/Strings' % package],
                                   builder.message)
    mros2_render.templates_header(endpoints)
    mros2_render.peer_profile(1472, 4194304)
    return renders


def test_every_template_renders_the_same_bytes_compiled_and_through_empy_3_and_4(
        tmp_path, monkeypatch, request):
    from colcon_mros.core import render
    _skip_where_rosidl_adapter_takes_not_this_empy()
    renders = _real_renders(tmp_path, monkeypatch)
    monkeypatch.undo()
    templates = sorted(glob.glob(os.path.join(REPO, 'colcon_mros', '*', 'templates', '*.em')))
    assert sorted({os.path.join(d, n) for d, n, _, _ in renders}) == templates
    # This python's empy (Debian's empy 3), here, over the traced contexts.
    for template_dir, name, context, text in renders:
        assert render.render_with_empy(os.path.join(template_dir, name), context) == text, name
    # empy 4's, in the venv, over what the traced renders recorded (after
    # the above, which a skip for want of PyPI does not skip).
    empy4_python = request.getfixturevalue('empy4_python')
    out = tmp_path / 'empy4.json'
    recorded = json.dumps([{'dir': d, 'name': n, 'context': {k: _recorded(v)
                                                             for k, v in c.items()}}
                           for d, n, c, _ in renders])
    result = subprocess.run([empy4_python, '-c', EMPY4_RENDERS, str(out)], input=recorded,
                            capture_output=True, text=True, env=dict(os.environ, PYTHONPATH=REPO))
    assert (result.returncode, result.stdout, result.stderr) == (0, '', '')
    empy4 = json.loads(out.read_text())
    print('empy %s: %d templates, %d renders' % (empy4['version'], len(templates), len(renders)))
    assert empy4['version'].startswith('4.') and empy4['stdout_and_meta_path_kept']
    for (_, name, _, text), (compiled, interpreted) in zip(renders, empy4['texts']):
        assert (compiled.encode(), interpreted.encode()) == (text.encode(), text.encode()), name


# A user's template directory (genmros -e): the package's mROS v1 templates,
# msg.h.em with a statement and expressions no template of the package holds.
USERS_LINES = ('@{names = [msg.name] * 2}@\n'
               '// @(", ".join(names)), @(len(names)) times'
               '@[if msg.name == "Header"] (std_msgs)@[end if]\n')


def test_a_users_template_directory_renders_the_same_under_empy_3_and_4(tmp_path, request):
    templates = str(tmp_path / 'templates')
    shutil.copytree(os.path.join(REPO, 'colcon_mros', 'mros_v1', 'templates'), templates)
    with open(os.path.join(templates, 'msg.h.em'), 'a') as stream:
        stream.write(USERS_LINES)
    header = os.path.join(ros_paths.ros1_package_dir('std_msgs'), 'Header.msg')
    texts = []
    for empy, python in [('empy3', '/usr/bin/python3'),
                         ('empy4', request.getfixturevalue('empy4_python'))]:
        output = str(tmp_path / empy)
        result = subprocess.run([python, '-m', 'colcon_mros', 'generate', header, '-p', 'std_msgs',
                                 '-o', output, '-e', templates], capture_output=True, text=True,
                                cwd=REPO)
        assert (result.returncode, result.stderr) == (0, ''), empy
        with open(os.path.join(output, 'Header.h')) as stream:
            texts.append(stream.read())
    assert texts[0].endswith('// Header, Header, 2 times (std_msgs)\n')
    assert texts[1] == texts[0]
