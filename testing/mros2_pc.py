# SPDX-License-Identifier: BSD-3-Clause
"""genmros mros2-pc programs, run for the tests, the main job and the bench.

:func:`build` builds an app with the user's mros2 through genmros' own build
(:mod:`colcon_mros.library_tools.mros2.pc_target.build`); a :class:`Session` holds the
board's network (:class:`~colcon_mros.library_tools.mros2.pc_target.network.BoardNetwork`),
runs the program on its board side with its output in a log, and the plain node
(testing/mros2_pc_peer.py, in the ROS 2 wheels' venv, with a :func:`plain_job`) on its ROS
side. Waits are for events (a line in the board's log, the peer's "peer ready", the graph's
matching), each with a cap that only a broken run reaches.
"""

import json
import os
import signal
import subprocess
import time

from colcon_mros.library_tools.mros2.pc_target.build import Mros2PcBuild
from colcon_mros.library_tools.mros2.pc_target.build import build as build_program
from colcon_mros.library_tools.mros2.pc_target.network import BoardNetwork
from colcon_mros.mros2.render import peer_profile
from colcon_mros.mros2.rules import PEER_RECEIVE_BUFFER
from testing.ros_paths import ros2_wheels

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
WHEELS_VENV = ros2_wheels()
PEER_SCRIPT = os.path.join(REPO, 'testing', 'mros2_pc_peer.py')
GRAPH_SCRIPT = os.path.join(REPO, 'testing', 'mros2_pc_graph.py')
SERVICES_SCRIPT = os.path.join(REPO, 'testing', 'mros2_pc_services.py')
# What a run waits for at most: discovery through embeddedRTPS' SEDP, whose heartbeat
# comes every 4 s, under qemu on a busy 2-core machine.
EVENT_CAP = 180
# What mros2 as it is needs of genmros' series to exchange with ROS 2 nodes at all: without
# the first it discovers no participant of Fast DDS 3 or 2.14 (Kilted's, Jazzy's); without
# the second it matches a node that starts after it seconds after the node matched it, and
# the samples of that time are lost.
TALKING_PATCHES = ('accept-fast-dds-3-discovery', 'reader-catches-up-at-once')
# The plain node's procedure, what an ordinary ROS 2 node does: once the graph shows every
# endpoint matched, it waits SETTLE seconds, publishes each sample once, PERIOD seconds
# apart, then waits up to REPLY_WAIT seconds for the replies.
SETTLE = 3.0
PERIOD = 0.1
REPLY_WAIT = 30.0


def plain_job(publish=(), subscribe=(), expect=None, period=PERIOD, settle=SETTLE,
              reply_wait=REPLY_WAIT, match_wait=EVENT_CAP, qos=None):
    """The plain node's job: publish, [(topic, type, [serialized samples])]; subscribe,
    [(topic, type)]; expect, {topic: count} (its wait for replies ends once they came);
    match_wait, its cap on the wait for matching; qos, {topic: the plain node's QoS name}
    (best_effort where a topic is not named)."""
    qos = qos or {}
    return {'publish': [{'topic': topic, 'type': type_name,
                         'qos': qos.get(topic, 'best_effort'),
                         'samples': [sample.hex() for sample in samples]}
                        for topic, type_name, samples in publish],
            'subscribe': [{'topic': topic, 'type': type_name,
                           'qos': qos.get(topic, 'best_effort')}
                          for topic, type_name in subscribe],
            'expect': dict(expect or {}), 'period': period, 'settle': settle,
            'reply_wait': reply_wait, 'match_wait': match_wait}


def build(app_dir, build_dir, mros2_root, rtps_config, **options):
    """The Mros2Program of app_dir, built in build_dir (options: Mros2PcBuild's)."""
    options.setdefault('prefixes', [WHEELS_VENV])
    options.setdefault('jobs', 2)
    return build_program(Mros2PcBuild(app_dir=app_dir, rtps_config=rtps_config,
                                      mros2_root=mros2_root, build_dir=build_dir, **options))


def peer_environment(log_dir, max_message=None):
    """rclpy's environment: the wheels' Fast DDS with its defaults, logs in log_dir; with
    max_message, genmros' profile (genmros mros2-peer-profile), which fragments what is
    larger."""
    env = {key: value for key, value in os.environ.items()
           if not key.startswith(('ROS_', 'RMW_', 'FASTRTPS_', 'FASTDDS_', 'AMENT_'))}
    env.update(RMW_IMPLEMENTATION='rmw_fastrtps_cpp', ROS_LOG_DIR=log_dir)
    if max_message:
        profile = os.path.join(log_dir, 'fast_dds_max_message_%d.xml' % max_message)
        with open(profile, 'w') as stream:
            stream.write(peer_profile(max_message, PEER_RECEIVE_BUFFER))
        # Fast DDS 3 reads the first, 2.x the second.
        env.update(FASTDDS_DEFAULT_PROFILES_FILE=profile, FASTRTPS_DEFAULT_PROFILES_FILE=profile)
    return env


class Peer:
    """The plain node (testing/mros2_pc_peer.py), or the service peer
    (testing/mros2_pc_services.py), running on the ROS side."""

    def __init__(self, command, job, log_dir, max_message=None):
        # Files, not pipes: a report larger than a pipe holds would wait for its reader.
        name = os.path.join(log_dir, 'peer-%d' % time.monotonic_ns())
        self._stdout = open(name + '.out', 'w+')
        self._stderr = open(name + '.err', 'w+')
        self._process = subprocess.Popen(command, stdin=subprocess.PIPE, stdout=self._stdout,
                                         stderr=self._stderr, text=True,
                                         env=peer_environment(log_dir, max_message))
        self._process.stdin.write(json.dumps(job))
        self._process.stdin.close()

    def wait_ready(self):
        wait_for(lambda: 'peer ready' in self._errors() or self._process.poll() is not None,
                 'the rclpy peer to start')
        assert self._process.poll() is None, self._errors()[-3000:]

    def running(self):
        return self._process.poll() is None

    def matched(self):
        """Whether the node has seen every endpoint matched."""
        return 'peer matched' in self._errors()

    def _errors(self):
        self._stderr.seek(0)
        return self._stderr.read()

    def result(self, stop=False):
        """Its report once it is done (stop: end it now): received, {topic: [samples]};
        sent; matched, whether the graph showed every endpoint matched; matched_after."""
        if stop:
            self._process.send_signal(signal.SIGTERM)
        status = self._process.wait(timeout=EVENT_CAP)
        if status != 0:
            raise AssertionError('the rclpy peer failed (%d): %s' % (status,
                                                                     self._errors()[-3000:]))
        self._stdout.seek(0)
        report = json.loads(self._stdout.read())
        if 'received' in report:
            report['received'] = {topic: [bytes.fromhex(sample) for sample in samples]
                                  for topic, samples in report['received'].items()}
        return report


class GraphWatcher:
    """The graph watcher (testing/mros2_pc_graph.py) running on the ROS side."""

    def __init__(self, command, job, log_dir):
        self._stderr = open(os.path.join(log_dir, 'graph-%d.err' % time.monotonic_ns()), 'w+')
        self._process = subprocess.Popen(command, stdin=subprocess.PIPE, stdout=subprocess.PIPE,
                                         stderr=self._stderr, text=True,
                                         env=peer_environment(log_dir))
        self._process.stdin.write(json.dumps(job) + '\n')
        self._process.stdin.flush()

    def _report(self):
        line = self._process.stdout.readline()
        if not line:
            self._stderr.seek(0)
            raise AssertionError('the graph watcher failed: %s' % self._stderr.read()[-3000:])
        return json.loads(line)

    def seen(self):
        """What the graph showed once the node and its endpoints were in it (or the wait
        ended): nodes, publishers, subscribers (as rclpy gives them), seen_after."""
        return self._report()

    def gone(self):
        """Once the board has stopped: the seconds until the node left the graph (None: it
        stayed for the watcher's wait)."""
        self._process.stdin.write('stopped\n')
        self._process.stdin.close()
        report = self._report()
        assert self._process.wait(timeout=EVENT_CAP) == 0
        return report['gone_after']

    def stop(self):
        """Ends the watcher without waiting for the node to leave."""
        self._process.terminate()
        self._process.wait(timeout=EVENT_CAP)


def wait_for(condition, what):
    deadline = time.monotonic() + EVENT_CAP
    while not condition():
        if time.monotonic() > deadline:
            raise AssertionError('waited %d s for %s' % (EVENT_CAP, what))
        time.sleep(0.05)


class Session:
    """A program on a BoardNetwork's board side and peers on its ROS side."""

    def __init__(self, program, work_dir):
        self.program = program
        self.work_dir = work_dir
        self.log_path = os.path.join(work_dir, 'board.log')
        self.network = BoardNetwork(program.board_address, program.domain_id)
        self._board = None
        self.status = None

    def __enter__(self):
        self.network.__enter__()
        return self

    def start_board(self, command=None, job=None, max_message=None):
        """Starts the program on the board side, or command in its place (the control, given
        job as JSON on its stdin, max_message as peer_environment takes it)."""
        self._log = open(self.log_path, 'w')
        self._board = subprocess.Popen(
            self.network.board_command(command or self.program.command),
            stdin=subprocess.PIPE if job is not None else subprocess.DEVNULL, stdout=self._log,
            stderr=subprocess.STDOUT, text=True,
            env=peer_environment(self.work_dir, max_message) if command else None)
        if job is not None:
            self._board.stdin.write(json.dumps(job))
            self._board.stdin.close()

    def output(self):
        with open(self.log_path, errors='replace') as stream:
            return stream.read()

    def wait_for_output(self, text):
        wait_for(lambda: text in self.output() or self._board.poll() is not None,
                 "'%s' in the board's output" % text)
        return text in self.output()

    def stopped(self):
        return self._board.poll() is not None

    def wait_for_exit(self):
        self.status = self._board.wait(timeout=EVENT_CAP)
        return self.status

    def peer(self, job, max_message=None, script=PEER_SCRIPT):
        """A Peer with job on the ROS side, once its endpoints exist (max_message: see
        peer_environment; script: the plain node's, or SERVICES_SCRIPT)."""
        peer = Peer(self.network.ros_command([os.path.join(WHEELS_VENV, 'bin', 'python'),
                                              script]), job, self.work_dir, max_message)
        peer.wait_ready()
        return peer

    def graph_watcher(self, node, publishers, subscribers, wait=EVENT_CAP):
        """A GraphWatcher on the ROS side for node (in '/') with at least so many publishers
        and subscribers."""
        return GraphWatcher(
            self.network.ros_command([os.path.join(WHEELS_VENV, 'bin', 'python'),
                                      GRAPH_SCRIPT]),
            {'node': node, 'namespace': '/', 'publishers': publishers,
             'subscribers': subscribers, 'wait': wait}, self.work_dir)

    def drop_datagrams(self, port, every):
        """The board's network drops every so many datagrams to port, the first included
        (nftables, on the board's side), from now on."""
        rules = ('table ip genmros_drop {\n chain incoming {\n  type filter hook input '
                 'priority 0;\n  udp dport %d numgen inc mod %d 0 drop\n }\n}\n' % (port, every))
        subprocess.run(self.network.board_command(['nft', '-f', '-']), input=rules, text=True,
                       check=True)

    def stop_board(self):
        """Stops the board as Ctrl-C does; returns its output."""
        if self._board is not None and self._board.poll() is None:
            self._board.send_signal(signal.SIGINT)
            self.status = self._board.wait(timeout=EVENT_CAP)
        return self.output()

    def __exit__(self, *exception):
        if self._board is not None:
            if self._board.poll() is None:
                self._board.kill()
                self._board.wait()
            self._log.close()
        self.network.__exit__()


def host_network():
    """The host namespace's addresses, routes and links, as ip -j gives them."""
    return [subprocess.run(['ip', '-j'] + what, capture_output=True, text=True,
                           check=True).stdout
            for what in (['addr'], ['route'], ['link'])]


def defined_c_symbols(objects, nm='nm'):
    """The C symbols the objects define for others (their own C++ is left out)."""
    result = subprocess.run([nm, '-g', '--defined-only'] + objects, capture_output=True,
                            text=True, check=True)
    return {fields[2] for fields in (line.split() for line in result.stdout.splitlines())
            if len(fields) == 3 and fields[1] in 'TDBRV' and not fields[2].startswith('_Z')
            and not fields[2].startswith('DW.ref.')}
