# SPDX-License-Identifier: BSD-3-Clause
"""colcon_mros.core.render: empy templates, translated once into Python,
render as empy's own interpreter renders them, in the process a real run
has (no test runner's stdout) too; what a logic-free template may not
hold is refused."""

import re
import subprocess
import sys

import pytest

from conftest import REPO

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
