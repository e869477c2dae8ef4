# SPDX-License-Identifier: BSD-3-Clause
"""Fixtures shared by the test modules."""

import os
import subprocess
import sys

import pytest

from support import built_workspace
from support.checkout import REPO, TEST_WS, run_genmros
from support.debian_messages import DEBIAN_MESSAGE_PACKAGES
from support.user_checkouts import CHECKOUTS
from testing import ros_paths
from testing.ros_graph import let_children_stop_on_sigint

# What the tests take from PyPI (rosbags), installed there by
# scripts/setup.sh --tests (scripts/test-requirements.txt), not into a Python of the system.
sys.path.append(os.path.join(REPO, 'build', 'test-python'))

# The suite started in the background (`scripts/run-tests.sh &`) ignores SIGINT; the
# processes its tests stop with SIGINT, as a user's Ctrl-C does, must not.
let_children_stop_on_sigint()


# The mros2 corpora's fixtures (tests/support/mros2_corpus.py), and empy 3's stdout proxy
# kept across pytest's capture (tests/support/empy_stdout.py).
pytest_plugins = ['support.mros2_corpus', 'support.empy_stdout']


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


@pytest.fixture(scope='session')
def empy4_python(tmp_path_factory):
    """The python of a venv over Debian's Python (genmsg, rosidl) with empy 4
    from PyPI (pip's cache will do) in place of Debian's empy 3, made once per
    session; a test that needs it skips, saying why, where pip gets no empy 4."""
    venv = str(tmp_path_factory.mktemp('empy4_venv'))
    subprocess.run(['/usr/bin/python3', '-m', 'venv', '--system-site-packages', venv], check=True)
    python = os.path.join(venv, 'bin', 'python')
    result = subprocess.run([python, '-m', 'pip', 'install', '-q', 'empy>=4,<5'],
                            capture_output=True, text=True)
    if result.returncode != 0:
        pytest.skip('no empy 4 from PyPI for the venv: %s'
                    % (result.stderr.strip().splitlines() or ['pip failed'])[-1])
    return python


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
