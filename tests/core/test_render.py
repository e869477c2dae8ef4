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
