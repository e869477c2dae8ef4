# SPDX-License-Identifier: BSD-3-Clause
"""On-board delivery while frames wait, on the real mROS v1 library: an app
(tests/fixtures/mros_v1_pc_app/onboard_burst.cpp) keeps its subscriber
task busy while one message waits on one topic and six more are published
on another of the same type. Each message the library delivers arrives
whole: delivery remembers where every waiting frame of a type is, as many
as the library's publishing pools hold (it remembered the last 4 notes)."""

import pytest

from testing.ros_graph import DELIVERY_TIMEOUT, Board, RosGraph
from support.user_checkouts import MROS_V1_ROOT
from support.pc_target_apps import build_app

pytestmark = [pytest.mark.needs_mros_v1, pytest.mark.needs_qemu, pytest.mark.slow]


@pytest.mark.parametrize('flags', [(), ('--hardened',)], ids=['as it is', 'hardened'])
def test_a_waiting_frame_arrives_whole_after_more_of_its_type(tmp_path, flags):
    # Hardened, the library passes each frame's size to delivery
    # (frame-size-to-delivery), which then needs no note of it.
    program = build_app(MROS_V1_ROOT, str(tmp_path), 'onboard_burst.cpp', header_flags=flags)
    with RosGraph() as graph:
        board = Board(graph, program, str(tmp_path))
        board.process.wait_for('published', timeout=DELIVERY_TIMEOUT)
        board.process.wait_for(r'got \w \S+ \d+', timeout=DELIVERY_TIMEOUT, count=3)
        got = sorted(line.split('got ', 1)[1] for line in board.process.lines() if 'got ' in line)
    # The library keeps the newest message of a topic.
    assert got == ['a gggggg 6', 'a xxx 0', 'b %s 100' % ('b' * 20)], board.process.output()
