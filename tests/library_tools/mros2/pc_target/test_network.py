# SPDX-License-Identifier: BSD-3-Clause
"""The board's network of genmros mros2-pc: two network namespaces in one user namespace,
made and taken down without root and without touching the host's namespace; unicast
and multicast cross its veth pair; where user namespaces are refused, one line says why
and what to do instead."""

import os
import shutil
import subprocess
import sys
import tempfile

import pytest

from support.checkout import REPO
from testing.mros2_pc import host_network

BOARD_ADDRESS = '192.168.11.3'
# Joins the multicast group DDS discovery uses, binds a port, says so, prints one datagram.
RECEIVER = '''
import socket, struct, sys
receiver = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
receiver.bind(('', 7400))
receiver.setsockopt(socket.IPPROTO_IP, socket.IP_ADD_MEMBERSHIP,
                    struct.pack('4s4s', socket.inet_aton('239.255.0.1'),
                                socket.inet_aton(sys.argv[1])))
print('bound', flush=True)
for _ in range(2):
    data, sender = receiver.recvfrom(100)
    print(data.decode(), sender[0], flush=True)
'''
SENDER = '''
import socket, sys
sender = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
sender.sendto(b'unicast', (sys.argv[1], 7400))
sender.sendto(b'multicast', ('239.255.0.1', 7400))
'''
# The exchange as one program, for another uid: a BoardNetwork, the receiver on the board
# side, the sender on the ROS side.
EXCHANGE = '''
import subprocess, sys
from colcon_mros.library_tools.mros2.pc_target.network import BoardNetwork
with BoardNetwork(%(address)r, 0) as network:
    receiver = subprocess.Popen(network.board_command(
        [sys.executable, '-c', %(receiver)r, network.board_address]), stdout=subprocess.PIPE,
        text=True)
    assert receiver.stdout.readline() == 'bound\\n'
    subprocess.run(network.ros_command([sys.executable, '-c', %(sender)r,
                                        network.board_address]), check=True)
    print(receiver.stdout.read(), end='')
    receiver.wait()
'''


def exchange_program():
    return EXCHANGE % {'address': BOARD_ADDRESS, 'receiver': RECEIVER, 'sender': SENDER}


def check_exchange(output):
    assert output.splitlines() == ['unicast 192.168.11.2', 'multicast 192.168.11.2']


def test_datagrams_cross_and_the_host_namespace_stays_as_it_was():
    before = host_network()
    result = subprocess.run([sys.executable, '-c', exchange_program()], capture_output=True,
                            text=True, env=dict(os.environ, PYTHONPATH=REPO), timeout=120)
    assert result.returncode == 0, result.stderr
    check_exchange(result.stdout)
    assert host_network() == before


@pytest.mark.skipif(os.geteuid() != 0 or shutil.which('setpriv') is None,
                    reason='runs the exchange as another uid: needs root and setpriv')
def test_without_root():
    before = host_network()
    with tempfile.TemporaryDirectory() as home:  # pytest's own are root's alone
        os.chown(home, 65534, 65534)
        result = subprocess.run(
            ['setpriv', '--reuid', '65534', '--regid', '65534', '--clear-groups',
             '/usr/bin/env', 'HOME=%s' % home, 'XDG_RUNTIME_DIR=%s' % home,
             'PYTHONPATH=%s' % REPO, sys.executable, '-c', exchange_program()],
            capture_output=True, text=True, timeout=120)
    assert result.returncode == 0, result.stderr
    check_exchange(result.stdout)
    assert host_network() == before


def test_no_user_namespace_one_line():
    """A user namespace that may make no more of them stands in for a machine that
    refuses them (a container's seccomp, AppArmor's restriction)."""
    program = ('from colcon_mros.errors import GenmrosError\n'
               'from colcon_mros.library_tools.mros2.pc_target.network import BoardNetwork\n'
               'try:\n'
               '    BoardNetwork(%r, 0).__enter__()\n'
               'except GenmrosError as error:\n'
               '    print(error)\n' % BOARD_ADDRESS)
    result = subprocess.run(
        ['unshare', '--user', '--map-root-user', 'sh', '-c',
         'echo 0 > /proc/sys/user/max_user_namespaces && exec "$@"', 'sh',
         sys.executable, '-c', program],
        capture_output=True, text=True, env=dict(os.environ, PYTHONPATH=REPO), timeout=60)
    assert result.returncode == 0, result.stderr
    assert result.stdout.splitlines() == [
        "cannot make the board's network: unshare --user --net failed (unshare failed: No "
        'space left on device): user.max_user_namespaces is 0, so this machine gives no '
        'namespace without root. Run genmros mros2-pc as root, or run the app on mros2-posix '
        '(docs/mros2.md)']
