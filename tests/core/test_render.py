"""colcon_mros.core.render: empy templates rendered through empy's public
interpreter, in the process a real run has (no test runner's stdout)."""

import subprocess
import sys

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


# Every markup the package's templates use: comments, expressions,
# statements, for, if/elif/else, a nested template text and escapes.
MARKUPS = '''@# a comment line
@{
greeting = 'Hello'
}@
@(greeting), @(name)! @@ and @(len(items)) items:
@[for item in items]@
  - @(item)@[if item == 'b'] (second)@[elif item == 'c'] (third)@[else]@[end if]
@[end for]@
@[if not items]@
none
@[end if]@
'''


def _with_the_interpreters_string(text, **context):
    import io
    import em
    output = io.StringIO()
    interpreter = em.Interpreter(output=output, globals=dict(context))
    try:
        interpreter.string(text, 'markups.em')
        interpreter.flush()
        return output.getvalue()
    finally:
        interpreter.shutdown()


def test_scanned_tokens_run_again_as_the_interpreter_runs_the_text(tmp_path):
    from colcon_mros.core.render import render_template
    (tmp_path / 'markups.em').write_text(MARKUPS)
    for context in ({'name': 'board', 'items': ['a', 'b', 'c']}, {'name': 'PC', 'items': []},
                    {'name': 'board', 'items': ['c']}):
        expected = _with_the_interpreters_string(MARKUPS, **context)
        assert render_template(str(tmp_path), 'markups.em', **context) == expected
    assert render_template(str(tmp_path), 'markups.em', name='x', items=['b']) == (
        'Hello, x! @ and 1 items:\n  - b (second)\n')
