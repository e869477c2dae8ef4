# SPDX-License-Identifier: BSD-3-Clause
"""The patch reader-catches-up-at-once, unit-tested: embeddedRTPS' real StatefulReader of a
copy of MROS2_ROOT, as it is and with the patch (alone, and with the whole series, through
the series' driver), driven by the stateful reader check of testing/mros2_library against a
writer simulated here as Fast DDS' SEDP writer behaves when a node starts (seen in a capture
of genmros mros2-pc against an rclpy node): it announces its first samples with a heartbeat,
sends its newer ones as they are made, answers each ACKNACK with the samples it asks for,
and sends a heartbeat each period."""

import pytest

from support.entity_checks import VERSIONS, RunningCheck, build_version

pytestmark = [pytest.mark.needs_mros2]

PATCH = 'reader-catches-up-at-once'
# An rclpy node's publications: 13 endpoints, 2 of them made before the board matched.
SAMPLES = 13
ANNOUNCED = 2


@pytest.fixture(scope='module', params=VERSIONS)
def reader(request, tmp_path_factory):
    """(version, the check built on it)."""
    return request.param, build_version(request.param, PATCH,
                                        tmp_path_factory.mktemp(request.param),
                                        'stateful_reader_check', 'reader')


class Reader(RunningCheck):
    """The stateful reader check running: steps in, what the reader did out."""

    def step(self, line):
        """([sequence numbers taken], [[sequence numbers asked for] per ACKNACK])."""
        taken, asked = [], []
        for output in super().step(line):
            kind, *numbers = output.split()
            (taken.extend if kind == 'took' else asked.append)(list(map(int, numbers)))
        return taken, asked


def _node_start(program, heartbeat_periods=30, answered=None, size=4):
    """The simulated writer against the reader until it has taken every sample: (the heartbeat
    periods that took, the samples in the order taken, the ACKNACKs' requests). answered: how
    many of the samples asked for an answer brings (a board cuts a datagram at its receive
    limit); all by default. size: each sample's, in bytes."""
    reader = Reader(program)
    taken, requests = [], []
    count = 1
    pending = reader.step('heartbeat 1 %d %d' % (ANNOUNCED, count))[1]
    for sn in range(ANNOUNCED + 1, SAMPLES + 1):  # made after the match: sent at once
        got, asked = reader.step('data %d %d' % (sn, size))
        taken += got
        pending += asked
    periods = 0
    while len(taken) < SAMPLES and periods < heartbeat_periods:
        while pending:  # each ACKNACK answered with what it asks for
            request = pending.pop(0)
            requests.append(request)
            for sn in request[:answered]:
                got, asked = reader.step('data %d %d' % (sn, size))
                taken += got
                pending += asked
        if len(taken) < SAMPLES:
            periods += 1
            count += 1
            pending += reader.step('heartbeat 1 %d %d' % (SAMPLES, count))[1]
    reader.close()
    return periods, taken, requests


def test_a_node_start_is_caught_up_with_before_the_next_heartbeat(reader):
    version, program = reader
    periods, taken, requests = _node_start(program)
    assert taken == list(range(1, SAMPLES + 1))
    if version == 'as-it-is':
        # The defect: one sample asked for, and taken, per heartbeat period.
        assert periods == SAMPLES - ANNOUNCED + 1
        assert all(len(request) == 1 for request in requests)
    else:
        assert periods == 0
        # 4 at first, then twice as many after each answer taken whole: the samples are
        # small (4 bytes), so many fit the datagram Fast DDS answers in.
        assert requests == [[1, 2], [3, 4, 5, 6, 7, 8, 9, 10], [11, 12, 13]]


def test_discovery_samples_are_asked_for_4_at_a_time(reader):
    """4 SEDP samples of about 700 bytes fill what an answer may hold: no more are asked."""
    version, program = reader
    periods, taken, requests = _node_start(program, size=700)
    assert taken == list(range(1, SAMPLES + 1))
    if version != 'as-it-is':
        assert periods == 0
        assert requests == [[1, 2], [3, 4, 5, 6], [7, 8, 9, 10], [11, 12, 13]]


def test_a_lost_answer_is_asked_for_again_in_half(reader):
    """Nothing of the answer came: lost, or cut before its first sample (a receive limit
    below it); the reader cannot tell, and asks for half as many."""
    version, program = reader
    checked = Reader(program)
    assert checked.step('heartbeat 1 8 1')[1] == ([[1]] if version == 'as-it-is' else
                                                  [[1, 2, 3, 4]])
    assert checked.step('heartbeat 1 8 2')[1] == ([[1]] if version == 'as-it-is' else [[1, 2]])
    checked.close()


def test_answers_cut_to_one_sample_make_the_requests_smaller(reader):
    version, program = reader
    periods, taken, requests = _node_start(program, answered=1)
    assert taken == list(range(1, SAMPLES + 1))
    if version == 'as-it-is':
        assert periods == SAMPLES - ANNOUNCED + 1
    else:
        # A heartbeat finds [1, 2] answered with 1 alone, the next [2, 3]: two halvings, then
        # one at a time, each asked for as soon as the one before is taken, until 8 came
        # whole: two are tried once more, [11, 12], which the next heartbeat finds cut.
        assert periods == 3
        assert requests == [[1, 2], [2, 3]] + [[sn] for sn in range(3, 11)] + [[11, 12]] + [
            [sn] for sn in range(12, SAMPLES + 1)]


def test_what_the_writer_no_longer_has_is_not_waited_for(reader):
    version, program = reader
    checked = Reader(program)
    # The writer holds 5 to 8: samples 1 to 4 are gone.
    taken, asked = checked.step('heartbeat 5 8 1')
    assert asked == ([[1]] if version == 'as-it-is' else [[5, 6, 7, 8]])
    assert checked.step('data 5') == (([], []) if version == 'as-it-is' else ([5], []))
    # A heartbeat whose first is past its last and one: not a range; nothing is skipped. It
    # finds the request answered in part: the next asks for half as many.
    taken, asked = checked.step('heartbeat 20 8 2')
    assert asked == ([[1]] if version == 'as-it-is' else [[6, 7]])
    checked.close()


def test_a_sample_after_a_gap_asks_once_for_what_is_missing(reader):
    version, program = reader
    checked = Reader(program)
    assert checked.step('data 1') == ([1], [])
    gap = [checked.step('data %d' % sn) for sn in (3, 4)]
    if version == 'as-it-is':
        assert gap == [([], []), ([], [])]
    else:
        # Sample 3 shows the writer has 2 and 3; 4 comes while that request is open.
        assert gap == [([], [[2, 3]]), ([], [])]
        assert checked.step('data 2') == ([2], [])
        assert checked.step('data 3') == ([3], [[4]])
    checked.close()
