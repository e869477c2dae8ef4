# SPDX-License-Identifier: BSD-3-Clause
"""The rosidl generator's entry point (colcon_mros.integrations.rosidl_generator)
over arguments files as rosidl_write_generator_arguments() writes them: what
rosidl_generate_interfaces() hands it on each rosidl line. The CMake side,
built with colcon, is test_rosidl_extension.py's."""

import json
import os
import subprocess
import sys

import pytest

from support.checkout import REPO

PING_IDL = '''module demo {
  module msg {
    struct Ping {
      int32 value;
    };
  };
};
'''
# An action's .idl, as rosidl_adapter writes one (mros2 has no actions).
FIBONACCI_IDL = '''module demo {
  module action {
    struct Fibonacci_Goal {
      int32 order;
    };
    struct Fibonacci_Result {
      sequence<int32> sequence;
    };
    struct Fibonacci_Feedback {
      sequence<int32> partial_sequence;
    };
  };
};
'''
# Humble's rosidl (3.1) has no rosidl_pycommon; its helpers are the Python
# module rosidl_cmake. This start-up makes the modules its first argument
# names unimportable, puts the directory its second names and the checkout
# first on the path, and runs the entry point on the rest.
WITHOUT_MODULES = '''
import sys
blocked = sys.argv.pop(1).split(',')
class Blocked:
    def find_spec(self, name, path=None, target=None):
        if name.split('.')[0] in blocked:
            raise ModuleNotFoundError('No module named %%r' %% name)
        return None
sys.meta_path.insert(0, Blocked())
sys.path[:0] = [sys.argv.pop(1), %r]
from colcon_mros.integrations.rosidl_generator import main
sys.exit(main(sys.argv[1:]))
''' % REPO


def _write(path, text):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, 'w') as stream:
        stream.write(text)
    return path


def _arguments_file(tmp_path, **arguments):
    arguments.setdefault('package_name', 'demo')
    arguments.setdefault('output_dir', str(tmp_path / 'out'))
    return _write(str(tmp_path / 'arguments.json'), json.dumps(arguments))


def _run(*arguments):
    return subprocess.run([sys.executable, '-m', 'colcon_mros.integrations.rosidl_generator']
                          + list(arguments), capture_output=True, text=True, cwd=REPO)


def _written(tmp_path):
    root = str(tmp_path / 'out')
    return sorted(os.path.relpath(os.path.join(d, name), root)
                  for d, _, names in os.walk(root) for name in names)


def test_an_action_is_skipped_with_one_line_and_the_rest_is_written(tmp_path):
    base = str(tmp_path / 'adapter')
    _write(os.path.join(base, 'msg', 'Ping.idl'), PING_IDL)
    _write(os.path.join(base, 'action', 'Fibonacci.idl'), FIBONACCI_IDL)
    result = _run('--generator-arguments-file', _arguments_file(
        tmp_path, idl_tuples=['%s:msg/Ping.idl' % base, '%s:action/Fibonacci.idl' % base]))
    assert (result.returncode, result.stderr) == (0, '')
    assert result.stdout == ('rosidl_generator_mros2: skipped demo/action/Fibonacci: mros2 has '
                             'no actions\n')
    # The support headers are the generator's install's, not the package's.
    assert _written(tmp_path) == ['demo/msg/ping.hpp']


def test_an_error_names_the_msg_the_user_wrote_at_its_line(tmp_path):
    # rosidl_adapter's .idl is a form of the .msg; genmros reads the .msg,
    # which ros_interface_files (the target's sources) names.
    base = str(tmp_path / 'adapter')
    _write(os.path.join(base, 'msg', 'Ping.idl'), PING_IDL)
    source = _write(str(tmp_path / 'src' / 'msg' / 'Ping.msg'), 'int32 value\nother/Inner inner\n')
    result = _run('--generator-arguments-file', _arguments_file(
        tmp_path, idl_tuples=['%s:msg/Ping.idl' % base], ros_interface_files=[source]))
    assert (result.returncode, result.stdout) == (1, '')
    assert result.stderr == ("genmros: error: %s:2: unknown package 'other' of type "
                             "'other/msg/Inner' (not in the workspace or the installed ROS 2 "
                             'packages; rosidl_generate_interfaces() passes only the packages it '
                             'names: add other to its DEPENDENCIES, with find_package(other '
                             'REQUIRED) before it)\n' % source)
    assert _written(tmp_path) == []


def test_contained_types_come_from_the_dependencies_listed(tmp_path):
    base = str(tmp_path / 'adapter')
    _write(os.path.join(base, 'msg', 'Wrapped.idl'), PING_IDL.replace(
        'int32 value;', 'other::msg::Inner inner;').replace('Ping', 'Wrapped').replace(
        'module demo {', '#include "other/msg/Inner.idl"\nmodule demo {'))
    inner = _write(str(tmp_path / 'prefix' / 'share' / 'other' / 'msg' / 'Inner.idl'),
                   PING_IDL.replace('demo', 'other').replace('Ping', 'Inner'))
    result = _run('--generator-arguments-file', _arguments_file(
        tmp_path, idl_tuples=['%s:msg/Wrapped.idl' % base],
        ros_interface_dependencies=['other:%s' % inner]))
    assert (result.returncode, result.stderr) == (0, '')
    # The contained type's header is its own package's to write.
    assert _written(tmp_path) == ['demo/msg/wrapped.hpp']
    with open(str(tmp_path / 'out' / 'demo' / 'msg' / 'wrapped.hpp')) as stream:
        assert 'other::msg::Inner inner;' in stream.read()


def test_a_missing_arguments_file_is_one_line(tmp_path):
    missing = str(tmp_path / 'none.json')
    result = _run('--generator-arguments-file', missing)
    assert (result.returncode, result.stdout) == (1, '')
    assert result.stderr == ('genmros: error: %s: cannot read the generator arguments: No such '
                             'file or directory\n' % missing)


def test_the_depfile_names_its_code_templates_and_static_headers(tmp_path):
    base = str(tmp_path / 'adapter')
    _write(os.path.join(base, 'msg', 'Ping.idl'), PING_IDL)
    depfile, stamp = str(tmp_path / 'out dir' / 'rule.stamp.d'), str(tmp_path / 'rule.stamp')
    result = _run('--generator-arguments-file', _arguments_file(
        tmp_path, package_name='demo', output_dir=str(tmp_path / 'out'),
        idl_tuples=['%s:msg/Ping.idl' % base]), '--dependency-file', depfile,
        '--dependency-target', stamp)
    assert result.returncode == 0, result.stderr
    with open(depfile) as stream:
        target, _, dependencies = stream.read().partition(': ')
    assert target == stamp
    files = [name.strip() for name in dependencies.split(' \\\n')]
    package = os.path.join(REPO, 'colcon_mros')
    for relative in ('mros2/templates/message_class.hpp.em',
                     'mros2/support/mros2_message_wire.hpp',
                     'core/support/mros_message_containers.h', 'ros2/model.py',
                     'integrations/rosidl_generator.py'):
        assert os.path.join(package, relative) in files
    assert all(os.path.isfile(path) for path in files)
    assert not [path for path in files if '/mros_v1/' in path or '/ros1/' in path]


def test_a_depfile_needs_its_target(tmp_path):
    result = _run('--generator-arguments-file', 'arguments.json', '--dependency-file', 'x.d')
    assert result.returncode == 2
    assert result.stderr.splitlines()[-1] == ('rosidl_generator_mros2: error: --dependency-file '
                                              'and --dependency-target go together')


def _without(blocked, path, *arguments):
    return subprocess.run([sys.executable, '-c', WITHOUT_MODULES, ','.join(blocked), path]
                          + list(arguments), capture_output=True, text=True)


def test_it_runs_on_humbles_rosidl_without_rosidl_pycommon(tmp_path):
    import rosidl_pycommon
    # Humble's rosidl_cmake Python module is rosidl 3.3's rosidl_pycommon
    # under its old name (the two differ in one comment).
    humble = str(tmp_path / 'humble')
    with open(rosidl_pycommon.__file__) as stream:
        _write(os.path.join(humble, 'rosidl_cmake', '__init__.py'), stream.read())
    base = str(tmp_path / 'adapter')
    _write(os.path.join(base, 'msg', 'Ping.idl'), PING_IDL)
    _write(os.path.join(base, 'msg', 'TwoWords.idl'), PING_IDL.replace('Ping', 'TwoWords'))
    arguments = _arguments_file(tmp_path, idl_tuples=['%s:msg/Ping.idl' % base,
                                                      '%s:msg/TwoWords.idl' % base])
    result = _without(['rosidl_pycommon'], humble, '--generator-arguments-file', arguments)
    assert (result.returncode, result.stdout, result.stderr) == (0, '', '')
    # The header names come from the helper: TwoWords -> two_words.hpp.
    assert _written(tmp_path) == ['demo/msg/ping.hpp', 'demo/msg/two_words.hpp']


def test_without_either_helper_module_it_says_what_to_install(tmp_path):
    result = _without(['rosidl_pycommon', 'rosidl_cmake'], str(tmp_path),
                      '--generator-arguments-file', _arguments_file(tmp_path, idl_tuples=[]))
    assert (result.returncode, result.stdout) == (1, '')
    assert result.stderr == (
        'genmros: error: %s cannot import rosidl_pycommon or rosidl_cmake; install or source '
        'rosidl (Debian: apt-get install python3-rosidl; ROS 2 Humble: source '
        '/opt/ros/humble/setup.bash), or run genmros with the Python that has it\n'
        % sys.executable)


@pytest.mark.parametrize('kind', ['msg', 'srv'])
def test_nothing_listed_of_a_kind_writes_nothing_of_it(tmp_path, kind):
    result = _run('--generator-arguments-file', _arguments_file(tmp_path, idl_tuples=[]))
    assert (result.returncode, result.stderr) == (0, '')
    assert not os.path.exists(str(tmp_path / 'out' / 'demo' / kind))


def test_a_type_that_became_uncarriable_loses_its_header_and_its_place_in_the_list(tmp_path):
    base = str(tmp_path / 'adapter')
    ping = _write(os.path.join(base, 'msg', 'Ping.idl'), PING_IDL)
    arguments = _arguments_file(tmp_path, idl_tuples=['%s:msg/Ping.idl' % base])
    header_list = str(tmp_path / 'headers')
    assert _run('--generator-arguments-file', arguments, '--header-list',
                header_list).returncode == 0
    assert _written(tmp_path) == ['demo/msg/ping.hpp']
    with open(header_list) as stream:
        assert stream.read() == 'demo/msg/ping.hpp\n'
    _write(ping, PING_IDL.replace('int32 value;', 'long double value;'))
    result = _run('--generator-arguments-file', arguments, '--header-list', header_list)
    assert (result.returncode, result.stderr) == (0, '')
    assert result.stdout == ("rosidl_generator_mros2: skipped demo/msg/Ping: mros2 cannot carry "
                             "it: %s:4: member 'value': long double has no fixed size on the "
                             'boards mros2 runs on\n' % ping)
    assert _written(tmp_path) == []
    with open(header_list) as stream:
        assert stream.read() == ''
