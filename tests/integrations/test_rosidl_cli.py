# SPDX-License-Identifier: BSD-3-Clause
"""``rosidl generate --type mros2`` (colcon_mros.integrations.rosidl_cli_extension),
through rosidl's own command line and the entry point an install registers,
with Debian's rosidl_cli and the ROS 2 wheels'."""

import os
import re
import subprocess

import pytest

from support.checkout import run_genmros
from support.checkout_install import checkout_install
from support.file_trees import package_xml, write_tree
from testing.ros_paths import KILTED_WHEELS

WHEELS_PYTHON = os.path.join(KILTED_WHEELS, 'bin', 'python')
PYTHONS = {'debian': '/usr/bin/python3', 'wheels': WHEELS_PYTHON}
ROSIDL = 'import sys; from rosidl_cli.cli import main; sys.exit(main())'
SOURCES = {
    'package.xml': package_xml('demo'),
    'msg/Ping.msg': 'int32 value\nstring<=8 label\n',
    'srv/Pair.srv': 'Ping first\n---\nbool ok\n',
}
WIDE_IDL = '''module demo {
  module msg {
    struct Wide {
      wchar letter;
    };
  };
};
'''
HEADERS = ['demo/msg/ping.hpp', 'demo/srv/pair.hpp']
# The wheel ros-rosidl-adapter holds both a .dist-info and an .egg-info,
# so rosidl_cli warns of its entry points twice, whatever the type.
WHEELS_WARNING = re.compile(r"Found duplicate entry point '(action|msg|srv)2idl': .*\n")


def _rosidl(python, package_dir, *arguments):
    if not os.path.isfile(python):
        pytest.fail('no %s: run scripts/setup.sh --tests' % python)
    env = checkout_install().environment(
        {key: value for key, value in os.environ.items() if key != 'PYTHONPATH'})
    return subprocess.run([python, '-c', ROSIDL, 'generate'] + list(arguments),
                          cwd=package_dir, env=env, capture_output=True, text=True)


def _files(root):
    return sorted(os.path.relpath(os.path.join(d, name), root)
                  for d, _, names in os.walk(root) for name in names
                  if not os.path.relpath(d, root).startswith('tmp'))


@pytest.mark.parametrize('rosidl', sorted(PYTHONS))
def test_rosidl_generate_type_mros2_writes_what_mros2_export_writes(rosidl, tmp_path):
    package = tmp_path / 'src' / 'demo'
    write_tree(str(package), SOURCES)
    output = tmp_path / 'out'
    result = _rosidl(PYTHONS[rosidl], str(package), '--type', 'mros2', '-o', str(output),
                     'demo', 'msg/Ping.msg', 'srv/Pair.srv')
    assert (result.returncode, WHEELS_WARNING.sub('', result.stderr)) == (0, ''), result.stderr
    # rosidl_cli's translate leaves its .idl forms in <output>/tmp.
    assert _files(str(output)) == HEADERS
    run_genmros('mros2-export', '--workspace', str(tmp_path / 'src'), '--package', 'demo',
                '-o', str(tmp_path / 'export'))
    for header in HEADERS:
        assert (output / header).read_text() == (tmp_path / 'export' / header).read_text()


def test_a_type_mros2_cannot_carry_is_skipped_with_one_line(tmp_path):
    package = tmp_path / 'demo'
    write_tree(str(package), dict(SOURCES, **{'msg/Wide.idl': WIDE_IDL}))
    output = tmp_path / 'out'
    result = _rosidl(PYTHONS['debian'], str(package), '--type', 'mros2', '-o', str(output),
                     'demo', 'msg/Ping.msg', 'msg/Wide.idl')
    assert (result.returncode, result.stderr) == (0, ''), result.stderr
    # After rosidl_adapter's lines of its translation of Ping.msg.
    assert [line for line in result.stdout.splitlines() if 'Wide' in line] == [
        "rosidl_generator_mros2: skipped demo/msg/Wide: mros2 cannot carry it: %s:4: member "
        "'letter': wchar has no agreed CDR size between ROS 2 serializers"
        % (package / 'msg' / 'Wide.idl')]
    assert _files(str(output)) == ['demo/msg/ping.hpp']


def test_an_error_names_the_msg_the_user_wrote(tmp_path):
    package = tmp_path / 'demo'
    write_tree(str(package), {'msg/Ping.msg': 'int32 value\nother/Inner inner\n'})
    result = _rosidl(PYTHONS['debian'], str(package), '--type', 'mros2', '-o',
                     str(tmp_path / 'out'), 'demo', 'msg/Ping.msg')
    assert result.returncode != 0
    assert "%s:2: unknown package 'other'" % (package / 'msg' / 'Ping.msg') in result.stderr
