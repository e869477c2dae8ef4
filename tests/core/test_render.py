# SPDX-License-Identifier: BSD-3-Clause
"""colcon_mros.core.render: empy templates, translated once into Python,
render as empy's own interpreter renders them, in the process a real run
has (no test runner's stdout) too; what a logic-free template may not
hold is refused."""

import glob
import json
import os
import re
import subprocess
import sys

import pytest

from support.checkout import REPO
from testing import ros_paths

# Two renders, then rosidl_adapter's own template, in one process, as
# genmros mros2-export and colcon's --mros-export run them.
TWO_RENDERS = '''
import os, sys
sys.path.insert(0, %r)
from colcon_mros.core.render import render_template
directory = sys.argv[1]
with open(os.path.join(directory, 't.em'), 'w') as stream:
    stream.write('@(greeting), @(name)!\\n')
print(render_template(directory, 't.em', greeting='Hello', name='board'), end='')
print(render_template(directory, 't.em', greeting='Bye', name='PC'), end='')
from rosidl_adapter.parser import parse_message_string
from rosidl_adapter.resource import evaluate_template
idl = evaluate_template('msg.idl.em', {'pkg_name': 'demo', 'relative_input_file': 'msg/A.msg',
                                       'msg': parse_message_string('demo', 'A', 'int32 x')})
print('int32 x;' in idl)
''' % REPO


def test_a_process_renders_many_templates_with_its_own_stdout(tmp_path):
    result = subprocess.run([sys.executable, '-c', TWO_RENDERS, str(tmp_path)],
                            capture_output=True, text=True)
    assert (result.stdout, result.stderr) == ('Hello, board!\nBye, PC!\nTrue\n', '')


# Every markup the package's templates use, and some they may: comments,
# expressions (None writes nothing), for, if/elif/else, nesting, escapes.
MARKUPS = '''@# a comment line
@(greeting), @name! @@ and @(len(items)) items@(nothing):
@[for item in items]@
  - @(item)@[if item == 'b'] (second)@[elif item == 'c'] (third)@[else]@[end if]
@[end for]@
@[if not items]@
none
@[end if]@
'''


def _with_the_interpreters_string(template_text, **context):
    import io
    import em
    output = io.StringIO()
    interpreter = em.Interpreter(output=output, globals=dict(context))
    try:
        interpreter.string(template_text, 'markups.em')
        interpreter.flush()
        return output.getvalue()
    finally:
        interpreter.shutdown()


def test_a_translated_template_renders_as_empys_interpreter_renders_it(tmp_path):
    from colcon_mros.core.render import render_template
    (tmp_path / 'markups.em').write_text(MARKUPS)
    for context in ({'name': 'board', 'items': ['a', 'b', 'c']}, {'name': 'PC', 'items': []},
                    {'name': 'board', 'items': ['c']}):
        context.update(greeting='Hello', nothing=None)
        expected = _with_the_interpreters_string(MARKUPS, **context)
        assert render_template(str(tmp_path), 'markups.em', **context) == expected
    assert render_template(str(tmp_path), 'markups.em', greeting='Hi', name='x', items=['b'],
                           nothing=None) == 'Hi, x! @ and 1 items:\n  - b (second)\n'


def test_every_template_of_the_package_renders_as_empys_interpreter_renders_it():
    """With a context that answers every name and attribute: the translation
    of each real template, against empy running it."""
    import glob
    import os
    from colcon_mros.core.render import render_template

    class Anything:
        def __getattr__(self, name):
            return Anything()

        def __iter__(self):
            return iter([Anything(), Anything()])

        def __str__(self):
            return 'value'

    for path in sorted(glob.glob(os.path.join(REPO, 'colcon_mros', '*', 'templates', '*.em'))):
        with open(path) as stream:
            text = stream.read()
        names = {name: Anything() for name in re.findall(r'[A-Za-z_]\w*', text)}
        assert render_template(os.path.dirname(path), os.path.basename(path), **names) == \
            _with_the_interpreters_string(text, **names), path


def test_a_statement_is_refused_when_the_template_is_read(tmp_path):
    from colcon_mros.core.render import render_template
    (tmp_path / 'logic.em').write_text('@{total = 1 + 2}@(total)\n')
    with pytest.raises(ValueError) as error:
        render_template(str(tmp_path), 'logic.em')
    assert str(error.value) == ('%s: @{total = 1 + 2} is more than a logic-free template holds'
                                % (tmp_path / 'logic.em'))


# Both ways over real contexts: every template of the package, with the
# contexts genmros' own runs give it (an mROS v1 export of Debian's std_msgs,
# std_srvs and geometry_msgs with its aggregates, an export dir's cmake
# table, the mros2 headers and templates.hpp of ROS 2's test interface
# files), rendered here the fast way, here through empy 3's interpreter, and
# in a venv with empy 4 from PyPI (no genmsg, no rosidl there) through empy
# 4's. What crosses to the venv is each context as the template saw it: a
# traced render records, of every object it reaches, the attributes read,
# the items iterated, str() and truth, and the venv rebuilds those answers.

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
# colcon_mros.core.render, the checkout on PYTHONPATH, and writes the texts
# and what it found to the file argv[1].
EMPY4_RENDERS = '''
import json, sys
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
texts = [render.render_template(r['dir'], r['name'],
                                **{k: decoded(v) for k, v in r['context'].items()})
         for r in renders]
with open(sys.argv[1], 'w') as stream:
    json.dump({'version': em.__version__, 'translates': render.TRANSLATES, 'texts': texts,
               'stdout_and_meta_path_kept': (sys.stdout, list(sys.meta_path)) == before,
               'proxy_left': hasattr(sys, '_EmPy_proxy')}, stream)
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


@pytest.fixture(scope='session')
def empy4_python(tmp_path_factory):
    """A venv's python with empy 4 from PyPI and no system site packages,
    made once per session; the test skips, saying why, without PyPI."""
    venv = str(tmp_path_factory.mktemp('empy4_venv'))
    subprocess.run(['/usr/bin/python3', '-m', 'venv', venv], check=True)
    python = os.path.join(venv, 'bin', 'python')
    result = subprocess.run([python, '-m', 'pip', 'install', '-q', 'empy>=4,<5'],
                            capture_output=True, text=True)
    if result.returncode != 0:
        pytest.skip('no empy 4 from PyPI for the venv: %s'
                    % (result.stderr.strip().splitlines() or ['pip failed'])[-1])
    return python


def test_every_template_renders_the_same_bytes_translated_and_through_empy_3_and_4(
        tmp_path, monkeypatch, request):
    from colcon_mros.core import render
    assert render.TRANSLATES  # Debian's empy 3
    renders = _real_renders(tmp_path, monkeypatch)
    monkeypatch.undo()
    templates = sorted(glob.glob(os.path.join(REPO, 'colcon_mros', '*', 'templates', '*.em')))
    assert sorted({os.path.join(d, n) for d, n, _, _ in renders}) == templates
    # empy 3's interpreter, here, over the traced contexts.
    monkeypatch.setattr(render, 'TRANSLATES', False)
    for template_dir, name, context, text in renders:
        assert render.render_template(template_dir, name, **context) == text, name
    monkeypatch.undo()
    # empy 4's, in the venv, over what the traced renders recorded (after
    # the above, which a skip for want of PyPI does not skip).
    empy4_python = request.getfixturevalue('empy4_python')
    out = tmp_path / 'empy4.json'
    request = json.dumps([{'dir': d, 'name': n, 'context': {k: _recorded(v)
                                                            for k, v in c.items()}}
                          for d, n, c, _ in renders])
    result = subprocess.run([empy4_python, '-c', EMPY4_RENDERS, str(out)], input=request,
                            capture_output=True, text=True, env=dict(os.environ, PYTHONPATH=REPO))
    assert (result.returncode, result.stdout, result.stderr) == (0, '', '')
    empy4 = json.loads(out.read_text())
    print('empy %s: %d templates, %d renders' % (empy4['version'], len(templates), len(renders)))
    assert empy4['version'].startswith('4.') and not empy4['translates']
    assert empy4['stdout_and_meta_path_kept'] and not empy4['proxy_left']
    for (_, name, _, text), empy4_text in zip(renders, empy4['texts']):
        assert empy4_text.encode() == text.encode(), name
