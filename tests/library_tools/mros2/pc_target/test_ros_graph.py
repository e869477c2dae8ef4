# SPDX-License-Identifier: BSD-3-Clause
"""The board in the ROS 2 graph (genmros mros2-pc, hardened: the patch node-in-the-ros-graph),
as rclpy's graph API shows it, the API ``ros2 node list`` and ``ros2 node info`` ask.

The app is testing/mros2_pc_apps/reliable_echo (node reliable_echo: publishers text_echo
and plain_echo, subscriptions text and plain, all std_msgs/msg/String). The board's config
is mros2-posix' with MAX_TYPENAME_LENGTH 64 (ros_discovery_info's type name takes 52) and a
lease of 10 s (embeddedRTPS announces SPDP_DEFAULT_REMOTE_LEASE_DURATION, 100 s in
mros2-posix)."""

import os

import pytest

from support import mros2_pc_boards
from support.user_checkouts import MROS2_ROOT
from testing import mros2_pc, mros2_soak

pytestmark = [pytest.mark.needs_mros2, pytest.mark.slow]

APP = os.path.join(mros2_soak.APPS, 'reliable_echo')
LEASE = 10
STRING = ['std_msgs/msg/String']

# The fixtures, shared.
posix_root = mros2_pc_boards.posix_root


@pytest.fixture(scope='module')
def program(posix_root, tmp_path_factory):
    work = tmp_path_factory.mktemp('ros_graph')
    config = mros2_soak.changed_config(posix_root, str(work), [
        (r'SPDP_DEFAULT_REMOTE_LEASE_DURATION = \{\s*100, 0\}',
         'SPDP_DEFAULT_REMOTE_LEASE_DURATION = {%d, 0}' % LEASE), mros2_soak.LONG_TYPE_NAMES])
    return mros2_pc.build(APP, str(work / 'build'), MROS2_ROOT, config, hardened=True,
                          target='native')


def test_rclpy_lists_the_node_with_exactly_its_topics_and_drops_it_after_its_lease(
        program, tmp_path):
    with mros2_pc.Session(program, str(tmp_path)) as session:
        session.start_board()
        assert session.wait_for_output('app ready')
        watcher = session.graph_watcher('reliable_echo', publishers=2, subscribers=2)
        seen = watcher.seen()
        session.stop_board()
        gone_after = watcher.gone()
    assert seen['seen_after'] is not None, seen
    assert ['reliable_echo', '/'] in seen['nodes']
    assert seen['publishers'] == [['/plain_echo', STRING], ['/text_echo', STRING]]
    assert seen['subscribers'] == [['/plain', STRING], ['/text', STRING]]
    # Gone once the lease the board announced has run out (Fast DDS checks it then).
    assert gone_after is not None and gone_after <= 2 * LEASE, gone_after
