# SPDX-License-Identifier: BSD-3-Clause
"""The board's network on this PC, without root: one user namespace that
holds two network namespaces joined by a veth pair.

The board side has the board's address (mros2-posix': 192.168.11.3/24),
the ROS side the peer's (.2 in the same /24); each routes multicast
(224.0.0.0/4) over the veth, so that DDS discovery reaches across. Two
namespaces are needed: in one, embeddedRTPS (which always takes participant
0's ports, 7410/7411 on domain 0) and Fast DDS (which binds its unicast
ports on 0.0.0.0 without SO_REUSEADDR) would collide, and embeddedRTPS
keeps only peer locators in its interface's subnet. ROS 2 nodes in the
machine's own network namespace are not reached.

:class:`BoardNetwork` sets the arrangement up and takes it down (the host
namespace is never touched); it writes where its ROS side is to a state
file that ``genmros mros2-pc-ros -- CMD`` (:func:`run_ros_side`) reads.
"""

import ipaddress
import json
import os
import select
import shutil
import signal
import subprocess
import sys
import tempfile

from colcon_mros.errors import GenmrosError

PREFIX_LENGTH = 24
# Seconds a ROS-side command has to end once asked to, when its board has stopped.
STOP_WAIT = 10
MULTICAST = '224.0.0.0/4'
BOARD_LINK, ROS_LINK = 'mros2-board', 'mros2-ros'
# A process that holds a namespace until its stdin closes; it says when
# it is in place.
_HOLDER = ['sh', '-c', 'echo ready; read done']
_REFUSED = (
    "cannot make the board's network: %s failed (%s): %s, so this machine gives no namespace "
    'without root. Run genmros mros2-pc as root, or run the app on mros2-posix '
    '(docs/mros2.md)')


def state_file():
    """Where a running board's network says where its ROS side is."""
    directory = os.environ.get('XDG_RUNTIME_DIR') or tempfile.gettempdir()
    return os.path.join(directory, 'genmros-mros2-pc-%d.json' % os.getuid())


def _why_refused():
    """What on this machine refuses an unprivileged user namespace, as far as it says."""
    for path, value, cause in (
            ('/proc/sys/kernel/unprivileged_userns_clone', '0',
             'kernel.unprivileged_userns_clone is 0'),
            ('/proc/sys/kernel/apparmor_restrict_unprivileged_userns', '1',
             "AppArmor's kernel.apparmor_restrict_unprivileged_userns is 1"),
            ('/proc/sys/user/max_user_namespaces', '0', 'user.max_user_namespaces is 0')):
        try:
            with open(path) as stream:
                if stream.read().strip() == value:
                    return cause
        except OSError:
            continue
    return "likely a container's seccomp profile"


def peer_address(board_address):
    """The ROS side's address: the board's /24 with .2, or .3 where the board is .2."""
    network = ipaddress.ip_network('%s/%d' % (board_address, PREFIX_LENGTH), strict=False)
    hosts = [host for host in list(network.hosts())[1:3] if str(host) != board_address]
    return str(hosts[0])


def _inside(pid):
    """The command prefix that runs a command in process pid's user and network namespaces."""
    return ['nsenter', '--target', str(pid), '--user', '--net', '--preserve-credentials', '--']


class BoardNetwork:
    """The two namespaces, their veth pair and addresses; a context manager."""

    def __init__(self, board_address, domain_id):
        self.board_address = board_address
        self.ros_address = peer_address(board_address)
        self.domain_id = domain_id
        self._holders = []

    def _hold(self, command, what):
        holder = subprocess.Popen(command + _HOLDER, stdin=subprocess.PIPE,
                                  stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        if holder.stdout.readline().strip() != 'ready':
            error = holder.stderr.read().strip()
            holder.wait()
            reason = error.splitlines()[-1] if error else 'exit %d' % holder.returncode
            raise GenmrosError(_REFUSED % (what, reason.replace('unshare: ', ''),
                                           _why_refused()))
        self._holders.append(holder)
        return holder.pid

    def _ip(self, pid, *arguments):
        result = subprocess.run(_inside(pid) + ['ip'] + list(arguments), capture_output=True,
                                text=True)
        if result.returncode != 0:
            raise GenmrosError("cannot make the board's network: ip %s: %s"
                               % (' '.join(arguments), result.stderr.strip()))

    def __enter__(self):
        for tool in ('unshare', 'nsenter', 'ip'):
            if shutil.which(tool) is None:
                raise GenmrosError('%s not found: install %s' % (
                    tool, 'iproute2' if tool == 'ip' else 'util-linux'))
        try:
            self.ros_pid = self._hold(['unshare', '--user', '--map-root-user', '--net', '--'],
                                      'unshare --user --net')
            self.board_pid = self._hold(_inside(self.ros_pid) + ['unshare', '--net', '--'],
                                        'unshare --net')
            self._ip(self.ros_pid, 'link', 'add', ROS_LINK, 'type', 'veth', 'peer', 'name',
                     BOARD_LINK, 'netns', str(self.board_pid))
            for pid, link, address in ((self.ros_pid, ROS_LINK, self.ros_address),
                                       (self.board_pid, BOARD_LINK, self.board_address)):
                self._ip(pid, 'link', 'set', 'lo', 'up')
                self._ip(pid, 'addr', 'add', '%s/%d' % (address, PREFIX_LENGTH), 'dev', link)
                self._ip(pid, 'link', 'set', link, 'up')
                self._ip(pid, 'route', 'add', MULTICAST, 'dev', link)
            with open(state_file(), 'w') as stream:
                json.dump({'ros_pid': self.ros_pid, 'domain_id': self.domain_id,
                           'board_address': self.board_address,
                           'ros_address': self.ros_address}, stream)
        except BaseException:
            self.__exit__()
            raise
        return self

    def board_command(self, command):
        """command, run on the board side."""
        return _inside(self.board_pid) + list(command)

    def ros_command(self, command):
        """command, run on the ROS side with ROS_DOMAIN_ID the board's."""
        return _inside(self.ros_pid) + ['env', 'ROS_DOMAIN_ID=%d' % self.domain_id] + \
            list(command)

    def __exit__(self, *exception):
        """Ends the holders: the namespaces, and the veth pair with them, go."""
        try:
            os.unlink(state_file())
        except OSError:
            pass
        for holder in reversed(self._holders):
            holder.stdin.close()
            holder.wait()
            holder.stdout.close()
            holder.stderr.close()
        self._holders = []


def _running_board():
    """The state of the board this user runs now, and a pidfd of the process that holds
    its ROS side's namespace (it ends when the board's network goes)."""
    try:
        with open(state_file()) as stream:
            state = json.load(stream)
    except (OSError, ValueError):
        raise GenmrosError('no board runs (no %s): start one with genmros mros2-pc APP_DIR'
                           % state_file())
    try:
        return state, os.pidfd_open(state['ros_pid'])
    except ProcessLookupError:
        raise GenmrosError('the board that wrote %s has stopped: start one with genmros '
                           'mros2-pc APP_DIR' % state_file())


def run_ros_side(command):
    """Runs command on the ROS side of the board this user runs now, until it ends or the
    board stops (then it is stopped, with one line saying why: on its own it would go on in
    a namespace that nothing else is in); returns its exit status."""
    state, network_gone = _running_board()
    child = subprocess.Popen(_inside(state['ros_pid']) +
                             ['env', 'ROS_DOMAIN_ID=%d' % state['domain_id']] + list(command))
    child_done = os.pidfd_open(child.pid)
    try:
        while True:
            try:
                ready, _, _ = select.select([network_gone, child_done], [], [])
                break
            except KeyboardInterrupt:  # Ctrl-C reached the command too: wait for it
                continue
        if child_done not in ready:
            print('genmros: the board stopped: stopping %s' % command[0], file=sys.stderr,
                  flush=True)
            child.terminate()
            try:
                child.wait(timeout=STOP_WAIT)
            except subprocess.TimeoutExpired:
                child.kill()
        status = child.wait()
        # A command ended by a signal ends genmros as a shell reports it: 128 + the signal.
        return status if status >= 0 else 128 - status
    finally:
        os.close(network_gone)
        os.close(child_done)


def run_board(program):
    """Runs a Mros2Program on the board side of a BoardNetwork until it
    ends or is stopped (Ctrl-C, SIGTERM); returns its exit status."""
    with BoardNetwork(program.board_address, program.domain_id) as network:
        print('genmros: the board runs at %s, the ROS side at %s (ROS_DOMAIN_ID=%d); from '
              'another shell, ROS 2 commands reach it with: genmros mros2-pc-ros -- ros2 topic '
              'list' % (network.board_address, network.ros_address, network.domain_id),
              flush=True)
        board = subprocess.Popen(network.board_command(program.command))
        stop = signal.signal(signal.SIGTERM, lambda *_: board.send_signal(signal.SIGTERM))
        try:
            while True:
                try:
                    status = board.wait()
                    break
                except KeyboardInterrupt:  # Ctrl-C: the board reports its stacks and ends
                    board.send_signal(signal.SIGINT)
        finally:
            signal.signal(signal.SIGTERM, stop)
        sys.stdout.flush()
        return status
