# SPDX-License-Identifier: BSD-3-Clause
"""Large samples into a hardened mros2 board on the PC target (genmros mros2-pc, native):
rclpy nodes whose Fast DDS profile (genmros mros2-peer-profile) keeps every
datagram within the board's receive limit, 1472 (an Ethernet frame) and 4096 (mros2-posix'
lwIP), send Images and strings larger than that in fragments, which the patch
data-frag-for-best-effort-readers puts together. The app is
testing/mros2_pc_apps/fragment_echo; the board's config is mros2-posix' with
FRAGMENT_BUFFER_SIZE 65000, FRAGMENT_BUFFERS 2 and THREAD_POOL_WORKLOAD_QUEUE_LENGTH 128
(a sample of 65000 bytes is 51 fragments of 1296 bytes under 1472). Discovery runs under
the same profile: SPDP and SEDP reach the board's reliable readers whole (no echo comes
back otherwise)."""

import os
import re

import numpy
import pytest

from colcon_mros.mros2.rules import FRAGMENT_OVERHEAD
from testing import mros2_pc, mros2_soak
from testing.mros2_posix import wire_bytes
from support.user_checkouts import MROS2_ROOT

from support import mros2_pc_boards
from support.mros2_pc_boards import config_of

pytestmark = [pytest.mark.needs_mros2, pytest.mark.slow]


APP = os.path.join(mros2_soak.APPS, 'fragment_echo')
BUFFER = 65000
STRING, IMAGE = 'std_msgs/msg/String', 'sensor_msgs/msg/Image'
# The board's port for user data (embeddedRTPS: participant 0 of domain 0).
USER_PORT = 7411
LIMITS = [1472, 4096]

# The fixtures, shared.
posix_root = mros2_pc_boards.posix_root
typestore = mros2_pc_boards.typestore


@pytest.fixture(scope='module', params=LIMITS, ids=['limit-%d' % limit for limit in LIMITS])
def board(request, posix_root, tmp_path_factory):
    """(program, receive limit): fragment_echo built hardened for that limit."""
    limit = request.param
    work = tmp_path_factory.mktemp('large_samples_%d' % limit)
    with open(config_of(posix_root)) as stream:
        config = stream.read()
    # A queue for both writers' fragments at once: an Image's 51 and a String's 16 under
    # 1472 (with 64, 2 of 20 strings lost a fragment while the reader thread was busy).
    config = config.replace('THREAD_POOL_WORKLOAD_QUEUE_LENGTH = 20',
                            'THREAD_POOL_WORKLOAD_QUEUE_LENGTH = 128')
    # Two buffers: the node's image and text writers send their fragments at once, and with
    # one the sample begun second finds the pool full (7 of 20 images were refused so).
    config, added = re.subn(r'\}\s*//\s*namespace Config',
                            'const DataSize_t FRAGMENT_BUFFER_SIZE = %d;\nconst uint8_t '
                            'FRAGMENT_BUFFERS = 2;\n} // namespace Config' % BUFFER, config)
    assert added == 1 and 'QUEUE_LENGTH = 128' in config
    (work / 'rtps').mkdir()
    (work / 'rtps' / 'config.h').write_text(config)
    program = mros2_pc.build(APP, str(work / 'build'), MROS2_ROOT, str(work / 'rtps' / 'config.h'),
                             hardened=True, target='native', receive_limit=str(limit),
                             peer_max_message=limit)
    return program, limit


def _strings(typestore, lengths):
    """One String of each length, each its own letters."""
    message = typestore.types[STRING]
    return [wire_bytes(typestore, message(data=chr(ord('a') + index % 26) * length), STRING)
            for index, length in enumerate(lengths)]


def _images(typestore, count, size):
    types = typestore.types
    images = []
    for index in range(count):
        data = numpy.arange(index, index + size, dtype=numpy.uint32).astype(numpy.uint8)
        image = types[IMAGE](
            header=types['std_msgs/msg/Header'](
                stamp=types['builtin_interfaces/msg/Time'](sec=index, nanosec=0),
                frame_id='camera'),
            height=size // 320, width=320, encoding='mono8', is_bigendian=0, step=320, data=data)
        images.append(wire_bytes(typestore, image, IMAGE))
    return images


def _exchange(program, limit, tmp_path, job, drop_every=None):
    """Runs the board and a peer with job under the profile; (peer's report, board's
    output). drop_every: the board's network drops every so many datagrams to its user-data
    port, the first included."""
    job.update(period=0.25)
    with mros2_pc.Session(program, str(tmp_path)) as session:
        if drop_every:
            session.drop_datagrams(USER_PORT, drop_every)
        session.start_board()
        assert session.wait_for_output('app ready')
        report = session.peer(job, max_message=limit).result()
        return report, session.stop_board()


def _refused(output):
    """The board's last counts: {reason: count}, or {} if it printed none."""
    lines = re.findall(r'refused: too large (\d+), pool full (\d+), inconsistent (\d+), '
                       r'abandoned (\d+), unmatched (\d+); dropped (\d+)', output)
    return dict(zip(('too_large', 'pool_full', 'inconsistent', 'abandoned', 'unmatched',
                     'dropped'), map(int, lines[-1]))) if lines else {}


def test_images_of_64_kb_and_strings_of_20_kb_come_back_byte_for_byte(
        board, typestore, tmp_path):
    program, limit = board
    images = _images(typestore, 20, 64000)
    texts = _strings(typestore, [20000] * 20)
    assert max(map(len, images)) <= BUFFER
    job = mros2_pc.plain_job(publish=[('image', IMAGE, images), ('text', STRING, texts)],
                             subscribe=[('image_back', IMAGE), ('text_back', STRING)],
                             expect={'image_back': 20, 'text_back': 20})
    report, output = _exchange(program, limit, tmp_path, job)
    for topic, sent in (('image_back', images), ('text_back', texts)):
        echoes = report['received'][topic]
        assert echoes == sent, '%s: %d of 20 came back' % (topic, len(set(echoes) & set(sent)))
    assert 'image: 64000 bytes' in output and 'text: 20000 characters' in output


def test_a_sample_at_the_buffers_size_is_taken_one_larger_refused_and_counted(
        board, typestore, tmp_path):
    """64991 characters make a sample of 65000 bytes; 64992, 65001 bytes, which Fast DDS pads
    to 65004 (the next size a String's sample can have)."""
    program, limit = board
    at_size, over = _strings(typestore, [64991, 64992])
    assert (len(at_size), len(over)) == (BUFFER, BUFFER + 4)
    # The refused one first: once the other is back, the board has had both.
    job = mros2_pc.plain_job(publish=[('text', STRING, [over, at_size])],
                             subscribe=[('text_back', STRING)], expect={'text_back': 1})
    report, output = _exchange(program, limit, tmp_path, job)
    assert report['received']['text_back'] == [at_size]
    assert 'text: 64991 characters' in output and 'text: 64992' not in output
    refused = _refused(output)
    assert refused['too_large'] >= 1, output[-2000:]
    assert refused['pool_full'] == refused['inconsistent'] == refused['dropped'] == 0


def test_a_lost_fragment_drops_its_sample_and_the_next_comes_whole(
        board, typestore, tmp_path):
    """The board's network drops the first of every two samples' fragments: every other
    sample loses one, is abandoned when the next begins, and that next one comes whole.
    Which of each two loses one is the run's: an extra datagram to the port shifts it (seen
    once in five runs)."""
    program, limit = board
    texts = _strings(typestore, [20000] * 8)
    fragments = -(-len(texts[0]) // (limit - FRAGMENT_OVERHEAD))
    job = mros2_pc.plain_job(publish=[('text', STRING, texts)], subscribe=[('text_back', STRING)],
                             expect={'text_back': 4})
    report, output = _exchange(program, limit, tmp_path, job, drop_every=2 * fragments)
    # The node publishes them in turn, so every other one loses a fragment: those in odd
    # places, or (should another datagram to the port shift the count) in even ones.
    echoed = set(report['received']['text_back'])
    assert echoed <= set(texts) and echoed
    assert any(texts[index] not in echoed and texts[index + 1] in echoed
               for index in range(len(texts) - 1)), len(echoed)
    refused = _refused(output)
    assert refused['abandoned'] >= 3, output[-2000:]
    assert refused['inconsistent'] == refused['pool_full'] == 0
