# SPDX-License-Identifier: BSD-3-Clause
"""The rosidl generator on the newer rosidl of the ROS 2 wheels on PyPI (4.9):
mros2_base_msgs of test_ws_ros2 built with CMake against the rosidl that
scripts/setup.sh --tests installs into build/ros2-wheels (its
rosidl_write_generator_arguments(), rosidl_find_package_idl(), Python and
rosidl_pycommon), with this checkout's rosidl_generator_mros2 (the CMake
package and support headers of its install, tests/support/checkout_install.py; the
checkout's entry point). Its header is
the one genmros writes for the same message with Debian's rosidl (3.3). And
an interface package as ROS 2's tutorials write it, naming only
rosidl_default_generators, gets its mros2 headers beside rosidl's C++ and
Python code."""

import os
import subprocess

import pytest

from support.checkout_install import checkout_install
from support.checkout import REPO, run_genmros

pytestmark = pytest.mark.slow

VENV = os.path.join(REPO, 'build', 'ros2-wheels')
PACKAGE = os.path.join(REPO, 'test_ws_ros2', 'src', 'mros2_base_msgs')
STAMP = os.path.join('mros2_base_msgs', 'msg', 'stamp.hpp')


def _extension_dir():
    """The CMake package of this checkout's install (with its support headers)."""
    return os.path.join(checkout_install().prefix, 'share', 'rosidl_generator_mros2', 'cmake')


def _mros2_include(install, package):
    """The package's mros2 include root: <install>/include/<pkg>/mros2."""
    return os.path.join(str(install), 'include', package, 'mros2')


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
        stream.write('#!/bin/sh\nPYTHONPATH=%s exec %s -m '
                     'colcon_mros.integrations.rosidl_generator'
                     ' "$@"\n' % (REPO, os.path.join(VENV, 'bin', 'python')))
    os.chmod(generator, 0o755)
    env = {key: value for key, value in os.environ.items()
           if key not in ('AMENT_PREFIX_PATH', 'CMAKE_PREFIX_PATH', 'PYTHONPATH')}
    env.update(PATH='%s:/usr/bin:/bin' % os.path.join(VENV, 'bin'), AMENT_PREFIX_PATH=VENV)
    build, install = str(root / 'build'), str(root / 'install')
    _run(['cmake', '-S', PACKAGE, '-B', build, '-DCMAKE_PREFIX_PATH=%s' % VENV,
          '-DPython3_EXECUTABLE=%s' % os.path.join(VENV, 'bin', 'python'),
          '-Drosidl_generator_mros2_DIR=%s' % _extension_dir(),
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
    with open(os.path.join(_mros2_include(install, 'mros2_base_msgs'), STAMP)) as wheels, \
            open(str(tmp_path / STAMP)) as debian:
        assert wheels.read() == debian.read()


TUTORIAL_CMAKE = '''cmake_minimum_required(VERSION 3.16)
project(tutorial_interfaces)
find_package(ament_cmake REQUIRED)
find_package(rosidl_default_generators REQUIRED)
rosidl_generate_interfaces(${PROJECT_NAME} "msg/Num.msg" "srv/AddThreeInts.srv")
ament_export_dependencies(rosidl_default_runtime)
ament_package()
'''
TUTORIAL_PACKAGE = '''<?xml version="1.0"?>
<package format="3">
  <name>tutorial_interfaces</name>
  <version>0.0.1</version>
  <description>Interfaces as ROS 2's tutorial declares them</description>
  <maintainer email="maintainer@example.com">Maintainer</maintainer>
  <license>Apache-2.0</license>
  <buildtool_depend>ament_cmake</buildtool_depend>
  <buildtool_depend>rosidl_default_generators</buildtool_depend>
  <exec_depend>rosidl_default_runtime</exec_depend>
  <member_of_group>rosidl_interface_packages</member_of_group>
  <export><build_type>ament_cmake</build_type></export>
</package>
'''


def test_a_package_naming_only_rosidl_default_generators_gets_mros2_headers(tmp_path):
    """As ROS 2's tutorials declare interfaces: rosidl_default_generators
    finds the mros2 generator through rosidl's generator group (this
    checkout as a prefix on AMENT_PREFIX_PATH), and its headers are
    installed beside rosidl's C++ headers and Python package."""
    source = tmp_path / 'src' / 'tutorial_interfaces'
    (source / 'msg').mkdir(parents=True)
    (source / 'srv').mkdir()
    (source / 'CMakeLists.txt').write_text(TUTORIAL_CMAKE)
    (source / 'package.xml').write_text(TUTORIAL_PACKAGE)
    (source / 'msg' / 'Num.msg').write_text('int64 num\n')
    (source / 'srv' / 'AddThreeInts.srv').write_text('int64 a\nint64 b\nint64 c\n---\nint64 sum\n')
    generator = tmp_path / 'rosidl_generator_mros2'
    generator.write_text('#!/bin/sh\nPYTHONPATH=%s exec %s -m colcon_mros.integrations.'
                         'rosidl_generator "$@"\n' % (REPO, os.path.join(VENV, 'bin', 'python')))
    generator.chmod(0o755)
    env = {key: value for key, value in os.environ.items()
           if key not in ('AMENT_PREFIX_PATH', 'CMAKE_PREFIX_PATH', 'PYTHONPATH')}
    env.update(PATH='%s:/usr/bin:/bin' % os.path.join(VENV, 'bin'),
               AMENT_PREFIX_PATH='%s:%s' % (VENV, REPO))
    build, install = str(tmp_path / 'build'), tmp_path / 'install'
    _run(['cmake', '-S', str(source), '-B', build, '-DCMAKE_PREFIX_PATH=%s;%s' % (VENV, REPO),
          '-DPython3_EXECUTABLE=%s' % os.path.join(VENV, 'bin', 'python'),
          '-Drosidl_generator_mros2_DIR=%s' % _extension_dir(),
          '-Drosidl_generator_mros2_BIN=%s' % generator,
          '-DCMAKE_INSTALL_PREFIX=%s' % install], env)
    _run(['cmake', '--build', build, '-j2'], env)
    _run(['cmake', '--install', build], env)
    for relative in ('include/tutorial_interfaces/mros2/tutorial_interfaces/msg/num.hpp',
                     'include/tutorial_interfaces/mros2/tutorial_interfaces/srv/'
                     'add_three_ints.hpp',
                     'include/tutorial_interfaces/tutorial_interfaces/msg/num.hpp',
                     'lib/python3.11/site-packages/tutorial_interfaces/msg/_num.py',
                     'lib/python3.11/site-packages/tutorial_interfaces/srv/_add_three_ints.py'):
        assert (install / relative).is_file(), relative
    run_genmros('mros2-export', '--workspace', str(tmp_path / 'src'), '--package',
                'tutorial_interfaces', '-o', str(tmp_path / 'export'))
    for relative in ('tutorial_interfaces/msg/num.hpp',
                     'tutorial_interfaces/srv/add_three_ints.hpp'):
        assert (install / 'include' / 'tutorial_interfaces' / 'mros2' / relative).read_text() == \
            (tmp_path / 'export' / relative).read_text()
