# SPDX-License-Identifier: BSD-3-Clause
"""The patch best-effort-writer-after-a-burst, unit-tested: embeddedRTPS' real StatelessWriter
of a copy of MROS2_ROOT, as it is and with the patch (alone, and with the whole series),
driven by the stateless writer check of testing/mros2_library, which runs the writer
thread's workloads by hand: a burst of samples published before the writer thread takes
their workloads, more than the history holds (HISTORY_SIZE_STATELESS 2), then a reader
matched and one more sample."""

import pytest

from support.entity_checks import VERSIONS, RunningCheck, build_version

pytestmark = [pytest.mark.needs_mros2]

PATCH = 'best-effort-writer-after-a-burst'
BURST = 5


@pytest.fixture(scope='module', params=VERSIONS)
def program(request, tmp_path_factory):
    """(version, the check built on it)."""
    return request.param, build_version(request.param, PATCH,
                                        tmp_path_factory.mktemp(request.param),
                                        'stateless_writer_check', 'writer')


@pytest.fixture
def writer(program):
    """(version, a new writer of the check)."""
    version, path = program
    check = RunningCheck(path)
    yield version, check
    check.close()


def _burst(check):
    """What the writer sent of a burst of BURST samples, their workloads run after it."""
    published = [check.step('publish') for _ in range(BURST)]
    assert published == [['published %d' % sn] for sn in range(1, BURST + 1)]
    return [line for _ in range(BURST) for line in check.step('work')]


def test_after_a_burst_with_no_reader_the_next_sample_goes_to_a_new_reader(writer):
    version, check = writer
    assert _burst(check) == []  # nobody to send to
    check.step('reader 1')
    assert check.step('publish') == ['published %d' % (BURST + 1)]
    sent = check.step('work')
    if version == 'as-it-is':
        # The workloads of the 3 dropped samples moved on past the newest: the writer sends
        # none of the next 3 samples.
        assert sent == []
        for sn in range(BURST + 2, BURST + 4):
            assert check.step('publish') == ['published %d' % sn]
            assert check.step('work') == []
        assert check.step('publish') == ['published %d' % (BURST + 4)]
        assert check.step('work') == ['data %d' % (BURST + 4)]
    else:
        assert sent == ['data %d' % (BURST + 1)]


def test_a_burst_to_a_reader_sends_what_the_history_kept_then_each_new_sample(writer):
    _, check = writer
    check.step('reader 1')
    # The history keeps the last 2; the workloads of the 3 dropped ones find nothing.
    assert _burst(check) == ['data %d' % (BURST - 1), 'data %d' % BURST]
    assert check.step('publish') == ['published %d' % (BURST + 1)]
    assert check.step('work') == ['data %d' % (BURST + 1)]
