# SPDX-License-Identifier: BSD-3-Clause
"""Another python3 first on PATH (a venv, pyenv, conda): docs/install.md's fix works.

catkin's CMake takes the first python3 on PATH, which cannot import catkin_pkg,
even under Debian's /usr/bin/colcon; -DPYTHON_EXECUTABLE=/usr/bin/python3 or
/usr/bin first on PATH gives it Debian's, and genmros then runs. ament's CMake
finds Python with FindPython3, which -DPYTHON_EXECUTABLE does not reach:
an ROS 2 interface package needs -DPython3_EXECUTABLE=/usr/bin/python3.
docs/install.md says exactly these.
"""

import os
import shutil
import subprocess
import sys

import pytest

from support.build_integration import TEST_WS_SRC, run, user_environment

# cmake, colcon, catkin or make builds: more than half a minute.
pytestmark = pytest.mark.slow

FIX = '-DPYTHON_EXECUTABLE=/usr/bin/python3'
AMENT_FIX = '-DPython3_EXECUTABLE=/usr/bin/python3'
TEST_WS_ROS2_BASE = os.path.join(os.path.dirname(os.path.dirname(TEST_WS_SRC)), 'test_ws_ros2',
                                 'src', 'mros2_base_msgs')
HEADER = os.path.join('share', 'genmros', 'include', 'mros_test_base', 'Vector3i.h')


@pytest.fixture(scope='module')
def environment(tmp_path_factory):
    """The user's environment with a venv's python3 (no system site packages) first on PATH."""
    venv = str(tmp_path_factory.mktemp('other_python') / 'venv')
    subprocess.run([sys.executable, '-m', 'venv', '--without-pip', venv], check=True)
    env = user_environment()
    env['PATH'] = os.path.join(venv, 'bin') + os.pathsep + env['PATH']
    return env


def _workspace(root):
    shutil.copytree(os.path.join(TEST_WS_SRC, 'mros_test_base'),
                    os.path.join(root, 'src', 'mros_test_base'))
    return root


def test_catkin_make_needs_the_fix_and_works_with_it(environment, tmp_path):
    workspace = _workspace(str(tmp_path))
    failed = run(['catkin_make'], workspace, environment, check=False)
    assert failed.returncode != 0 and "No module named 'catkin_pkg'" in failed.stdout
    shutil.rmtree(os.path.join(workspace, 'build'))
    run(['catkin_make', FIX], workspace, environment)
    assert os.path.isfile(os.path.join(workspace, 'devel', HEADER))


def test_colcon_build_works_with_the_fix(environment, tmp_path):
    workspace = _workspace(str(tmp_path))
    run(['colcon', 'build', '--cmake-args', FIX], workspace, environment)
    assert os.path.isfile(os.path.join(workspace, 'install', 'mros_test_base', HEADER))


def test_debian_colcon_alone_is_no_fix(environment, tmp_path):
    workspace = _workspace(str(tmp_path))
    failed = run(['/usr/bin/colcon', 'build'], workspace, environment, check=False)
    assert failed.returncode != 0 and "No module named 'catkin_pkg'" in failed.stdout


def test_usr_bin_first_on_path_is_a_fix(environment, tmp_path):
    fixed = dict(environment, PATH='/usr/bin' + os.pathsep + environment['PATH'])
    workspace = _workspace(str(tmp_path / 'catkin_make'))
    run(['catkin_make'], workspace, fixed)
    assert os.path.isfile(os.path.join(workspace, 'devel', HEADER))
    workspace = _workspace(str(tmp_path / 'colcon'))
    run(['colcon', 'build'], workspace, fixed)
    assert os.path.isfile(os.path.join(workspace, 'install', 'mros_test_base', HEADER))


def test_an_ament_interface_package_needs_the_python3_fix_and_works_with_it(environment,
                                                                            tmp_path):
    workspace = str(tmp_path)
    shutil.copytree(TEST_WS_ROS2_BASE, os.path.join(workspace, 'src', 'mros2_base_msgs'))
    failed = run(['colcon', 'build', '--cmake-args', FIX], workspace, environment, check=False)
    assert failed.returncode != 0 and "No module named 'ament_package'" in failed.stdout, \
        failed.stdout[-3000:]
    shutil.rmtree(os.path.join(workspace, 'build'))
    run(['colcon', 'build', '--cmake-args', FIX, AMENT_FIX], workspace, environment)
    headers = [os.path.join(directory, 'stamp.hpp')
               for directory, _, names in os.walk(os.path.join(workspace, 'install'))
               if 'stamp.hpp' in names]
    assert any('mros2_base_msgs::msg::dds_::Stamp_' in open(path).read() for path in headers)
