# SPDX-License-Identifier: BSD-3-Clause
"""The patch data-frag-for-best-effort-readers, unit-tested: embeddedRTPS' real
MessageReceiver of a copy of MROS2_ROOT, as it is, with the patch alone and with the whole
series (through the series' driver), fed hand-built datagrams by the receiver check of
testing/mros2_library (its readers and writers are listed there). The check's config gives
two buffers of 1000 bytes; fragments are 100 bytes. And templates.hpp's buffer rule,
compiled against the patched header."""

import os
import shutil
import subprocess

import pytest

from colcon_mros.library_tools.mros2.patches import LIBRARY_DIRS, mros2_patches
from colcon_mros.library_tools.mros2.pc_target.build import TARGET_DIR
from colcon_mros.core.storage import HeapStorage
from colcon_mros.library_tools.patch_series import apply_patches
from colcon_mros.mros2.endpoints import parse_endpoints
from colcon_mros.mros2.render import templates_header
from colcon_mros.mros2.rules import data_frag_requirements
from colcon_mros.ros2.interfaces import all_packages
from colcon_mros.ros2.model import ModelBuilder
from support.checkout import REPO
from testing.ros_paths import ros2_prefixes
from testing.rtps_datagrams import data, data_frag, rtps_header
from support.user_checkouts import MROS2_ROOT

pytestmark = [pytest.mark.needs_mros2, pytest.mark.slow]

STAND_IN = os.path.join(REPO, 'testing', 'mros2_library')
PATCH = 'data-frag-for-best-effort-readers'
# The patch after which the receiver hands its readers what it read of the inline QoS.
INLINE_QOS_PATCH = 'services-both-ways'
REMOTE = bytes([0x11] * 12)
BEST_EFFORT, RELIABLE = bytes([0, 0, 1, 4]), bytes([0, 0, 2, 4])
WRITER_1, WRITER_2, WRITER_3, WRITER_4 = (bytes([0, 0, key, 3]) for key in (1, 2, 3, 4))
UNMATCHED = bytes([0, 0, 5, 3])
FRAGMENT = 100
BUFFER = 1000


def _copy(checkout, patches):
    """A copy of MROS2_ROOT's library at checkout, with the named patches."""
    for part in LIBRARY_DIRS:
        shutil.copytree(os.path.join(MROS2_ROOT, part), str(checkout / part))
    apply_patches(str(checkout), [patch for patch in mros2_patches() if patch.name in patches])
    return checkout


def _build(tmp_path, patches, buffers=True):
    checkout = _copy(tmp_path / 'mros2', patches)
    program = str(tmp_path / 'receiver_check')
    sources = [str(checkout / 'embeddedRTPS' / 'src' / 'messages' / name)
               for name in ('MessageReceiver.cpp', 'MessageTypes.cpp')]
    command = ['g++', '-std=gnu++14', '-g', '-fsanitize=address,undefined',
               '-fno-sanitize-recover=all', '-I', os.path.join(STAND_IN, 'receiver'),
               '-I', os.path.join(TARGET_DIR, 'include'),
               '-I', str(checkout / 'embeddedRTPS' / 'include'), *sources,
               os.path.join(STAND_IN, 'receiver_check.cpp'), '-o', program]
    if PATCH in patches:
        command.insert(1, '-DCHECK_FRAGMENT_COUNTS')
    if INLINE_QOS_PATCH in patches:
        command.insert(1, '-DRECEIVER_READS_INLINE_QOS')
    if buffers:
        command[1:1] = ['-DRECEIVER_CHECK_BUFFER_SIZE=%d' % BUFFER, '-DRECEIVER_CHECK_BUFFERS=2']
    result = subprocess.run(command, capture_output=True, text=True)
    assert result.returncode == 0, result.stderr[-4000:]
    return program


@pytest.fixture(scope='module')
def patched(tmp_path_factory):
    return _build(tmp_path_factory.mktemp('patched'), [PATCH])


def _run(program, *datagrams):
    """(samples as (reader, writer, sn, bytes), counts) the check printed."""
    result = subprocess.run([program], input=''.join(d.hex() + '\n' for d in datagrams),
                            capture_output=True, text=True, timeout=60)
    assert result.returncode == 0 and result.stderr == '', result.stderr[-4000:]
    samples, counts = [], None
    for line in result.stdout.splitlines():
        fields = line.split()
        if fields[0] == 'reader':
            samples.append((fields[1], fields[3], int(fields[5]), bytes.fromhex(fields[6])))
        else:
            counts = dict(zip(('too_large', 'pool_full', 'inconsistent', 'abandoned',
                               'unmatched'), map(int, fields[1:])))
    return samples, counts


def _sample(size, seed=1):
    """size bytes: a CDR little-endian encapsulation, then bytes that tell places apart."""
    return bytes([0, 1, 0, 0]) + bytes((seed * 7 + i) % 251 for i in range(size - 4))


def _fragment(sample, number, count=1, writer=WRITER_1, sn=1, reader=BEST_EFFORT,
              fragment_size=FRAGMENT, sample_size=None):
    """A datagram of fragments number..number + count - 1 of sample."""
    start = (number - 1) * fragment_size
    payload = sample[start:start + count * fragment_size]
    return rtps_header(REMOTE) + data_frag(
        reader, writer, sn, number, fragment_size,
        len(sample) if sample_size is None else sample_size, payload, count).encode()


def _nothing_refused(**counts):
    base = dict(too_large=0, pool_full=0, inconsistent=0, abandoned=0, unmatched=0)
    base.update(counts)
    return base


def test_in_order_in_one_submessage_and_out_of_order(patched):
    sample = _sample(250)
    in_order = [_fragment(sample, n) for n in (1, 2, 3)]
    out_of_order = [_fragment(sample, n, sn=2) for n in (3, 1, 2)]
    together = [_fragment(sample, 1, count=2, sn=3), _fragment(sample, 3, sn=3)]
    samples, counts = _run(patched, *in_order, *out_of_order, *together)
    assert samples == [('01', '01', sn, sample) for sn in (1, 2, 3)]
    assert counts == _nothing_refused()


def test_a_repeated_fragment_is_ignored(patched):
    sample = _sample(250)
    sent = [_fragment(sample, n) for n in (1, 1, 2, 1, 2, 3, 3, 2)]
    samples, counts = _run(patched, *sent)
    assert samples == [('01', '01', 1, sample)]
    assert counts == _nothing_refused()


def test_at_the_buffers_size_taken_one_byte_over_refused(patched):
    at_size, over = _sample(BUFFER), _sample(BUFFER + 1, seed=2)
    sent = [_fragment(at_size, n) for n in range(1, 11)] + \
        [_fragment(over, n, sn=2) for n in range(1, 12)]
    samples, counts = _run(patched, *sent)
    assert samples == [('01', '01', 1, at_size)]
    assert counts == _nothing_refused(too_large=1)


@pytest.mark.parametrize('wrong', [
    # the first fragment again with other bytes
    lambda sample: _fragment(bytes(len(sample)), 1),
    # past the end: two fragments announced, one and a half carried
    lambda sample: _fragment(sample[:150], 2, count=2, sample_size=250),
    # a fragment number out of range (a sample of 250 bytes has 3)
    lambda sample: _fragment(sample + bytes(100), 4, sample_size=250),
    # other sizes than the first fragment's
    lambda sample: _fragment(sample + bytes(50), 2),
    lambda sample: _fragment(sample, 2, fragment_size=50),
], ids=['overlap-other-bytes', 'past-the-end', 'number-out-of-range', 'sample-size',
        'fragment-size'])
def test_fragments_that_disagree_refuse_the_sample(patched, wrong):
    sample = _sample(250)
    sent = [_fragment(sample, 1), wrong(sample)] + [_fragment(sample, n) for n in (1, 2, 3)]
    samples, counts = _run(patched, *sent)
    assert samples == []
    assert counts == _nothing_refused(inconsistent=1)


def test_an_abandoned_sample_gives_way_to_the_newer(patched):
    older, newer = _sample(250), _sample(250, seed=2)
    # the older sample's fragments that come late are ignored, its first too (not counted)
    sent = [_fragment(older, 1), _fragment(older, 2), _fragment(newer, 1, sn=2),
            _fragment(older, 3), _fragment(older, 1), _fragment(newer, 2, sn=2),
            _fragment(newer, 3, sn=2)]
    samples, counts = _run(patched, *sent)
    assert samples == [('01', '01', 2, newer)]
    assert counts == _nothing_refused(abandoned=1)


def test_interleaved_writers_each_whole_and_a_full_pool_refuses_the_third(patched):
    first, second, third = (_sample(250, seed=seed) for seed in (1, 2, 3))
    sent = [_fragment(first, 1, writer=WRITER_1), _fragment(second, 1, writer=WRITER_2),
            _fragment(third, 1, writer=WRITER_4), _fragment(first, 2, writer=WRITER_1),
            _fragment(second, 2, writer=WRITER_2), _fragment(third, 2, writer=WRITER_4),
            _fragment(first, 3, writer=WRITER_1), _fragment(second, 3, writer=WRITER_2),
            _fragment(third, 3, writer=WRITER_4)]
    samples, counts = _run(patched, *sent)
    assert samples == [('01', '01', 1, first), ('01', '02', 1, second)]
    assert counts == _nothing_refused(pool_full=1)
    # once they are whole, the third writer's next sample finds a buffer
    samples, _ = _run(patched, *sent, *[_fragment(third, n, writer=WRITER_4, sn=2)
                                        for n in (1, 2, 3)])
    assert samples[-1] == ('01', '04', 2, third)


def test_unmatched_writers_and_reliable_readers_are_refused(patched):
    sample = _sample(250)
    sent = [_fragment(sample, n, writer=UNMATCHED) for n in (1, 2, 3)] + \
        [_fragment(sample, n, writer=WRITER_3, reader=RELIABLE) for n in (1, 2, 3)]
    samples, counts = _run(patched, *sent)
    assert samples == []
    assert counts == _nothing_refused(unmatched=2)


def _fragment_then_data(sample):
    """A datagram: fragment 1 of sample, then a DATA of a small sample (sn 9)."""
    return _fragment(sample, 1) + data(BEST_EFFORT, WRITER_1, 9, _sample(12)).encode()


@pytest.mark.parametrize('patches', [[PATCH], [patch.name for patch in mros2_patches()]],
                         ids=['alone', 'with-the-series'])
def test_without_the_config_settings_nothing_changes(tmp_path, patches):
    """The default buffer is 0 bytes: every sample in fragments is refused (counted), a
    DATA after a fragment in the same datagram still goes to its reader."""
    program = _build(tmp_path, patches, buffers=False)
    sample = _sample(250)
    samples, counts = _run(program, _fragment_then_data(sample), _fragment(sample, 2),
                           _fragment(sample, 3))
    assert samples == [('01', '01', 9, _sample(12))]
    assert counts == _nothing_refused(too_large=1)


def test_as_it_is_fragments_are_skipped(tmp_path):
    program = _build(tmp_path, [])
    sample = _sample(250)
    samples, counts = _run(program, _fragment_then_data(sample), _fragment(sample, 2),
                           _fragment(sample, 3))
    assert samples == [('01', '01', 9, _sample(12))] and counts is None


@pytest.fixture(scope='module')
def patched_root(tmp_path_factory):
    return _copy(tmp_path_factory.mktemp('patched_root'), [PATCH])


@pytest.mark.parametrize('buffer, error', [(736, None), (732, True), (None, True)],
                         ids=['enough', 'too-small', 'not-set'])
def test_templates_hpp_holds_the_buffer_rule(tmp_path, patched_root, buffer, error):
    """templates.hpp's static_assert on FRAGMENT_BUFFER_SIZE, for a type the ROS side sends
    in fragments (BoundedPlainSequences: 736 bytes with its encapsulation, over a
    --peer-max-message of 600), compiled against the patched receiver's header, whose
    default the board's config may replace."""
    endpoints, _ = parse_endpoints([], ['large:test_interface_files/msg/BoundedPlainSequences'],
                                   ModelBuilder(all_packages((), ros2_prefixes()),
                                                HeapStorage()).message)
    rules = [rule for rule in data_frag_requirements(endpoints, 600)
             if rule.setting == 'FRAGMENT_BUFFER_SIZE']
    text = templates_header(endpoints, rules)['templates.hpp']
    start = text.index('static_assert(736 <= rtps::Config::FRAGMENT_BUFFER_SIZE')
    source = tmp_path / 'rule.cpp'
    source.write_text('#include "rtps/messages/MessageReceiver.h"\n' +
                      text[start:text.index(';', start) + 1] + '\n')
    command = ['g++', '-std=gnu++14', '-fsyntax-only', '-I', os.path.join(STAND_IN, 'receiver'),
               '-I', os.path.join(TARGET_DIR, 'include'),
               '-I', str(patched_root / 'embeddedRTPS' / 'include'), str(source)]
    if buffer is not None:
        command += ['-DRECEIVER_CHECK_BUFFER_SIZE=%d' % buffer, '-DRECEIVER_CHECK_BUFFERS=1']
    result = subprocess.run(command, capture_output=True, text=True)
    if error:
        assert result.returncode != 0
        assert ('test_interface_files/msg/BoundedPlainSequences: a sample of up to 732 bytes '
                'and its encapsulation, put together from the fragments the ROS side sends '
                '(over --peer-max-message 600) needs rtps::Config::FRAGMENT_BUFFER_SIZE >= 736 '
                '(rtps/config.h)') in result.stderr
    else:
        assert result.returncode == 0, result.stderr
