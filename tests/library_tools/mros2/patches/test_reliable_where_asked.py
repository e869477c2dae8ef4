# SPDX-License-Identifier: BSD-3-Clause
"""The patch reliable-where-asked, unit-tested: embeddedRTPS' real StatefulWriter of a copy
of MROS2_ROOT with the whole series, driven by the stateful writer check of
testing/mros2_library: a writer that keeps its last samples, its readers' ACKNACKs given by
hand (one from another thread while a publish waits), and what it sends recorded."""

import pytest

from colcon_mros.library_tools.mros2.patches import mros2_patches
from support.entity_checks import RunningCheck, build_check

pytestmark = [pytest.mark.needs_mros2]

# The wait for room: long beside an ACKNACK's 50 ms, even on a busy machine.
WAIT = 1000


@pytest.fixture(scope='module')
def program(tmp_path_factory):
    return build_check(tmp_path_factory.mktemp('stateful_writer'), 'stateful_writer_check',
                       'writer', [patch.name for patch in mros2_patches()])


class Writer(RunningCheck):
    """The stateful writer check running: steps in, what the writer did out."""

    def publish(self):
        """(what the publish printed, the milliseconds it waited, the heartbeats it sent)."""
        lines = self.step('publish')
        waited = int(next(line for line in lines if line.startswith('waited')).split()[1])
        result = next(line for line in lines if line.startswith(('published', 'refused')))
        return result, waited, sum(line.startswith('heartbeat') for line in lines)


def _no_wait(published):
    """What a publish printed, once it is shown that it did not wait: no heartbeat asked
    for room."""
    result, _, heartbeats = published
    assert heartbeats == 0, published
    return result


@pytest.fixture
def writer(program):
    checked = Writer(program)
    assert checked.step('keep 3 %d' % WAIT) == ['kept']
    yield checked
    checked.close()


def test_the_depth_is_held_to_the_history(program):
    checked = Writer(program)
    assert checked.step('keep 11 100') == ['refused']  # HISTORY_SIZE_STATEFUL is 10
    assert checked.step('keep 0 100') == ['refused']
    assert checked.step('keep 10 100') == ['kept']
    checked.close()


def test_with_no_reader_the_last_samples_are_kept_and_none_waits(writer):
    for sn in range(1, 6):
        assert _no_wait(writer.publish()) == 'published %d' % sn


def test_a_full_history_nobody_acknowledged_refuses_after_the_wait(writer):
    writer.step('reader 7')
    for sn in range(1, 4):
        assert writer.publish()[0] == 'published %d' % sn
    result, waited, heartbeats = writer.publish()
    assert result == 'refused (1 so far)'
    # It waited its time, asking the reader for an ACKNACK every 10 ms or so.
    assert waited >= WAIT and heartbeats >= 10


def test_an_acknowledgement_makes_room_and_what_is_not_acknowledged_stays(writer):
    writer.step('reader 7')
    writer.step('reader 8')
    for sn in range(1, 4):
        writer.publish()
    # Reader 7 has 1 and 2, reader 8 only 1: one place frees, sample 1's. Each ACKNACK
    # brings what its reader lacks, sent again.
    assert writer.step('acknack 7 3 2') == ['data 3']
    assert writer.step('acknack 8 2 2') == ['data 2', 'data 3']
    assert _no_wait(writer.publish()) == 'published 4'
    assert writer.publish()[0] == 'refused (1 so far)'
    # A reader gone acknowledges nothing more, and holds nothing back.
    writer.step('gone 8')
    assert _no_wait(writer.publish()) == 'published 5'


def test_an_acknowledgement_during_the_wait_ends_it(writer):
    writer.step('reader 7')
    for sn in range(1, 4):
        writer.publish()
    writer.step('acknack-later 50 7 4 2')
    result, waited, heartbeats = writer.publish()
    assert result == 'published 4'
    assert 40 <= waited < WAIT and heartbeats >= 1
