# SPDX-License-Identifier: BSD-3-Clause
"""Where rosidl_adapter cannot render .msg files with the installed empy
(Debian 12's takes empy 3 only), genmros says so in one line, naming both
and what to install, instead of rosidl_adapter's own failure as a .msg's."""

import os
import subprocess

from support.checkout import REPO
from testing.ros2_messages import PACKAGE_XML
from testing.ros_paths import prefix_arguments, ros2_prefixes

ADAPTER_FAILS = ("genmros: error: rosidl_adapter ({adapter}) renders .msg and .srv files with "
                 "empy 3 only, and empy {version} is installed ({empy}): install empy 3 in its "
                 "place (pip install 'empy<4'), or a rosidl_adapter that renders with empy 4\n")


def _run(python, *code_or_arguments):
    return subprocess.run([python, *code_or_arguments], capture_output=True, text=True,
                          cwd=REPO, env=dict(os.environ, PYTHONPATH=REPO))


def test_a_msg_under_empy_4_with_debians_rosidl_adapter_asks_for_empy_3(tmp_path, empy4_python):
    package = tmp_path / 'src' / 'demo_msgs'
    (package / 'msg').mkdir(parents=True)
    (package / 'msg' / 'Reading.msg').write_text('int32 value\n')
    (package / 'package.xml').write_text(PACKAGE_XML % 'demo_msgs')
    version, empy, adapter = _run(
        empy4_python, '-c', 'import os, em, rosidl_adapter; print(em.__version__, em.__file__, '
        'os.path.dirname(rosidl_adapter.__file__))').stdout.split()
    assert version.startswith('4.')
    result = _run(empy4_python, '-m', 'colcon_mros', 'mros2-export', '--workspace', str(tmp_path),
                  *prefix_arguments(ros2_prefixes()), '-o', str(tmp_path / 'out'))
    assert (result.returncode, result.stdout, result.stderr) == (
        1, '', ADAPTER_FAILS.format(adapter=adapter, version=version, empy=empy))
    assert not (tmp_path / 'out').exists()
    # Debian's empy 3: the same workspace exports.
    result = _run('/usr/bin/python3', '-m', 'colcon_mros', 'mros2-export', '--workspace',
                  str(tmp_path), *prefix_arguments(ros2_prefixes()), '-o', str(tmp_path / 'out'))
    assert (result.returncode, result.stderr) == (0, '')
