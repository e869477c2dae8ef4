# SPDX-License-Identifier: BSD-3-Clause
"""Malformed definitions and bad arguments: one clear line, non-zero exit, output untouched."""

import os
import shutil
import subprocess
import sys

import pytest

from support.checkout import REPO, TEST_WS, run_genmros
from support.file_trees import assert_one_line_error, snapshot, write_tree
from testing.ros_paths import prefix_arguments, ros1_package_dir, ros1_prefixes

PACKAGE_XML = '''<?xml version="1.0"?>
<package format="2">
  <name>mros_bad</name>
  <version>0.0.1</version>
  <description>Fixture package for malformed definitions.</description>
  <maintainer email="dev@colcon-mros.invalid">colcon-mros developers</maintainer>
  <license>BSD</license>
  <buildtool_depend>catkin</buildtool_depend>
</package>
'''

GOOD_MESSAGE = 'Header header\nstring name\nint32 value\n'

# (case id, files to add to package mros_bad, expected location, expected problem)
DEFINITION_CASES = [
    ('missing-field-name', {'msg/Bad.msg': 'int32 ok\nint32\n'},
     'msg/Bad.msg:2:', 'Invalid declaration: int32'),
    ('unknown-builtin', {'msg/Bad.msg': 'int33 x\n'},
     'msg/Bad.msg:1:', "unknown type 'mros_bad/int33'"),
    ('unknown-package', {'msg/Bad.msg': '# c\n\nnopkg/Thing x\n'}, 'msg/Bad.msg:3:',
     "unknown package 'nopkg' for type 'nopkg/Thing'"),
    ('unknown-type-in-package', {'msg/Bad.msg': 'int8 a\nstd_msgs/Nothing x\n'}, 'msg/Bad.msg:2:',
     "unknown type 'std_msgs/Nothing'"),
    ('bad-field-name', {'msg/Bad.msg': 'int32 1abc\n'},
     'msg/Bad.msg:1:', '1abc is not a legal message field name'),
    ('duplicate-field', {'msg/Bad.msg': 'int32 a\nstring b\nint32 a # again\n'}, 'msg/Bad.msg:3:',
     "duplicate field name 'a'"),
    ('constant-out-of-range', {'msg/Bad.msg': 'uint8 X=256\n'}, 'msg/Bad.msg:1:', 'out of bounds'),
    ('negative-unsigned-constant',
     {'msg/Bad.msg': 'int8 a\nuint32 X=-1\n'}, 'msg/Bad.msg:2:', 'out of bounds'),
    ('non-numeric-constant', {'msg/Bad.msg': 'int32 X=abc\n'},
     'msg/Bad.msg:1:', 'Invalid constant value'),
    ('bad-float-constant', {'msg/Bad.msg': 'float32 X=1.2.3\n'},
     'msg/Bad.msg:1:', 'Invalid constant value'),
    ('array-constant', {'msg/Bad.msg': 'int32[] X=1\n'},
     'msg/Bad.msg:1:', 'int32[] is not a legal constant type'),
    ('message-constant', {'msg/Bad.msg': 'Header X=1\n'},
     'msg/Bad.msg:1:', 'Header is not a legal constant type'),
    ('constant-without-name', {'msg/Bad.msg': 'int32 =1\n'},
     'msg/Bad.msg:1:', "'' is not a legal constant name"),
    ('two-dimensional-array', {'msg/Bad.msg': 'int32[][] grid\n'},
     'msg/Bad.msg:1:', 'invalid field'),
    ('bad-array-length', {'msg/Bad.msg': 'int32[x] a\n'},
     'msg/Bad.msg:1:', 'int32[x] is not a legal message field type'),
    ('duplicate-constant', {'msg/Bad.msg': 'int32 A=1\nint32 A=2\n'}, 'msg/Bad.msg:2:',
     "name 'A' is already declared on line 1"),
    ('constant-named-like-field', {'msg/Bad.msg': 'int32 value=1\nint32 value\n'},
     'msg/Bad.msg:2:', "name 'value' is already declared on line 1"),
    ('keyword-escape-collision', {'msg/Bad.msg': 'int32 class\nint32 class_\n'}, 'msg/Bad.msg:2:',
     "name 'class_' is already declared on line 1"),
    ('recursive-type', {'msg/Bad.msg': 'int32 depth\nBad child\n'}, 'msg/Bad.msg:2:',
     "type 'mros_bad/Bad' contains itself through field 'child'"),
    ('error-in-dependency',
     {'msg/Bad.msg': 'Inner inner\n', 'msg/Inner.msg': 'int32 a\nint32 b c\n'},
     'msg/Inner.msg:2:', 'Invalid declaration: int32 b c'),
    ('service-response-line', {'srv/Bad.srv': 'int32 a\n---\nint32 b\nfloat32 1x\n'},
     'srv/Bad.srv:4:', '1x is not a legal message field name'),
    ('service-unknown-type', {'srv/Bad.srv': 'Missing a\n---\n'},
     'srv/Bad.srv:1:', "unknown type 'mros_bad/Missing'"),
    ('not-utf8', {'msg/Bad.msg': b'# caf\xe9\nint32 a\n'}, 'msg/Bad.msg:1:', 'not UTF-8 text'),
    ('illegal-type-name', {'msg/Bad-Name.msg': 'int32 a\n'},
     'msg/Bad-Name.msg:', "'Bad-Name' is not a legal ROS type name"),
    # A close match is named: a built-in type, a type of the package, a package.
    ('misspelt-builtin', {'msg/Bad.msg': 'flaot64 x\n'}, 'msg/Bad.msg:1:',
     "unknown type 'mros_bad/flaot64' (no flaot64.msg in"),
    ('misspelt-builtin-named', {'msg/Bad.msg': 'flaot64 x\n'}, 'msg/Bad.msg:1:',
     "; did you mean 'float64'?)"),
    ('misspelt-type', {'msg/Bad.msg': 'std_msgs/Heder h\n'}, 'msg/Bad.msg:1:',
     "; did you mean 'Header'?)"),
    ('misspelt-package', {'msg/Bad.msg': 'std_msg/Header h\n'}, 'msg/Bad.msg:1:',
     "unknown package 'std_msg' for type 'std_msg/Header' (not in the workspace or the installed "
     "ROS packages; did you mean 'std_msgs'?)"),
]


@pytest.fixture
def workspace(tmp_path):
    """A workspace whose package mros_bad has one good message, already exported to out/."""
    package = tmp_path / 'ws' / 'src' / 'mros_bad'
    write_tree(str(package), {'package.xml': PACKAGE_XML, 'msg/Good.msg': GOOD_MESSAGE})
    output = tmp_path / 'out'
    run_genmros('mros-v1-export', '--workspace', str(tmp_path / 'ws'), '-o', str(output),
                *prefix_arguments(ros1_prefixes()))
    assert (output / 'mros_bad' / 'Good.h').is_file()
    return str(tmp_path / 'ws'), str(package), str(output)


@pytest.mark.parametrize('files, location, problem', [c[1:] for c in DEFINITION_CASES],
                         ids=[c[0] for c in DEFINITION_CASES])
def test_bad_definition_in_export(workspace, files, location, problem):
    workspace_dir, package, output = workspace
    write_tree(package, files)
    before = snapshot(output)
    result = run_genmros('mros-v1-export', '--workspace', workspace_dir, '-o', output,
                         *prefix_arguments(ros1_prefixes()),
                         check=False)
    assert_one_line_error(result, os.path.join(package, location), problem)
    assert snapshot(output) == before


@pytest.mark.parametrize('files, location, problem', [c[1:] for c in DEFINITION_CASES],
                         ids=[c[0] for c in DEFINITION_CASES])
def test_bad_definition_in_generator_mode(workspace, files, location, problem):
    _, package, output = workspace
    write_tree(package, files)
    target = [name for name in files if name.startswith(('msg/Bad', 'srv/Bad'))][0]
    before = snapshot(output)
    result = run_genmros('generate', os.path.join(package, target), '-p', 'mros_bad',
                         '-o', os.path.join(output, 'mros_bad'),
                         '-I', 'mros_bad:' + os.path.join(package, 'msg'),
                         '-I', 'std_msgs:' + ros1_package_dir('std_msgs'), check=False)
    assert_one_line_error(result, os.path.join(package, location), problem)
    assert snapshot(output) == before


ARGUMENT_CASES = [
    ('unknown-selected-type', ['--type', 'mros_bad/Nope'],
     "unknown type 'mros_bad/Nope' (package mros_bad has no"),
    ('malformed-selected-type', ['--type', 'Nope'],
     "bad type name 'Nope' (expected PACKAGE/TYPE)"),
    ('unknown-selected-package', ['--package', 'no_such_pkg'], "unknown package 'no_such_pkg'"),
    ('misspelt-selected-type', ['--type', 'mros_bad/Goood'],
     "unknown type 'mros_bad/Goood' (package mros_bad has no Goood.msg or Goood.srv; did you mean "
     "'Good'?)"),
    ('misspelt-selected-package', ['--package', 'mros_bda'],
     "unknown package 'mros_bda' (not in the workspace or the installed ROS packages; did you "
     "mean 'mros_bad'?)"),
]


@pytest.mark.parametrize('arguments, problem', [c[1:] for c in ARGUMENT_CASES],
                         ids=[c[0] for c in ARGUMENT_CASES])
def test_bad_export_selection(workspace, arguments, problem):
    workspace_dir, _, output = workspace
    before = snapshot(output)
    result = run_genmros('mros-v1-export', '--workspace', workspace_dir, '-o', output,
                         *prefix_arguments(ros1_prefixes()),
                         *arguments, check=False)
    assert_one_line_error(result, problem)
    assert snapshot(output) == before


def test_output_directory_that_is_a_file(workspace, tmp_path):
    workspace_dir, _, _ = workspace
    blocker = tmp_path / 'blocker'
    blocker.write_text('not a directory')
    result = run_genmros('mros-v1-export', '--workspace', workspace_dir, '-o',
                         str(blocker / 'include'), *prefix_arguments(ros1_prefixes()), check=False)
    assert_one_line_error(result, str(blocker), 'output directory is not a directory')
    assert blocker.read_text() == 'not a directory'


def test_unwritable_output_directory(workspace, tmp_path):
    workspace_dir, _, _ = workspace
    locked = tmp_path / 'locked'
    locked.mkdir()
    locked.chmod(0o555)
    try:
        if os.access(str(locked), os.W_OK):
            # root ignores permissions; a read-only bind is not available here,
            # so check the same path through a directory even root may not
            # create (EPERM in sysfs).
            target = '/sys/genmros-cannot-create/include'
        else:
            target = str(locked / 'include')
        result = run_genmros('mros-v1-export', '--workspace', workspace_dir, '-o', target,
                             *prefix_arguments(ros1_prefixes()),
                             check=False)
        assert_one_line_error(result, os.path.dirname(target), 'cannot write to output directory',
                              ': make it writable for this user, or give another (-o, '
                              'MROS_EXPORT_DIR, --mros-export)')
    finally:
        locked.chmod(0o755)


def test_missing_input_file(tmp_path):
    result = run_genmros('generate', str(tmp_path / 'Nope.msg'), '-p', 'mros_bad',
                         '-o', str(tmp_path / 'out' / 'mros_bad'), check=False)
    assert_one_line_error(result, str(tmp_path / 'Nope.msg'), 'cannot read file')
    assert not (tmp_path / 'out').exists()


def test_bad_include_flag(tmp_path):
    source = tmp_path / 'Good.msg'
    source.write_text(GOOD_MESSAGE)
    result = run_genmros('generate', str(source), '-p', 'mros_bad', '-o',
                         str(tmp_path / 'out'), '-I', 'std_msgs', check=False)
    assert_one_line_error(result, "bad include path 'std_msgs' (expected PACKAGE:DIRECTORY)")


def test_removed_type_leaves_no_header(workspace):
    workspace_dir, package, output = workspace
    write_tree(package, {'msg/Second.msg': 'int8 a\n'})
    run_genmros('mros-v1-export', '--workspace', workspace_dir, '-o', output,
                *prefix_arguments(ros1_prefixes()))
    assert os.path.isfile(os.path.join(output, 'mros_bad', 'Second.h'))
    os.remove(os.path.join(package, 'msg', 'Second.msg'))
    # A hand-written header beside the generated ones is not genmros' to remove.
    with open(os.path.join(output, 'mros_bad', 'Handwritten.h'), 'w') as stream:
        stream.write('#pragma once\n')
    run_genmros('mros-v1-export', '--workspace', workspace_dir, '-o', output,
                *prefix_arguments(ros1_prefixes()))
    assert not os.path.exists(os.path.join(output, 'mros_bad', 'Second.h'))
    assert os.path.isfile(os.path.join(output, 'mros_bad', 'Good.h'))
    assert os.path.isfile(os.path.join(output, 'mros_bad', 'Handwritten.h'))
    with open(os.path.join(output, 'message_headers.h')) as stream:
        assert 'mros_bad/Second.h' not in stream.read()


def test_unchanged_headers_keep_their_mtime(workspace):
    workspace_dir, _, output = workspace
    before = snapshot(output)
    run_genmros('mros-v1-export', '--workspace', workspace_dir, '-o', output,
                *prefix_arguments(ros1_prefixes()))
    assert snapshot(output) == before


def test_failed_write_changes_no_file(workspace):
    workspace_dir, package, output = workspace
    write_tree(package, {'msg/Good.msg': GOOD_MESSAGE + 'float64 added\n'})
    # std_msgs/Header.h sorts after the headers that would change, so they are
    # already written out (to temporaries) when std_msgs/ turns out to be a file.
    shutil.rmtree(os.path.join(output, 'std_msgs'))
    with open(os.path.join(output, 'std_msgs'), 'w') as stream:
        stream.write('in the way\n')
    before = snapshot(output)
    result = run_genmros('mros-v1-export', '--workspace', workspace_dir, '-o', output,
                         *prefix_arguments(ros1_prefixes()), check=False)
    assert_one_line_error(result, 'cannot write to output directory')
    assert snapshot(output) == before


@pytest.mark.parametrize('mode', ['export', 'generator'])
def test_relative_output_paths_whose_first_part_is_new(tmp_path, mode):
    # The common call from a build or app directory: genmros ... -o include
    if mode == 'export':
        arguments = ['mros-v1-export', '--workspace', TEST_WS, '--type', 'mros_test/PersonalData',
                     '-o', os.path.join('new', 'include'), *prefix_arguments(ros1_prefixes())]
        written = tmp_path / 'new' / 'include' / 'mros_test' / 'PersonalData.h'
    else:
        arguments = ['generate',
                     os.path.join(TEST_WS, 'src', 'mros_test', 'msg', 'PersonalData.msg'),
                     '-p', 'mros_test', '-o', os.path.join('new', 'mros_test')]
        written = tmp_path / 'new' / 'mros_test' / 'PersonalData.h'
    result = subprocess.run([sys.executable, '-m', 'colcon_mros'] + arguments, cwd=str(tmp_path),
                            env=dict(os.environ, PYTHONPATH=REPO), capture_output=True, text=True)
    assert result.returncode == 0, result.stderr
    assert written.is_file()
