# SPDX-License-Identifier: BSD-3-Clause
"""Reliable endpoints on the PC target (genmros mros2-pc, hardened: the patches
acknacks-on-the-writer-threads and reliable-where-asked), on both targets, against the plain
node (rclpy, the ROS 2 wheels' Fast DDS with its defaults).

The app is testing/mros2_pc_apps/reliable_echo: what comes on text (a reliable subscription)
goes back on text_echo (a reliable publisher keeping its last 10), published in the callback;
plain and plain_echo are best-effort, created with mros2's int argument. The board's config is
mros2-posix' (HISTORY_SIZE_STATEFUL 10, THREAD_POOL_WORKLOAD_QUEUE_LENGTH 20)."""

import os
import re

import pytest

from support import mros2_pc_boards
from support.mros2_pc_boards import config_of
from support.user_checkouts import MROS2_ROOT
from testing import mros2_pc, mros2_soak
from testing.mros2_posix import wire_bytes

pytestmark = [pytest.mark.needs_mros2, pytest.mark.slow]

APP = os.path.join(mros2_soak.APPS, 'reliable_echo')
STRING = 'std_msgs/msg/String'
# The board's port for user data (embeddedRTPS: participant 0 of domain 0).
USER_PORT = 7411

# The fixtures, shared.
posix_root = mros2_pc_boards.posix_root
typestore = mros2_pc_boards.typestore


@pytest.fixture(scope='module', params=['native', 'arm'])
def program(request, posix_root, tmp_path_factory):
    work = tmp_path_factory.mktemp('reliable_%s' % request.param)
    return mros2_pc.build(APP, str(work / 'build'), MROS2_ROOT, config_of(posix_root),
                          hardened=True, target=request.param)


def _texts(typestore, count, prefix='text'):
    message = typestore.types[STRING]
    return [wire_bytes(typestore, message(data='%s %d' % (prefix, index)), STRING)
            for index in range(count)]


def _exchange(program, tmp_path, job, drop_every=None):
    """The board and the plain node with job; (the node's report, the board's output).
    drop_every: the board's network drops every so many datagrams to its user-data port."""
    with mros2_pc.Session(program, str(tmp_path)) as session:
        if drop_every:
            session.drop_datagrams(USER_PORT, drop_every)
        session.start_board()
        assert session.wait_for_output('app ready')
        report = session.peer(job).result()
        return report, session.stop_board()


def _refused(output):
    """How many publishes the board's app saw refused (its last count)."""
    counts = re.findall(r'\((\d+) refused\)', output)
    return int(counts[-1]) if counts else 0


def test_a_default_qos_subscription_gets_every_sample_of_a_reliable_publisher(
        program, typestore, tmp_path):
    """rclpy's default QoS (reliable, keep last 10) on both sides: every echo, in order."""
    texts = _texts(typestore, 100)
    job = mros2_pc.plain_job(publish=[('text', STRING, texts)],
                             subscribe=[('text_echo', STRING)], expect={'text_echo': 100},
                             period=0.02, qos={'text': 'default', 'text_echo': 'default'})
    report, output = _exchange(program, tmp_path, job)
    assert report['received']['text_echo'] == texts
    assert 'text 100 (0 refused)' in output


def test_a_burst_of_1000_comes_back_whole_and_in_order(program, typestore, tmp_path):
    """The node publishes 1000 at once (reliable, keep all); the board's history of 10 holds
    each echo until the node has it."""
    texts = _texts(typestore, 1000)
    job = mros2_pc.plain_job(publish=[('text', STRING, texts)],
                             subscribe=[('text_echo', STRING)], expect={'text_echo': 1000},
                             period=0, qos={'text': 'keep_all', 'text_echo': 'keep_all'})
    report, output = _exchange(program, tmp_path, job)
    assert report['received']['text_echo'] == texts
    assert _refused(output) == 0


def test_with_datagrams_dropped_the_burst_still_comes_back_whole(program, typestore, tmp_path):
    """The board's network drops every 20th datagram to its port (samples, answers, ACKNACKs
    and heartbeats alike): what is lost is asked for again, both ways."""
    texts = _texts(typestore, 1000)
    job = mros2_pc.plain_job(publish=[('text', STRING, texts)],
                             subscribe=[('text_echo', STRING)], expect={'text_echo': 1000},
                             period=0, reply_wait=mros2_pc.EVENT_CAP,
                             qos={'text': 'keep_all', 'text_echo': 'keep_all'})
    report, output = _exchange(program, tmp_path, job, drop_every=20)
    assert report['received']['text_echo'] == texts
    assert _refused(output) == 0


def test_best_effort_endpoints_beside_them_are_as_before(program, typestore, tmp_path):
    texts = _texts(typestore, 20, 'plain')
    job = mros2_pc.plain_job(publish=[('plain', STRING, texts)],
                             subscribe=[('plain_echo', STRING)], expect={'plain_echo': 20})
    report, _ = _exchange(program, tmp_path, job)
    assert report['received']['plain_echo'] == texts


def test_a_reliable_subscription_does_not_match_a_best_effort_publisher(
        program, typestore, tmp_path):
    """As DDS has it: a best-effort writer offers less than a reliable reader asks, so the
    node's publisher sees no subscription (and the node sends nothing)."""
    job = mros2_pc.plain_job(publish=[('text', STRING, _texts(typestore, 1))],
                             subscribe=[('text_echo', STRING)], match_wait=15)
    report, _ = _exchange(program, tmp_path, job)
    assert not report['matched'] and report['sent'] == 0
