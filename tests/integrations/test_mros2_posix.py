# SPDX-License-Identifier: BSD-3-Clause
"""A real mros2-posix app on genmros' headers exchanges samples with a real rclpy node.

Opt-in: MROS2_POSIX_ROOT names an assembled mros2-posix checkout (docs/mros2.md), and the
run needs root (network namespaces) and the ROS 2 wheels' venv, build/ros2-wheels (rclpy
on Fast DDS 3). A copy of the checkout gets testing/mros2_posix_app with the headers and
templates.hpp of genmros mros2-export, is built without build.bash, and runs in a network
namespace as 192.168.11.3, a veth pair away from an rclpy node at 192.168.11.2. The node
asks for 20 test images (0 to 323 bytes of pixels: the larger ones go out as DATA_FRAG)
and sends 20 strings (6 to 140 characters) that the app decodes and echoes; each answer
is the bytes rosbags writes for the values the app put in, zero-padded to 4 as mros2 pads.

mros2 v0.4.1, which mros2-posix pins, sends every message through its last publisher, so
its app answers everything on one Image publisher; with MROS2_ROOT (mros2 v0.5.4) patched
by genmros mros2-harden in its place, the app has two publishers, and images and String
echoes arrive each on their own topic. Both runs apply genmros' patch
accept-fast-dds-3-discovery to the copy's embeddedRTPS, without which it discovers no Fast
DDS 3 participant (v0.4.1: that patch alone; v0.5.4: the whole series).
"""

import os

import pytest

from testing import mros2_posix
from testing.ros_paths import KILTED_WHEELS

pytestmark = pytest.mark.slow

WHEELS_VENV = KILTED_WHEELS
EXCHANGES = mros2_posix.EXCHANGES


@pytest.fixture(scope='module')
def posix_checkout():
    """The user's mros2-posix checkout; skips, saying why, when a run cannot be made."""
    root = os.environ.get('MROS2_POSIX_ROOT')
    problem = mros2_posix.checkout_problem(root)
    if problem:
        pytest.skip(problem)
    if os.geteuid() != 0:
        pytest.skip('needs root for the network namespace')
    if not os.path.isfile(os.path.join(WHEELS_VENV, 'bin', 'python')):
        pytest.skip('no %s (rclpy): run scripts/setup.sh --tests' % WHEELS_VENV)
    return root


@pytest.fixture(scope='module')
def typestore():
    from rosbags.typesys import Stores, get_typestore
    return get_typestore(Stores.ROS2_HUMBLE)


def _check(exchanged, warnings):
    assert warnings == []
    assert 'app ready' in exchanged.app_output
    for kind in ('images', 'echoes'):
        assert exchanged.wrong(kind) == []
        assert exchanged.exact(kind) == EXCHANGES
    assert max(len(image) for image in exchanged.answers['images']) > 300
    assert max(len(echo) for echo in exchanged.answers['echoes']) > 100
    print('requests sent: %d for %d answers' % (exchanged.requests_sent, 2 * EXCHANGES))


def test_one_publisher_on_the_pinned_mros2(tmp_path, posix_checkout, typestore):
    _check(*mros2_posix.exchange(posix_checkout, WHEELS_VENV, str(tmp_path), typestore))


def test_two_publishers_on_patched_mros2(tmp_path, posix_checkout, typestore):
    mros2_root = os.environ.get('MROS2_ROOT')
    if not mros2_root or not os.path.isfile(os.path.join(mros2_root, 'src', 'mros2.cpp')):
        pytest.skip('MROS2_ROOT is not set to an mros2 v0.5.4 checkout')
    _check(*mros2_posix.exchange(posix_checkout, WHEELS_VENV, str(tmp_path), typestore,
                                 mros2_root))
