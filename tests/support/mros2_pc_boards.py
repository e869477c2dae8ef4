# SPDX-License-Identifier: BSD-3-Clause
"""What the mros2 PC-target tests share: the user's mros2-posix (MROS2_POSIX_ROOT: its
example apps and its include/rtps/config.h, the board's config) and the ROS 2 type store
the samples are serialized with: fixtures, which a test module takes as its own by
assigning them (posix_root = mros2_pc_boards.posix_root)."""

import os

import pytest

from testing import mros2_pc


@pytest.fixture(scope='module')
def posix_root():
    """MROS2_POSIX_ROOT; the test skips, saying why, without it or the wheels' rclpy."""
    root = os.environ.get('MROS2_POSIX_ROOT')
    if not root or not os.path.isfile(os.path.join(root, 'workspace', 'echoreply_string',
                                                   'app.cpp')):
        pytest.skip('needs mros2-posix (its workspace/ example apps and include/rtps/config.h):'
                    ' set MROS2_POSIX_ROOT (docs/testing.md)')
    if not os.path.isfile(os.path.join(mros2_pc.WHEELS_VENV, 'bin', 'python')):
        pytest.skip('no %s (rclpy): run scripts/setup.sh --tests' % mros2_pc.WHEELS_VENV)
    return root


@pytest.fixture(scope='module')
def typestore():
    from rosbags.typesys import Stores, get_typestore
    return get_typestore(Stores.ROS2_HUMBLE)


def config_of(posix_root):
    return os.path.join(posix_root, 'include', 'rtps', 'config.h')
