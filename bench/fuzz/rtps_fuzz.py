#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""Fuzz an mros2 board's RTPS side on the PC target (genmros mros2-pc), on its own network.

    MROS2_ROOT=... MROS2_POSIX_ROOT=... /usr/bin/python3 bench/fuzz/rtps_fuzz.py
        [--seconds 600] [--seed S] [--as-it-is] [--coverage] [--build-dir DIR]
        [--findings DIR] [--replay FILE]

builds mros2-posix' echoreply_string with MROS2_ROOT --hardened (--as-it-is: with
accept-fast-dds-3-discovery and reader-catches-up-at-once alone)
for this PC with --sanitize (AddressSanitizer and
UndefinedBehaviorSanitizer), starts it, and records on the ROS side of its network the
datagrams of a real exchange with an rclpy node (testing/mros2_pc_peer.py), both ways: SPDP,
SEDP, DATA, HEARTBEAT, ACKNACK, INFO_TS, INFO_DST, and DATA_FRAG (the node's Fast DDS sends
no datagram over 1400 bytes, and one string of 3000 characters). That exchange has no GAP:
the mutation of a submessage's kind makes GAPs, HEARTBEAT's body having GAP's layout.
Then it sends the board those datagrams mutated (testing/rtps_datagrams.Mutator: submessage
lengths, counts and kinds, parameter lists, inline QoS (related sample identities, key
hashes, status infos: disposes), names longer than the config's fields, locators,
sequence and fragment numbers, encapsulation headers, truncation, flipped bytes), from the
rclpy participant the board has discovered and, one datagram in four (--unknown-share), from
one it has not; and, one pick in fifty, new samples in DATA_FRAGs in the name of an rclpy
writer the board has matched for the run (Mutator.fragment_sequence: sizes, fragments per
submessage, repeats, overlaps, out of order, interleaved with another sample or writer)
for the patch data-frag-for-best-effort-readers, whose buffers the hardened build's config
sets (FRAGMENT_BUFFER_SIZE 8192, FRAGMENT_BUFFERS 2, added to mros2-posix').
Every 500 datagrams it checks that the board runs and its output holds no sanitizer report;
a finding saves the last 500 datagrams sent (--findings DIR, JSON lines "port hex") and
stops. At the end (after the config's longest lease, 180 s, and a liveliness check, for the
fuzzed participants to leave the board's table) the board must still echo an rclpy node's
strings byte for byte.
--coverage builds with gcov and prints, for the parsers the fuzzer must reach, how often
each ran. --replay FILE sends a finding's datagrams to a fresh board and says whether it
still reports. Exit 0: no finding and the board still echoing; 1: a finding; 3: no finding,
but the board no longer echoes.
"""

import argparse
import collections
import json
import os
import random
import shutil
import subprocess
import sys
import tempfile
import time

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, REPO)  # colcon_mros and the shared testing package
sys.path.append(os.path.join(REPO, 'build', 'test-python'))  # rosbags
from testing import mros2_pc, mros2_soak, rtps_datagrams  # noqa: E402
from testing.mros2_posix import wire_bytes  # noqa: E402

BATCH = 500
# The board's reader queue holds 20 datagrams (THREAD_POOL_WORKLOAD_QUEUE_LENGTH): the sender
# pauses after each 20, so that most reach the parsers instead of being dropped.
PACE = 20
PAUSE_SECONDS = 0.005
# The SPDP port of domain 0, where the board announces itself once a second
# (SPDP_RESEND_PERIOD_MS); it checks its participants' leases every third announcement
# (SPDP_CYCLECOUNT_HEARTBEAT 2): 5 announcements from the replay on hold a check after it,
# in mros2-posix' config.
SPDP_PORT = 7400
LIVELINESS_CHECK_ANNOUNCEMENTS = 5
# SPDP_MAX_REMOTE_LEASE_DURATION of mros2-posix' config.
MAX_REMOTE_LEASE_SECONDS = 180
# gcov, and its dump linked in: the board's stop calls it (a weak reference alone would not
# take it from libgcov).
COVERAGE_FLAGS = ('--coverage', '-Wl,--undefined=__gcov_dump')
SANITIZER_REPORTS = ('AddressSanitizer', 'LeakSanitizer', 'runtime error:', 'Segmentation fault')
# The share of picks that send a sample in DATA_FRAGs, and the fragment buffers the hardened
# board's config gets for them: small enough that samples over them come.
FRAGMENT_SHARE = 0.02
FRAGMENT_SETTINGS = ('const DataSize_t FRAGMENT_BUFFER_SIZE = 8192;\n'
                     'const uint8_t FRAGMENT_BUFFERS = 2;\n')
# The functions the fuzzer must reach, as gcov names them (demangled, prefix matched; of
# two, the hardened board's first: acknacks-on-the-writer-threads takes ACKNACKs on the
# writer threads, after the network thread has sorted each datagram).
PARSERS = (('MessageReceiver: DATA', 'rtps::MessageReceiver::processDataSubmessage'),
           ('MessageReceiver: HEARTBEAT', 'rtps::MessageReceiver::processHeartbeatSubmessage'),
           ('MessageReceiver: ACKNACK', ('rtps::MessageReceiver::processAckNacks',
                                         'rtps::MessageReceiver::processAckNackSubmessage')),
           ('MessageReceiver: ACKNACKs sorted out', 'rtps::MessageReceiver::ackNacksIn'),
           ('StatefulWriter: ACKNACK', 'rtps::StatefulWriterT<rtps::UdpDriver>::onNewAckNack'),
           ('ParticipantProxyData::readFromUcdrBuffer',
            'rtps::ParticipantProxyData::readFromUcdrBuffer'),
           ('TopicData::readFromUcdrBuffer', 'rtps::TopicData::readFromUcdrBuffer'),
           ('SEDP: publications', 'rtps::SEDPAgent::onNewPublisher'),
           ('SEDP: subscriptions', 'rtps::SEDPAgent::onNewSubscriber'),
           ('MessageReceiver: inline QoS', 'rtps::MessageReceiver::readInlineQos'),
           ('SEDP: a dispose heeded', 'rtps::Participant::removeRemoteEndpoint'),
           ('MessageReceiver: DATA_FRAG', 'rtps::MessageReceiver::processDataFragSubmessage'),
           ('MessageReceiver: fragments taken', 'rtps::MessageReceiver::takeFragments'),
           ("mros2's callback", 'void mros2::Subscriber::callback_handler'))


# The recording's rclpy node sends no datagram over this (a Fast DDS profile), so that its
# long string goes out as DATA_FRAG.
RECORDING_MAX_MESSAGE = 1400


def strings(texts):
    """Each text as a std_msgs/String sample on the wire."""
    from rosbags.typesys import Stores, get_typestore
    typestore = get_typestore(Stores.ROS2_HUMBLE)
    string = typestore.types['std_msgs/msg/String']
    return [wire_bytes(typestore, string(data=text), 'std_msgs/msg/String') for text in texts]


def echoes(session, texts, max_message=None, match_wait=mros2_pc.EVENT_CAP):
    """The plain node sends the board each text once: (the samples sent, those echoed)."""
    samples = strings(texts)
    job = mros2_pc.plain_job(publish=[('to_stm', 'std_msgs/msg/String', samples)],
                             subscribe=[('to_linux', 'std_msgs/msg/String')],
                             expect={'to_linux': len(texts)}, match_wait=match_wait)
    peer = session.peer(job, max_message)
    # A board that dies meanwhile (a sanitizer's report) echoes nothing more.
    while peer.running() and not session.stopped():
        time.sleep(0.1)
    return samples, peer.result(stop=session.stopped())['received']['to_linux']


def echoes_exact(session, texts, match_wait=mros2_pc.EVENT_CAP):
    """Whether every text comes back, once, in order."""
    samples, echoed = echoes(session, texts, match_wait=match_wait)
    return echoed == samples


def start_capture(session, path):
    """testing/rtps_datagrams' capture on the ROS side, writing to path, once it listens."""
    capture = subprocess.Popen(session.network.ros_command(
        [sys.executable, '-m', 'testing.rtps_datagrams', 'capture', 'mros2-ros', path]),
        stderr=subprocess.PIPE, text=True, env=dict(os.environ, PYTHONPATH=REPO))
    assert capture.stderr.readline().strip() == 'capturing'
    return capture


def wait_for_announcements(session, path, count):
    """Until the board has sent count SPDP announcements into the capture at path."""
    def announced():
        return sum(1 for entry in rtps_datagrams.read_capture(path)
                   if not entry['to_board'] and entry['port'] == SPDP_PORT) >= count
    mros2_pc.wait_for(lambda: announced() or session.stopped(), 'the board to announce itself')


def record(session, work_dir):
    """The datagrams of an exchange with rclpy, as JSON objects (testing/rtps_datagrams)."""
    path = os.path.join(work_dir, 'recorded.jsonl')
    capture = start_capture(session, path)
    # Strings within mros2's 100-byte buffer: echoreply_string's echo of a longer one reads
    # the callback's message after it is freed (mros2 v0.5.4 sends it later, from the
    # writer thread, through a reference), a finding of its own (docs/mros2.md).
    # The long one (in fragments) is taken only with data-frag-for-best-effort-readers.
    texts = ['record %d %s' % (index, 'x' * (8 * index)) for index in range(11)]
    samples, echoed = echoes(session, ['fragments ' + 'f' * 3000] + texts, RECORDING_MAX_MESSAGE)
    capture.terminate()
    capture.wait()
    # The long one comes back only with the patch; every other one must.
    if [sample for sample in echoed if sample != samples[0]] != samples[1:]:
        raise SystemExit('the board did not echo before fuzzing: see %s' % session.log_path)
    return rtps_datagrams.read_capture(path)


def live_writer(session, work_dir, seconds):
    """An rclpy node that publishes a long string to the board once a second, in DATA_FRAGs,
    for seconds (the writer the board has matched while the fuzzer sends new samples in its
    name), and the datagrams of its first fragmented sample: (peer, datagrams)."""
    path = os.path.join(work_dir, 'live_writer.jsonl')
    capture = start_capture(session, path)
    sample, = strings(['fragments ' + 'f' * 3000])
    job = mros2_pc.plain_job(publish=[('to_stm', 'std_msgs/msg/String', [sample] * int(seconds))],
                             period=1.0, reply_wait=0)
    peer = session.peer(job, RECORDING_MAX_MESSAGE)

    def fragments():
        return [entry for entry in rtps_datagrams.read_capture(path) if entry['to_board'] and
                'DATA_FRAG' in rtps_datagrams.kinds(bytes.fromhex(entry['data']))]
    mros2_pc.wait_for(lambda: fragments() or session.stopped(), 'rclpy to send fragments')
    capture.terminate()
    capture.wait()
    return peer, [(entry['port'], bytes.fromhex(entry['data'])) for entry in fragments()]


def reports(output):
    return [word for word in SANITIZER_REPORTS if word in output]


class Sender:
    """testing/rtps_datagrams' sender on the ROS side."""

    def __init__(self, session):
        self.process = subprocess.Popen(session.network.ros_command(
            [sys.executable, '-m', 'testing.rtps_datagrams', 'send',
             session.program.board_address]), stdin=subprocess.PIPE, stdout=subprocess.PIPE,
            text=True, env=dict(os.environ, PYTHONPATH=REPO))
        self.sent = 0

    def send(self, port, data):
        """Sends one datagram, pausing after each PACE."""
        self.process.stdin.write('%d %s\n' % (port, data.hex()))
        self.sent += 1
        if self.sent % PACE == 0:
            self.process.stdin.flush()
            time.sleep(PAUSE_SECONDS)

    def close(self):
        self.process.stdin.close()
        return self.process.stdout.read().strip()


def fuzz(session, recorded, seconds, seed, findings_dir, unknown_share):
    """Mutated datagrams until seconds pass or a finding; (counts, finding path or None)."""
    mutator = rtps_datagrams.Mutator(seed)
    corpus = [(entry['port'], bytes.fromhex(entry['data'])) for entry in recorded
              if rtps_datagrams.parse(bytes.fromhex(entry['data']))]
    # New samples in fragments go the way of a writer the board has matched for the whole
    # run (the recording's node is gone: its writer is no longer matched).
    writer, fragmented = live_writer(session, os.path.dirname(session.log_path),
                                     seconds + mros2_pc.EVENT_CAP)
    counts = collections.Counter()
    kinds = collections.Counter(kind for _, data in corpus for kind in rtps_datagrams.kinds(data))
    print('recorded: %d datagrams; submessages: %s' % (len(corpus), dict(kinds)), flush=True)
    sent = collections.deque(maxlen=BATCH)
    deadline = time.monotonic() + seconds
    sender = Sender(session)
    finding = None
    while time.monotonic() < deadline and finding is None:
        batch_end = sum(counts.values()) + BATCH
        while sum(counts.values()) < batch_end:
            if fragmented and mutator.random.random() < FRAGMENT_SHARE:
                port, data = mutator.random.choice(fragmented)
                batch = [('fragment_sequence', datagram)
                         for datagram in mutator.fragment_sequence(data)]
            else:
                port, data = mutator.random.choice(corpus)
                batch = [mutator.mutate(data, mutator.random.random() < unknown_share)]
            for name, mutated in batch:
                sender.send(port, mutated)
                sent.append((port, mutated))
                counts[name] += 1
        found = reports(session.output())
        if found or session.stopped():
            if 'AddressSanitizer' in found:
                session.wait_for_exit()  # it ends the board once its report is out
            else:
                session.stop_board()  # UndefinedBehaviorSanitizer goes on after its report
            finding = os.path.join(findings_dir, 'finding-%d-%d.jsonl'
                                   % (seed, sum(counts.values())))
            os.makedirs(findings_dir, exist_ok=True)
            with open(finding, 'w') as stream:
                stream.writelines('%d %s\n' % (port, data.hex()) for port, data in sent)
    print('sender: %s' % sender.close(), flush=True)
    if writer.running():
        writer.result(stop=True)
    return counts, finding


def coverage(program, build_dir):
    """{parser: executions} from the gcov counts a stopped --coverage board wrote."""
    obj_dir = os.path.join(os.path.dirname(program.path), 'obj')
    counts = collections.Counter()
    for name in sorted(os.listdir(obj_dir)):
        if not (name.startswith('lib_') and name.endswith('.gcda')):
            continue
        result = subprocess.run(['gcov', '--json-format', '--stdout', '--demangled-names',
                                 os.path.join(obj_dir, name)], capture_output=True, text=True,
                                cwd=build_dir)
        for line in result.stdout.splitlines():
            for source in json.loads(line)['files']:
                for function in source.get('functions', []):
                    for title, prefix in PARSERS:
                        if function['demangled_name'].startswith(prefix):
                            counts[title] += function['execution_count']
    return counts


def board_config(work, as_it_is):
    """mros2-posix' rtps/config.h; hardened, with FRAGMENT_SETTINGS added and room for
    ros_discovery_info's type name, so that the board publishes it (a copy in work)."""
    posix_root = os.environ['MROS2_POSIX_ROOT']
    if as_it_is:
        return os.path.join(posix_root, 'include', 'rtps', 'config.h')
    return mros2_soak.changed_config(posix_root, work, [
        (r'\}\s*//\s*namespace Config', FRAGMENT_SETTINGS + '} // namespace Config'),
        mros2_soak.LONG_TYPE_NAMES])


def build(options, work):
    app = os.path.join(work, 'echoreply_string')
    if not os.path.isdir(app):
        shutil.copytree(os.path.join(os.environ['MROS2_POSIX_ROOT'], 'workspace',
                                     'echoreply_string'), app)
    patches = {'patches': mros2_pc.TALKING_PATCHES} if options.as_it_is else \
        {'hardened': True}
    return mros2_pc.build(app, os.path.join(work, 'build'), os.environ['MROS2_ROOT'],
                          board_config(work, options.as_it_is), target='native', sanitize=True,
                          extra_flags=COVERAGE_FLAGS if options.coverage else (), **patches)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    parser.add_argument('--seconds', type=float, default=600)
    parser.add_argument('--seed', type=int, default=None)
    parser.add_argument('--as-it-is', action='store_true')
    parser.add_argument('--coverage', action='store_true')
    parser.add_argument('--build-dir')
    parser.add_argument('--findings', default=os.path.join(os.getcwd(), 'rtps_findings'))
    parser.add_argument('--replay')
    parser.add_argument('--unknown-share', type=float, default=0.25,
                        help='the share of datagrams from a participant the board has not '
                             'discovered (default 0.25)')
    options = parser.parse_args()
    if not os.environ.get('MROS2_ROOT') or not os.environ.get('MROS2_POSIX_ROOT'):
        print('rtps_fuzz.py: needs MROS2_ROOT (mros2 v0.5.4) and MROS2_POSIX_ROOT (its example '
              'apps): docs/testing.md', file=sys.stderr)
        return 2
    seed = options.seed if options.seed is not None else random.randrange(1 << 30)
    work = options.build_dir or tempfile.mkdtemp(prefix='rtps_fuzz_')
    program = build(options, work)
    started = time.monotonic()
    with mros2_pc.Session(program, work) as session:
        session.start_board()
        session.wait_for_output('ready to pub/sub message')
        recorded = record(session, work)
        if options.replay:
            announcements = os.path.join(work, 'replay.jsonl')
            capture = start_capture(session, announcements)
            sender = Sender(session)
            with open(options.replay) as stream:
                for line in stream:
                    port, _, data = line.partition(' ')
                    sender.send(int(port), bytes.fromhex(data.strip()))
            print('replayed: %s' % sender.close())
            # An echo after them: the board's reader has been through what it kept.
            echoing = not session.stopped() and echoes_exact(session, ['after replay'])
            # And the liveliness check of the participants it added, which runs on the SPDP
            # writer thread every SPDP_CYCLECOUNT_HEARTBEAT + 1 announcements.
            wait_for_announcements(session, announcements, LIVELINESS_CHECK_ANNOUNCEMENTS)
            capture.terminate()
            capture.wait()
            found = reports(session.output())
            print('the board %s' % ('reports: %s' % found if found else
                                    'reports nothing and echoes' if echoing else
                                    'reports nothing and no longer echoes'))
            return 0 if echoing and not found else 1
        counts, finding = fuzz(session, recorded, options.seconds, seed, options.findings,
                               options.unknown_share)
        # The fuzzed participants in the board's table leave it once their leases end, at
        # most SPDP_MAX_REMOTE_LEASE_DURATION after their last announcement, at the next
        # liveliness check. The echo's node waits for that: until then the board has no
        # place for it, and the node may yet see the board's endpoints (its SEDP writers
        # resend by multicast for a fuzzed participant that acknowledges nothing) and send
        # into nothing.
        if finding is None:
            time.sleep(MAX_REMOTE_LEASE_SECONDS)
            announcements = os.path.join(work, 'after_fuzzing.jsonl')
            capture = start_capture(session, announcements)
            wait_for_announcements(session, announcements, LIVELINESS_CHECK_ANNOUNCEMENTS)
            capture.terminate()
            capture.wait()
        still = finding is None and echoes_exact(
            session, ['after %d' % index for index in range(5)])
        output = session.stop_board()
    print('seed %d, %.0f s, %d datagrams sent: %s'
          % (seed, time.monotonic() - started, sum(counts.values()), dict(counts)))
    if finding:
        print('FINDING: %s; the board said:\n%s' % (finding, output[-3000:]))
    else:
        print('no sanitizer report; the board %s echoing byte for byte afterwards'
              % ('went on' if still else 'STOPPED'))
    if options.coverage:
        hits = coverage(program, work)
        for title, _ in PARSERS:
            print('  %-45s %d' % (title, hits[title]))
    return 1 if finding else 0 if still else 3


if __name__ == '__main__':
    sys.exit(main())
