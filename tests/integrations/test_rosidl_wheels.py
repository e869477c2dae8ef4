# SPDX-License-Identifier: BSD-3-Clause
"""The rosidl generator on the newer rosidl of the ROS 2 wheels on PyPI (4.9):
mros2_base_msgs of test_ws_ros2 built with CMake against the rosidl that
scripts/setup.sh --tests installs into build/ros2-wheels (its
rosidl_write_generator_arguments(), rosidl_find_package_idl(), Python and
rosidl_pycommon), with this checkout's rosidl_generator_mros2
(tests/support/rosidl_wheels.py). Its header is the one genmros writes for
the same message with Debian's rosidl (3.3). And
an interface package as ROS 2's tutorials write it, naming only
rosidl_default_generators, gets its mros2 headers beside rosidl's C++ and
Python code."""

import os

import pytest

from support.checkout import REPO, run_genmros
from support.rosidl_wheels import (build_interface_package, installed_version, mros2_include,
                                   require_venv)
from testing.ros_paths import KILTED_WHEELS

pytestmark = pytest.mark.slow

VENV = KILTED_WHEELS
PACKAGE = os.path.join(REPO, 'test_ws_ros2', 'src', 'mros2_base_msgs')
STAMP = os.path.join('mros2_base_msgs', 'msg', 'stamp.hpp')


@pytest.fixture(scope='module')
def wheel_build(tmp_path_factory):
    require_venv(VENV)
    return build_interface_package(PACKAGE, tmp_path_factory.mktemp('wheels'), VENV)


def test_the_build_used_the_wheels_rosidl(wheel_build):
    build = wheel_build.build
    with open(os.path.join(build, 'CMakeCache.txt')) as stream:
        cache = stream.read()
    assert 'rosidl_cmake_DIR:PATH=%s' % os.path.join(VENV, 'share', 'rosidl_cmake', 'cmake') \
        in cache
    assert installed_version(VENV, 'ros-rosidl-pycommon').startswith('4.9.')


def test_its_header_is_the_one_debians_rosidl_gives(wheel_build, tmp_path):
    install = wheel_build.install
    run_genmros('mros2-export', '--workspace', os.path.join(REPO, 'test_ws_ros2'),
                '--type', 'mros2_base_msgs/msg/Stamp', '-o', str(tmp_path))
    with open(os.path.join(mros2_include(install, 'mros2_base_msgs'), STAMP)) as wheels, \
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
    require_venv(VENV)
    build_interface_package(source, tmp_path, VENV, prefixes=[REPO])
    install = tmp_path / 'install'
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
