# SPDX-License-Identifier: BSD-3-Clause
"""Fixtures shared by the test modules."""

import os
import subprocess
import sys

import pytest

import built_workspace
from testing import ros_paths
from user_checkouts import CHECKOUTS

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
TEST_WS = os.path.join(REPO, 'test_ws')
# What the tests take from PyPI (rosbags), installed there by
# scripts/setup.sh --tests (scripts/test-requirements.txt), not into a Python of the system.
TEST_PYTHON_PACKAGES = os.path.join(REPO, 'build', 'test-python')
sys.path.append(TEST_PYTHON_PACKAGES)

# The Debian ROS message packages genmros is held against.
DEBIAN_MESSAGE_PACKAGES = [
    'std_msgs', 'geometry_msgs', 'sensor_msgs', 'nav_msgs', 'trajectory_msgs',
    'visualization_msgs', 'diagnostic_msgs', 'actionlib_msgs', 'shape_msgs',
    'stereo_msgs', 'tf2_msgs', 'map_msgs', 'pcl_msgs', 'std_srvs', 'rosgraph_msgs',
]


# The mros2 corpora's fixtures (tests/mros2_corpus.py).
pytest_plugins = ['mros2_corpus']


def pytest_collection_modifyitems(config, items):
    """Tests that need a user's checkout (needs_mros_v1, needs_mros2) are
    skipped, saying why, without one."""
    for checkout in CHECKOUTS:
        if checkout.found():
            continue
        skip = pytest.mark.skip(reason=checkout.missing_reason())
        for item in items:
            if checkout.marker in item.keywords:
                item.add_marker(skip)


def let_empy_take_stdout():
    """empy 3 wraps sys.stdout in a proxy when its first interpreter starts,
    and refuses to start another once sys.stdout has been replaced since.
    pytest's capture replaces it for every test; a genmros process, colcon's
    and rosidl's never do (tests/core/test_render.py runs two of them). So
    the next interpreter may wrap the stdout pytest gives now (a fixture of
    a wider scope, which runs before the test's own, calls this too)."""
    try:
        import em
    except ImportError:  # a test of a Python without ROS
        return
    if not hasattr(sys.stdout, '_testProxy'):
        em.Interpreter._wasProxyInstalled = False


@pytest.fixture(autouse=True)
def empy_takes_the_tests_stdout():
    """Each test lets its first empy interpreter wrap its stdout."""
    let_empy_take_stdout()
    yield


def run_genmros(*arguments, check=True):
    """Run genmros from this checkout as users run it; returns the CompletedProcess."""
    result = subprocess.run([sys.executable, '-m', 'colcon_mros'] + list(arguments),
                            capture_output=True, text=True, cwd=REPO)
    if check and result.returncode != 0:
        raise AssertionError('genmros %s failed:\n%s' % (' '.join(arguments), result.stderr))
    return result


@pytest.fixture(scope='session')
def debian_export(tmp_path_factory):
    """genmros export of every Debian message package: the include root."""
    root = str(tmp_path_factory.mktemp('debian_export'))
    arguments = ['export', '-o', root, *ros_paths.prefix_arguments(ros_paths.ros1_prefixes())]
    for package in DEBIAN_MESSAGE_PACKAGES:
        arguments += ['--package', package]
    run_genmros(*arguments)
    return root


@pytest.fixture(scope='session')
def test_ws_export(tmp_path_factory):
    """genmros export of test_ws: the include root."""
    root = str(tmp_path_factory.mktemp('test_ws_export'))
    run_genmros('export', '--workspace', TEST_WS, '-o', root,
                *ros_paths.prefix_arguments(ros_paths.ros1_prefixes()))
    return root


@pytest.fixture(scope='session')
def ros_workspace():
    """test_ws built with catkin_make: the ROS nodes the mROS v1 apps talk to."""
    return built_workspace.workspace()


@pytest.fixture(scope='session')
def ros2_prefixes():
    """The installed ROS 2 prefixes (testing.ros_paths)."""
    return ros_paths.ros2_prefixes()
