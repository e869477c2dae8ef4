# SPDX-License-Identifier: BSD-3-Clause
"""Services both ways on the PC target (genmros mros2-pc, hardened: the patch
services-both-ways), on both targets, against the service peer (rclpy, the ROS 2 wheels' Fast
DDS with its defaults; testing/mros2_pc_services.py).

The app is testing/mros2_pc_apps/service_pair: it serves parameter_types and calls the peer's
name_lengths, both rcl_interfaces/srv/GetParameterTypes, whose reply gives each name's length.
The board's config is mros2-posix' with MAX_TYPENAME_LENGTH 64 (the services' type names take
up to 49)."""

import re

import pytest

from support import mros2_pc_boards
from support.user_checkouts import MROS2_ROOT
from testing import mros2_pc, mros2_soak

pytestmark = [pytest.mark.needs_mros2, pytest.mark.slow]

APP = mros2_soak.SERVICE_PAIR
CALLS = 100
CLIENTS = 3
SERVICE_TYPE = ['rcl_interfaces/srv/GetParameterTypes']

# The fixtures, shared.
posix_root = mros2_pc_boards.posix_root


@pytest.fixture(scope='module', params=['native', 'arm'])
def exchange(request, posix_root, tmp_path_factory):
    """One run of the board with the service peer: (the peer's report, the board's output)."""
    work = tmp_path_factory.mktemp('services_%s' % request.param)
    config = mros2_soak.changed_config(posix_root, str(work), [mros2_soak.LONG_TYPE_NAMES])
    program = mros2_pc.build(APP, str(work / 'build'), MROS2_ROOT, config, hardened=True,
                             target=request.param)
    job = mros2_soak.service_job(CALLS)
    with mros2_pc.Session(program, str(work)) as session:
        session.start_board()
        assert session.wait_for_output('app ready')
        report = session.peer(job, script=mros2_pc.SERVICES_SCRIPT).result()
        assert session.wait_for_output('calls done')
        return report, session.stop_board()


def test_rclpy_calls_the_boards_service_100_times_with_every_reply_right(exchange):
    report, _ = exchange
    assert report['calls'] == [CALLS, CALLS]


def test_three_rclpy_clients_at_once_each_get_only_their_own_replies(exchange):
    report, _ = exchange
    assert report['clients'] == [[10, 10]] * CLIENTS


def test_a_client_gone_before_its_reply_leaves_the_service_serving(exchange):
    """The peer destroys a client right after its request; the board's reply writer forgets
    its reader at the reader's dispose, so the next 100 calls (ten times the writer's depth)
    all come back, and no reply is refused."""
    report, output = exchange
    assert report['after_gone'] == [CALLS, CALLS]
    assert re.findall(r'requests \d+ \((\d+) replies refused\)', output)[-1] == '0'


def test_the_board_calls_rclpys_service_100_times_with_every_field_right(exchange):
    report, output = exchange
    assert report['requests'] == [['call %d' % i, 'x' * i] for i in range(CALLS)]
    assert ['call %d ok' % i for i in range(CALLS)] == [
        line for line in output.splitlines() if line.startswith('call ')]


def test_rclpy_lists_the_boards_service_by_name_and_by_node(exchange):
    report, _ = exchange
    assert ['/parameter_types', SERVICE_TYPE] in report['services']
    assert report['services_by_node'] == [['/parameter_types', SERVICE_TYPE]]
