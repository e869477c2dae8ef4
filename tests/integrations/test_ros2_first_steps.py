# SPDX-License-Identifier: BSD-3-Clause
"""The ROS 2 user's first steps (docs/mros2.md, "First steps"), as written.

- The docs' interface-package CMakeLists is test_ws_ros2's mros2_base_msgs
  file, which the colcon tests build on Debian 12 and test_rosidl_wheels.py
  with the wheels' rosidl.
- The message packages Debian 12 lacks come from the ROS 2 wheels in a venv
  (the one scripts/setup.sh --tests makes, from the pins the docs name):
  mros2-export reads them with --prefix; without it, the unknown package's
  line names the wheel.
- On ROS 2 Humble (opt-in: HUMBLE_ROSIDL_PREFIX, a prefix holding Humble's
  rosidl 3.1.6, rosidl_defaults and ament_cmake 1.3.11 built from their
  checkouts, with a setup.bash; docs/testing.md), test_ws_ros2 builds with
  that rosidl, sourced as a Humble user sources /opt/ros/humble, the
  generator's prefix not on AMENT_PREFIX_PATH, and gets its mros2 headers,
  equal to genmros' own.
"""

import os
import re
import shutil
import subprocess

import pytest

from conftest import REPO, run_genmros
from fixtures.build_integration.tools import run, user_environment

DOCS = os.path.join(REPO, 'docs', 'mros2.md')
INTERFACE_PACKAGE = os.path.join(REPO, 'test_ws_ros2', 'src', 'mros2_base_msgs')
WHEELS = os.path.join(REPO, 'build', 'ros2-wheels')
WHEEL_PINS = os.path.join(REPO, 'scripts', 'test-requirements-ros2-wheels.txt')
HUMBLE = os.environ.get('HUMBLE_ROSIDL_PREFIX', '')


def _docs():
    with open(DOCS, encoding='utf-8') as stream:
        return stream.read()


def _section(text):
    start = text.index('## First steps')
    return text[start:text.index('\n## ', start + 1)]


def test_the_docs_cmakelists_is_the_one_the_tests_build():
    blocks = re.findall(r'```cmake\n(.*?)```', _section(_docs()), re.S)
    with open(os.path.join(INTERFACE_PACKAGE, 'CMakeLists.txt'), encoding='utf-8') as stream:
        assert blocks == [stream.read()]


def test_the_docs_wheels_are_the_pinned_ones():
    with open(WHEEL_PINS, encoding='utf-8') as stream:
        pins = set(re.findall(r'^(ros-[a-z-]+==[0-9.]+)$', stream.read(), re.M))
    named = set(re.findall(r'ros-[a-z-]+==[0-9.]+', _section(_docs())))
    assert named and named <= pins


@pytest.fixture(scope='module')
def wheels():
    if not os.path.isfile(os.path.join(WHEELS, 'bin', 'python')):
        pytest.fail('no %s: run scripts/setup.sh --tests' % WHEELS)
    return WHEELS


def test_a_firmware_takes_ros2_message_packages_from_the_wheels(wheels, tmp_path):
    result = run_genmros('mros2-export', '--prefix', wheels, '-o', str(tmp_path),
                         '--subscribe', 'cmd_vel:geometry_msgs/msg/Twist',
                         '--publish', 'image:sensor_msgs/msg/Image')
    assert 'genmros: 5 mros2 message types, 0 services' in result.stdout, result.stdout
    for header in ('geometry_msgs/msg/twist.hpp', 'geometry_msgs/msg/vector3.hpp',
                   'sensor_msgs/msg/image.hpp', 'std_msgs/msg/header.hpp',
                   'builtin_interfaces/msg/time.hpp'):
        assert (tmp_path / header).is_file(), header


def test_without_them_the_unknown_package_names_the_wheel(tmp_path):
    empty = tmp_path / 'empty_prefix'
    (empty / 'share').mkdir(parents=True)
    result = run_genmros('mros2-export', '--prefix', str(empty), '-o', str(tmp_path / 'out'),
                         '--subscribe', 'cmd_vel:geometry_msgs/msg/Twist', check=False)
    assert result.returncode == 1
    assert result.stderr == (
        "genmros: error: unknown package 'geometry_msgs' of type 'geometry_msgs/msg/Twist' (not "
        'in the workspace or the installed ROS 2 packages; AMENT_PREFIX_PATH or --prefix names '
        'the installed ones; where no ROS 2 distribution is installed, as on Debian 12, a venv '
        'with the wheel ros-geometry-msgs holds it: --prefix VENV, docs/mros2.md)\n')


@pytest.mark.slow
@pytest.mark.skipif(not os.path.isfile(os.path.join(HUMBLE, 'setup.bash')),
                    reason='needs ROS 2 Humble\'s rosidl built into a prefix: set '
                           'HUMBLE_ROSIDL_PREFIX (docs/testing.md)')
def test_humble_builds_the_docs_package_with_its_rosidl(tmp_path):
    workspace = str(tmp_path / 'ws')
    shutil.copytree(os.path.join(REPO, 'test_ws_ros2', 'src'), os.path.join(workspace, 'src'))
    # A Humble user's shell: the distribution sourced (AMENT_PREFIX_PATH holds
    # only it), genmros installed elsewhere (this checkout's install).
    environment = user_environment(AMENT_PREFIX_PATH=None)
    environment['PATH'] = '/usr/bin:' + environment['PATH']
    command = '. "%s/setup.bash" && exec colcon build --event-handlers console_direct+' % HUMBLE
    run(['bash', '-c', command], workspace, environment)
    with open(os.path.join(workspace, 'build', 'mros2_base_msgs', 'CMakeCache.txt')) as stream:
        cache = stream.read()
    for package in ('rosidl_cmake', 'rosidl_default_generators'):
        found = re.search(r'^%s_DIR:PATH=(.*)$' % package, cache, re.M).group(1)
        assert found.startswith(os.path.realpath(HUMBLE)) or found.startswith(HUMBLE), found
    expected = tmp_path / 'expected'
    run_genmros('mros2-export', '--workspace', os.path.join(REPO, 'test_ws_ros2'), '-o',
                str(expected), '--package', 'mros2_base_msgs', '--package', 'mros2_test_msgs')
    installed = [os.path.join(directory, name)
                 for directory, _, names in os.walk(os.path.join(workspace, 'install'))
                 for name in names]
    for header in ('mros2_base_msgs/msg/stamp.hpp', 'mros2_test_msgs/msg/reading.hpp',
                   'mros2_test_msgs/srv/query.hpp'):
        # rosidl_generator_cpp's header has the same name: the mros2 one
        # carries the DDS type name.
        ours = [path for path in installed if path.endswith(os.sep + header)
                and 'dds_::' in open(path, errors='replace').read()]
        assert len(ours) == 1, (header, ours)
        with open(ours[0]) as built, open(str(expected / header)) as exported:
            assert built.read() == exported.read(), header
