# SPDX-License-Identifier: BSD-3-Clause
"""A real DDS peer for the mros2 tests: a Fast DDS participant
(dds_raw_peer.cpp beside this file, built with Debian's libfastrtps-dev) that
stands for the ROS 2 side, as Fast DDS is the peer mros2 is tested with.

It only moves bytes: a sample is a message's serialized form as it travels in
an RTPS DATA submessage (the CDR encapsulation header 00 01 00 00, then the
CDR body), sent or received on the topic and type names given as ROS 2 spells
them (``rt/chatter``, ``std_msgs::msg::dds_::String_``). Whether the bytes
are right is the tests' job.

- :func:`build`: compiles the program once into a directory.
- :func:`receiver`: a receiving participant for the length of a ``with``
  block; its :meth:`Receiver.samples` waits for the samples it was started
  for and raises :class:`PeerError` (an AssertionError, with the peer's
  log) if they do not come in time.
- :func:`echoer`: as :func:`receiver`, and each sample is written back
  on a reply topic (a ROS 2 node that answers).
- :func:`send`: a sending participant that writes samples once a reader
  matched, waits until they are acknowledged and exits.
- :func:`free_domain_id`: a DDS domain for one test, so parallel runs do not
  meet.

The endpoints are reliable and transient-local unless reliability
('best-effort') and durability ('volatile') say otherwise. A reader matches
only writers that offer as much, and mros2's endpoints (embeddedRTPS) are
best-effort and announce no durability (so volatile): a receiver of an
mros2 publisher needs reliability='best-effort', durability='volatile'
(Fast DDS logs "INCOMPATIBLE QOS" otherwise). With a best-effort reader,
send does not learn whether the samples arrived.

Both sides use UDPv4 on 127.0.0.1 only (no shared memory, no multicast):
a participant announces itself by unicast to the domain's well-known
discovery ports of the first participant ids on 127.0.0.1 and listens on
its own there. Every process runs in its own process group and is killed on
leaving, also when the code using it fails. Only the standard library is
used.
"""

import itertools
import os
import signal
import socket
import subprocess
import threading
import time

from testing.ros_paths import DEBIAN_PREFIX, ros2_include_prefix

SOURCE = os.path.join(os.path.dirname(os.path.abspath(__file__)), 'dds_raw_peer.cpp')
# How long discovery and delivery may take on a loaded machine.
DELIVERY_TIMEOUT = 30
# What would change the peer's settings: Fast DDS' XML profiles (also read
# from the working directory, the build directory here) and builtin
# transports, and ROS_DOMAIN_ID (the domain is always given).
_PROFILE_VARIABLES = ('FASTRTPS_DEFAULT_PROFILES_FILE', 'FASTDDS_DEFAULT_PROFILES_FILE',
                      'FASTDDS_BUILTIN_TRANSPORTS', 'ROS_DOMAIN_ID')
_domain_calls = itertools.count()


class PeerError(AssertionError):
    """The peer did not receive, or have acknowledged, what it was to in time,
    or it failed."""


def build(out_dir):
    """dds_raw_peer compiled into out_dir (once: an existing program newer
    than the source is kept); its path. Raises RuntimeError with the
    compiler's output if the build fails."""
    os.makedirs(out_dir, exist_ok=True)
    program = os.path.join(out_dir, 'dds_raw_peer')
    if os.path.exists(program) and os.path.getmtime(program) >= os.path.getmtime(SOURCE):
        return program
    partial = '%s.%d' % (program, os.getpid())
    # Fast DDS where the ROS 2 prefixes have it; Debian's is the compiler's default.
    prefix = ros2_include_prefix('fastdds')
    paths = ([] if prefix in (None, DEBIAN_PREFIX)
             else ['-I' + os.path.join(prefix, 'include'), '-L' + os.path.join(prefix, 'lib'),
                   '-Wl,-rpath,' + os.path.join(prefix, 'lib')])
    argv = ['g++', '-std=c++14', '-O1', '-Wall', '-Wextra', '-o', partial, SOURCE] + paths + [
        '-lfastrtps', '-lfastcdr']
    result = subprocess.run(argv, capture_output=True, text=True)
    if result.returncode != 0:
        raise RuntimeError('%s failed:\n%s' % (' '.join(argv), result.stderr[-6000:]))
    os.replace(partial, program)
    return program


def _domain_in_use(domain):
    """Whether a participant on 127.0.0.1 has one of the domain's first
    discovery ports (RTPS' well-known ports: 7400 + 250 * domain + 10 +
    2 * participant id)."""
    for participant in range(4):
        with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as probe:
            try:
                probe.bind(('127.0.0.1', 7410 + 250 * domain + 2 * participant))
            except OSError:
                return True
    return False


def free_domain_id():
    """A DDS domain id in 1..200 for one test, another on each call: from the
    process id (spread, so that parallel test processes with near ids start
    far apart), skipping domains whose discovery ports are taken on
    127.0.0.1. Domain 0, the one ROS 2 uses by default, is never chosen."""
    start = os.getpid() * 37
    for _ in range(200):
        domain = 1 + (start + next(_domain_calls)) % 200
        if not _domain_in_use(domain):
            return domain
    return domain


def _environment():
    env = dict(os.environ, SKIP_DEFAULT_XML='1')
    for name in _PROFILE_VARIABLES:
        env.pop(name, None)
    return env


def _argv(program, mode, topic, type_name, domain, timeout, qos):
    argv = [program, mode, '--topic', topic, '--type', type_name, '--domain', str(domain),
            '--timeout-ms', str(int(timeout * 1000))]
    for name in ('reliability', 'durability'):
        if qos.get(name):
            argv += ['--' + name, qos[name]]
    return argv


def _kill(popen):
    if popen.poll() is not None:
        return
    try:
        os.killpg(popen.pid, signal.SIGKILL)
    except ProcessLookupError:
        pass
    popen.wait()


def encode(samples):
    """Samples (bytes) as dds_raw_peer send reads them: a hex line each."""
    return ''.join(bytes(sample).hex() + '\n' for sample in samples)


class Receiver:
    """A running `dds_raw_peer receive` (or echo): its samples and its log."""

    def __init__(self, program, topic, type_name, count, domain, timeout, reply=None, **qos):
        self.description = '%s (%s) in domain %d' % (topic, type_name, domain)
        self.count = count
        self._stdout = []
        self._stderr = []
        self._changed = threading.Condition()
        argv = _argv(program, 'echo' if reply else 'receive', topic, type_name, domain, timeout,
                     qos) + ['--count', str(count)]
        if reply:
            argv += ['--reply-topic', reply[0], '--reply-type', reply[1]]
            self.description += ', echoing on %s (%s)' % reply
        self.popen = subprocess.Popen(argv, env=_environment(), cwd=os.path.dirname(program),
                                      stdin=subprocess.DEVNULL, stdout=subprocess.PIPE,
                                      stderr=subprocess.PIPE, start_new_session=True)
        self._readers = [threading.Thread(target=self._read, args=(stream, lines), daemon=True)
                         for stream, lines in ((self.popen.stdout, self._stdout),
                                               (self.popen.stderr, self._stderr))]
        for reader in self._readers:
            reader.start()

    def _read(self, stream, lines):
        for raw in stream:
            with self._changed:
                lines.append(raw.decode(errors='replace').rstrip('\n'))
                self._changed.notify_all()
        with self._changed:
            lines.append(None)
            self._changed.notify_all()

    def log(self):
        """What the peer wrote to stderr so far (its own lines and Fast DDS')."""
        with self._changed:
            return '\n'.join(line for line in self._stderr if line is not None)

    def _wait(self, done, timeout, what):
        deadline = time.monotonic() + timeout
        with self._changed:
            while not done():
                remaining = deadline - time.monotonic()
                if remaining <= 0 or None in self._stdout:
                    self.popen.poll()
                    raise PeerError('dds_raw_peer receiving %s: %s within %.0f s '
                                    '(exit status %s); received %d sample(s); log:\n%s'
                                    % (self.description, what, timeout, self.popen.returncode,
                                       len(self._received()), self.log()))
                self._changed.wait(min(remaining, 0.1))

    def _received(self):
        return [bytes.fromhex(line) for line in self._stdout if line]

    def wait_until_ready(self, timeout=DELIVERY_TIMEOUT):
        """Waits until the reader exists (so a sender may start)."""
        self._wait(lambda: 'ready' in self._stderr, timeout, 'no reader')

    def wait_for_log(self, text, timeout=DELIVERY_TIMEOUT):
        """Waits until the peer's log holds text (Fast DDS logs as discovery
        goes on, not when a sample is due)."""
        self._wait(lambda: any(text in line for line in self._stderr if line), timeout,
                   "no '%s' in its log" % text)

    def samples(self, timeout=DELIVERY_TIMEOUT):
        """The `count` samples received, as bytes, in order; raises
        PeerError if they have not all come within timeout seconds."""
        self._wait(lambda: len(self._received()) >= self.count, timeout,
                   'not %d sample(s)' % self.count)
        with self._changed:
            return self._received()[:self.count]

    def stop(self):
        _kill(self.popen)
        for reader in self._readers:
            reader.join(2)


class _Receiving:
    def __init__(self, *arguments, **keywords):
        self._arguments = arguments
        self._keywords = keywords
        self.receiver = None

    def __enter__(self):
        self.receiver = Receiver(*self._arguments, **self._keywords)
        try:
            self.receiver.wait_until_ready()
        except BaseException:
            self.receiver.stop()
            raise
        return self.receiver

    def __exit__(self, *exc_info):
        self.receiver.stop()


def receiver(program, topic, type_name, count, domain, timeout=600, reliability=None,
             durability=None):
    """A context manager: `dds_raw_peer receive` for `count` samples on
    topic/type_name in domain, started and its reader created on entry,
    killed on exit. It yields the :class:`Receiver`. timeout bounds the
    process's own life; Receiver.samples takes the timeout a test waits."""
    return _Receiving(program, topic, type_name, count, domain, timeout,
                      reliability=reliability, durability=durability)


def echoer(program, topic, type_name, reply_topic, count, domain, reply_type=None, timeout=600,
           reliability=None, durability=None):
    """As :func:`receiver`, with `dds_raw_peer echo`: each sample received is
    also written back unchanged on reply_topic (of reply_type, default
    type_name). The process exits once a reader of the reply acknowledged
    all `count`; Receiver.samples gives what it received."""
    return _Receiving(program, topic, type_name, count, domain, timeout,
                      reply=(reply_topic, reply_type or type_name), reliability=reliability,
                      durability=durability)


def send(program, topic, type_name, samples, domain, timeout=DELIVERY_TIMEOUT, reliability=None,
         durability=None):
    """Runs `dds_raw_peer send`: samples (bytes each, header included) are
    written on topic/type_name in domain once a reader matched. Returns when
    every sample is acknowledged; raises PeerError with the peer's log if
    no reader matched or acknowledged them within timeout seconds."""
    samples = list(samples)
    argv = _argv(program, 'send', topic, type_name, domain, timeout,
                 {'reliability': reliability, 'durability': durability})
    popen = subprocess.Popen(argv, env=_environment(), cwd=os.path.dirname(program),
                             stdin=subprocess.PIPE, stdout=subprocess.PIPE,
                             stderr=subprocess.PIPE, start_new_session=True)
    try:
        stdout, stderr = popen.communicate(encode(samples).encode(), timeout=timeout + 10)
    except subprocess.TimeoutExpired:
        _kill(popen)
        raise PeerError('dds_raw_peer sending on %s (%s) in domain %d did not exit within %.0f s'
                        % (topic, type_name, domain, timeout + 10))
    finally:
        _kill(popen)
    if popen.returncode != 0 or stdout.decode().split() != ['sent', str(len(samples))]:
        raise PeerError('dds_raw_peer sending %d sample(s) on %s (%s) in domain %d: exit status '
                        '%d, output %r; log:\n%s'
                        % (len(samples), topic, type_name, domain, popen.returncode,
                           stdout.decode(), stderr.decode(errors='replace')))
