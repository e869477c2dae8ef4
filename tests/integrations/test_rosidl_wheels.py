"""The rosidl generator on the newer rosidl of the ROS 2 wheels on PyPI (4.9):
mros2_base_msgs of test_ws_ros2 built with CMake against the rosidl that
scripts/setup.sh --tests installs into build/ros2-wheels (its
rosidl_write_generator_arguments(), rosidl_find_package_idl(), Python and
rosidl_pycommon), with this checkout's rosidl_generator_mros2. Its header is
the one genmros writes for the same message with Debian's rosidl (3.3)."""

import os
import subprocess

import pytest

from conftest import REPO, run_genmros

pytestmark = pytest.mark.slow

VENV = os.path.join(REPO, 'build', 'ros2-wheels')
PACKAGE = os.path.join(REPO, 'test_ws_ros2', 'src', 'mros2_base_msgs')
EXTENSION_DIR = os.path.join(REPO, 'share', 'rosidl_generator_mros2', 'cmake')
STAMP = os.path.join('mros2_base_msgs', 'msg', 'stamp.hpp')


def _run(argv, env):
    result = subprocess.run(argv, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                            text=True)
    assert result.returncode == 0, ' '.join(argv) + '\n' + result.stdout[-6000:]
    return result


@pytest.fixture(scope='module')
def wheel_build(tmp_path_factory):
    if not os.path.isfile(os.path.join(VENV, 'bin', 'python')):
        pytest.fail('no %s: run scripts/setup.sh --tests' % VENV)
    root = tmp_path_factory.mktemp('wheels')
    generator = str(root / 'rosidl_generator_mros2')
    with open(generator, 'w') as stream:
        stream.write('#!/bin/sh\nPYTHONPATH=%s exec %s -m colcon_mros.integrations.rosidl_generator'
                     ' "$@"\n' % (REPO, os.path.join(VENV, 'bin', 'python')))
    os.chmod(generator, 0o755)
    env = {key: value for key, value in os.environ.items()
           if key not in ('AMENT_PREFIX_PATH', 'CMAKE_PREFIX_PATH', 'PYTHONPATH')}
    env.update(PATH='%s:/usr/bin:/bin' % os.path.join(VENV, 'bin'), AMENT_PREFIX_PATH=VENV)
    build, install = str(root / 'build'), str(root / 'install')
    _run(['cmake', '-S', PACKAGE, '-B', build, '-DCMAKE_PREFIX_PATH=%s' % VENV,
          '-DPython3_EXECUTABLE=%s' % os.path.join(VENV, 'bin', 'python'),
          '-Drosidl_generator_mros2_DIR=%s' % EXTENSION_DIR,
          '-Drosidl_generator_mros2_BIN=%s' % generator, '-DCMAKE_INSTALL_PREFIX=%s' % install],
         env)
    _run(['cmake', '--build', build], env)
    _run(['cmake', '--install', build], env)
    return build, install


def test_the_build_used_the_wheels_rosidl(wheel_build):
    build, _ = wheel_build
    with open(os.path.join(build, 'CMakeCache.txt')) as stream:
        cache = stream.read()
    assert 'rosidl_cmake_DIR:PATH=%s' % os.path.join(VENV, 'share', 'rosidl_cmake', 'cmake') \
        in cache
    version = subprocess.run([os.path.join(VENV, 'bin', 'python'), '-c',
                              'import importlib.metadata as m; '
                              'print(m.version("ros-rosidl-pycommon"))'],
                             capture_output=True, text=True, check=True).stdout.strip()
    assert version.startswith('4.9.')


def test_its_header_is_the_one_debians_rosidl_gives(wheel_build, tmp_path):
    _, install = wheel_build
    run_genmros('mros2-export', '--workspace', os.path.join(REPO, 'test_ws_ros2'),
                '--type', 'mros2_base_msgs/msg/Stamp', '-o', str(tmp_path))
    with open(os.path.join(install, 'include', 'mros2', STAMP)) as wheels, \
            open(str(tmp_path / STAMP)) as debian:
        assert wheels.read() == debian.read()
