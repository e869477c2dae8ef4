# SPDX-License-Identifier: BSD-3-Clause
"""Fixtures shared by the test modules."""

import os
import sys

import pytest

from support import built_workspace
from support.checkout import REPO, TEST_WS, run_genmros
from support.debian_messages import DEBIAN_MESSAGE_PACKAGES
from support.empy_stdout import let_empy_take_stdout
from support.user_checkouts import CHECKOUTS
from testing import ros_paths

# What the tests take from PyPI (rosbags), installed there by
# scripts/setup.sh --tests (scripts/test-requirements.txt), not into a Python of the system.
sys.path.append(os.path.join(REPO, 'build', 'test-python'))


# The mros2 corpora's fixtures (tests/support/mros2_corpus.py).
pytest_plugins = ['support.mros2_corpus']


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


@pytest.fixture(autouse=True)
def empy_takes_the_tests_stdout():
    """Each test lets its first empy interpreter wrap its stdout."""
    let_empy_take_stdout()
    yield


@pytest.fixture(scope='session')
def debian_export(tmp_path_factory):
    """genmros mros-v1-export of every Debian message package: the include root."""
    root = str(tmp_path_factory.mktemp('debian_export'))
    arguments = ['mros-v1-export', '-o', root,
                 *ros_paths.prefix_arguments(ros_paths.ros1_prefixes())]
    for package in DEBIAN_MESSAGE_PACKAGES:
        arguments += ['--package', package]
    run_genmros(*arguments)
    return root


@pytest.fixture(scope='session')
def test_ws_export(tmp_path_factory):
    """genmros mros-v1-export of test_ws: the include root."""
    root = str(tmp_path_factory.mktemp('test_ws_export'))
    run_genmros('mros-v1-export', '--workspace', TEST_WS, '-o', root,
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
