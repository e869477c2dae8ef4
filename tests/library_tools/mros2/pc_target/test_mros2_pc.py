# SPDX-License-Identifier: BSD-3-Clause
"""genmros mros2-pc: the user's mros2 and apps, unchanged, on the PC target, against rclpy
nodes of the ROS 2 wheels (Fast DDS 3 with its defaults) on the ROS side of the board's
own network.

The apps are mros2-posix' examples (echoreply_string, pub_twist, sub_pose: taken from
MROS2_POSIX_ROOT's workspace/, with its include/rtps/config.h as the board's config) and
tests/fixtures/mros2_pc_apps. mros2 is MROS2_ROOT (v0.5.4) with only the patches
accept-fast-dds-3-discovery (without which embeddedRTPS discovers no Fast DDS 3
participant) and reader-catches-up-at-once (without which it matches a new node's endpoints
seconds after the node has matched it, and the node's samples are lost meanwhile), or
--hardened; v0.4.1 is mros2-posix' own, where it is assembled. The ROS side is the plain
node (testing/mros2_pc_peer.py): it sends each sample once and expects every reply.
"""

import json
import os
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import time

import pytest

from support.checkout import REPO
from support import mros2_pc_boards
from support.mros2_pc_boards import config_of
from testing import mros2_pc
from testing.mros2_posix import wire_bytes
from support.user_checkouts import MROS2_ROOT

pytestmark = [pytest.mark.needs_mros2, pytest.mark.slow]


DISCOVERY = mros2_pc.TALKING_PATCHES
FIXTURE_APPS = os.path.join(REPO, 'tests', 'fixtures', 'mros2_pc_apps')
STRING = 'std_msgs/msg/String'
SANITIZER_REPORTS = ('AddressSanitizer', 'LeakSanitizer', 'runtime error:')

# The fixtures, shared.
posix_root = mros2_pc_boards.posix_root
typestore = mros2_pc_boards.typestore


@pytest.fixture(scope='module')
def apps(posix_root, tmp_path_factory):
    """A copy of the example apps (their build directories go beside them)."""
    directory = str(tmp_path_factory.mktemp('apps'))
    for name in ('echoreply_string', 'pub_twist', 'sub_pose'):
        shutil.copytree(os.path.join(posix_root, 'workspace', name),
                        os.path.join(directory, name))
    shutil.copytree(os.path.join(FIXTURE_APPS, 'two_publishers'),
                    os.path.join(directory, 'two_publishers'))
    return directory


def strings(typestore, texts):
    message = typestore.types[STRING]
    return [wire_bytes(typestore, message(data=text), STRING) for text in texts]


def echo_job(typestore, texts):
    return mros2_pc.plain_job(publish=[('to_stm', STRING, strings(typestore, texts))],
                              subscribe=[('to_linux', STRING)], expect={'to_linux': len(texts)})


def check_echoes(report, typestore, texts):
    """Every text came back, once, in order."""
    assert report['received']['to_linux'] == strings(typestore, texts)


def run_echo(program, work_dir, typestore, peer_first=False, texts=None):
    """echoreply_string's round trip; returns the board's output."""
    texts = texts or ['hello %d' % index for index in range(5)]
    with mros2_pc.Session(program, work_dir) as session:
        if peer_first:
            peer = session.peer(echo_job(typestore, texts))
            session.start_board()
        else:
            session.start_board()
            assert session.wait_for_output('ready to pub/sub message')
            peer = session.peer(echo_job(typestore, texts))
        report = peer.result()
        output = session.stop_board()
    check_echoes(report, typestore, texts)
    assert "subscribed msg: 'hello" in output
    return output


def test_echoreply_string_on_arm(apps, posix_root, tmp_path, typestore):
    program = mros2_pc.build(os.path.join(apps, 'echoreply_string'), str(tmp_path / 'build'),
                             MROS2_ROOT, config_of(posix_root), patches=DISCOVERY)
    assert program.command[0] == 'qemu-arm'
    output = run_echo(program, str(tmp_path), typestore)
    # Stopped, the program reports each board stack's peak use, with its setting.
    assert re.search(r'ReaderThread +\d+ of +4096 bytes .*THREAD_POOL_READER_STACKSIZE, %s:\d+'
                     % re.escape(config_of(posix_root)), output)


def test_peer_first_then_board(apps, posix_root, tmp_path, typestore):
    program = mros2_pc.build(os.path.join(apps, 'echoreply_string'), str(tmp_path / 'build'),
                             MROS2_ROOT, config_of(posix_root), patches=DISCOVERY,
                             target='native')
    run_echo(program, str(tmp_path), typestore, peer_first=True)


def test_pub_twist(apps, posix_root, tmp_path, typestore):
    program = mros2_pc.build(os.path.join(apps, 'pub_twist'), str(tmp_path / 'build'),
                             MROS2_ROOT, config_of(posix_root), patches=DISCOVERY,
                             target='native')
    job = mros2_pc.plain_job(subscribe=[('cmd_vel', 'geometry_msgs/msg/Twist')],
                             expect={'cmd_vel': 3})
    with mros2_pc.Session(program, str(tmp_path)) as session:
        session.start_board()
        report = session.peer(job).result()
        session.stop_board()
    types = typestore.types
    twists = report['received']['cmd_vel']
    # The app publishes Twist n (every field n) each second; the peer sees a run of them.
    first = re.findall(r'linear: \{x: (\d+)\.0+,', session.output())
    expected = {wire_bytes(typestore, types['geometry_msgs/msg/Twist'](
        linear=types['geometry_msgs/msg/Vector3'](x=n, y=n, z=n),
        angular=types['geometry_msgs/msg/Vector3'](x=n, y=n, z=n)),
        'geometry_msgs/msg/Twist'): n for n in map(float, first)}
    counts = [expected.get(twist) for twist in twists]
    assert None not in counts and len(counts) >= 3
    assert counts == [counts[0] + index for index in range(len(counts))]


def test_sub_pose(apps, posix_root, tmp_path, typestore):
    program = mros2_pc.build(os.path.join(apps, 'sub_pose'), str(tmp_path / 'build'),
                             MROS2_ROOT, config_of(posix_root), patches=DISCOVERY,
                             target='native')
    types = typestore.types
    pose = types['geometry_msgs/msg/Pose'](
        position=types['geometry_msgs/msg/Point'](x=1.5, y=-2.25, z=3.0),
        orientation=types['geometry_msgs/msg/Quaternion'](x=0.0, y=0.5, z=-0.5, w=0.75))
    sample = wire_bytes(typestore, pose, 'geometry_msgs/msg/Pose')
    job = mros2_pc.plain_job(publish=[('cmd_vel', 'geometry_msgs/msg/Pose', [sample])])
    line = ('{ position: {x: 1.500000, y: -2.250000, z: 3.000000 }, orientation: '
            '{x: 0.000000, y: 0.500000, z: -0.500000, w: 0.750000 } }')
    with mros2_pc.Session(program, str(tmp_path)) as session:
        session.start_board()
        peer = session.peer(job)
        assert session.wait_for_output(line), session.output()[-3000:]
        peer.result(stop=True)
        session.stop_board()


def _two_publishers(apps, posix_root, tmp_path, want, **options):
    program = mros2_pc.build(os.path.join(apps, 'two_publishers'), str(tmp_path / 'build'),
                             MROS2_ROOT, config_of(posix_root), target='native', **options)
    job = mros2_pc.plain_job(subscribe=[('first', STRING), ('second', STRING)], expect=want)
    with mros2_pc.Session(program, str(tmp_path)) as session:
        session.start_board()
        report = session.peer(job).result()
        session.stop_board()
    return {topic: {sample[8:].rstrip(b'\0').decode().split(' ')[0] for sample in samples}
            for topic, samples in report['received'].items()}


def test_two_publishers_as_it_is_send_on_the_last_ones_topic(apps, posix_root, tmp_path):
    # mros2 v0.5.4's defect on the real runtime: one writer, the last publisher's; so the
    # fit check (which says so) is off for this build.
    topics = _two_publishers(apps, posix_root, tmp_path, {'second': 8}, patches=DISCOVERY,
                             fit_check=False)
    assert topics == {'first': set(), 'second': {'first', 'second'}}


def test_two_publishers_hardened_each_on_its_own(apps, posix_root, tmp_path):
    topics = _two_publishers(apps, posix_root, tmp_path, {'first': 4, 'second': 4},
                             hardened=True)
    assert topics == {'first': {'first'}, 'second': {'second'}}


def test_a_thread_over_its_stack_is_named(apps, posix_root, tmp_path, typestore):
    with open(config_of(posix_root)) as stream:
        text = stream.read()
    small, count = re.subn(r'THREAD_POOL_READER_STACKSIZE = \d+;',
                           'THREAD_POOL_READER_STACKSIZE = 1024;', text)
    assert count == 1
    config = tmp_path / 'board' / 'rtps' / 'config.h'
    config.parent.mkdir(parents=True)
    config.write_text(small)
    program = mros2_pc.build(os.path.join(apps, 'echoreply_string'), str(tmp_path / 'build'),
                             MROS2_ROOT, str(config), patches=DISCOVERY)
    with mros2_pc.Session(program, str(tmp_path)) as session:
        session.start_board()
        peer = session.peer(echo_job(typestore, ['hello']))
        assert session.wait_for_exit() == 70
        peer.result(stop=True)
    line = [line for line in session.output().splitlines() if 'overflowed' in line]
    assert len(line) == 1
    assert re.fullmatch(r'mros2 PC target: thread ReaderThread overflowed its stack of 1024 '
                        r'bytes \(rtps::Config::THREAD_POOL_READER_STACKSIZE, %s:\d+\); it needs '
                        r'at least \d+ bytes' % re.escape(str(config)), line[0]), line[0]


def test_sanitized_exchange_reports_nothing(apps, posix_root, tmp_path, typestore):
    program = mros2_pc.build(os.path.join(apps, 'echoreply_string'), str(tmp_path / 'build'),
                             MROS2_ROOT, config_of(posix_root), patches=DISCOVERY,
                             target='native', sanitize=True)
    output = run_echo(program, str(tmp_path), typestore)
    assert [word for word in SANITIZER_REPORTS if word in output] == []


def test_mros2_v041_of_mros2_posix(apps, posix_root, tmp_path, typestore):
    root = os.path.join(posix_root, 'mros2')
    if not os.path.isfile(os.path.join(root, 'embeddedRTPS', 'src', 'rtps.cpp')):
        pytest.skip('MROS2_POSIX_ROOT has no mros2 v0.4.1 with its embeddedRTPS (mros2/)')
    program = mros2_pc.build(os.path.join(apps, 'echoreply_string'), str(tmp_path / 'build'),
                             root, config_of(posix_root), patches=DISCOVERY, target='native')
    run_echo(program, str(tmp_path), typestore)


@pytest.mark.parametrize('build', [
    {'patches': DISCOVERY, 'target': 'native', 'sanitize': True},
    {'hardened': True, 'target': 'native', 'sanitize': True}, {'hardened': True}],
    ids=['as-it-is', 'hardened', 'hardened-arm'])
def test_a_sample_over_the_receive_limit(apps, posix_root, tmp_path, typestore, build):
    """The stack cuts the datagram at the limit, as mros2-posix' lwIP does; embeddedRTPS'
    length check then refuses the DATA submessage, which now runs past the datagram, so
    neither build delivers it (the unsized receive of mros2 as it is never sees it), and
    the PC target counts the cut datagrams. The samples that fit go on being echoed. On
    arm the report comes from a host thread: the board's tcpip thread, on its stack of
    1024 bytes, does not overflow."""
    program = mros2_pc.build(os.path.join(apps, 'echoreply_string'), str(tmp_path / 'build'),
                             MROS2_ROOT, config_of(posix_root), receive_limit='1000', **build)
    # The large one first: once the small ones are back, the board has had it.
    texts = ['B' * 2000] + ['small %d' % index for index in range(3)]
    job = echo_job(typestore, texts)
    job['expect'] = {'to_linux': 3}
    with mros2_pc.Session(program, str(tmp_path)) as session:
        session.start_board()
        assert session.wait_for_output('ready to pub/sub message')
        report = session.peer(job).result()
        output = session.stop_board()
    assert report['received']['to_linux'] == strings(typestore, texts[1:])
    assert re.search(r"mros2 PC target: a datagram of \d+ bytes from 192\.168\.11\.2:\d+ was cut "
                     r"to the board's receive limit of 1000 bytes \(1 so far\)", output)
    assert "subscribed msg: 'BBB" not in output and 'overflowed' not in output
    assert [word for word in SANITIZER_REPORTS if word in output] == []


@pytest.mark.parametrize('uid', [None, 65534], ids=['as-root', 'as-nobody'])
def test_the_command_runs_the_board_and_ros_commands_reach_it(posix_root, typestore, uid):
    """genmros mros2-pc as a user runs it (docs/mros2.md's example): the board on its
    network, a ROS 2 command on the ROS side through `genmros mros2-pc-ros --`, Ctrl-C, and
    the host as it was."""
    if uid is not None and (os.geteuid() != 0 or shutil.which('setpriv') is None):
        pytest.skip('runs genmros as another uid: needs root and setpriv')
    before = mros2_pc.host_network()
    with tempfile.TemporaryDirectory() as work:  # pytest's own are root's alone
        app = os.path.join(work, 'echoreply_string')
        shutil.copytree(os.path.join(posix_root, 'workspace', 'echoreply_string'), app)
        as_user = []
        if uid is not None:
            subprocess.run(['chown', '-R', '%d:%d' % (uid, uid), work], check=True)
            as_user = ['setpriv', '--reuid', str(uid), '--regid', str(uid), '--clear-groups']
        env = dict(mros2_pc.peer_environment(work), HOME=work, XDG_RUNTIME_DIR=work,
                   PYTHONPATH=REPO)
        genmros = as_user + [sys.executable, '-m', 'colcon_mros']
        log_path = os.path.join(work, 'genmros.log')
        with open(log_path, 'w') as log:
            board = subprocess.Popen(
                genmros + ['mros2-pc', app, '--rtps-config', config_of(posix_root), '--mros2-root',
                           MROS2_ROOT, '--prefix', mros2_pc.WHEELS_VENV, '--target', 'native',
                           '--hardened', '-j2'],
                stdout=log, stderr=subprocess.STDOUT, env=env)
        try:
            deadline = time.monotonic() + mros2_pc.EVENT_CAP
            while 'ready to pub/sub message' not in open(log_path).read():
                assert board.poll() is None and time.monotonic() < deadline, \
                    open(log_path).read()[-3000:]
                time.sleep(0.05)
            assert ('genmros: the board runs at 192.168.11.3, the ROS side at 192.168.11.2 '
                    '(ROS_DOMAIN_ID=0); from another shell, ROS 2 commands reach it with: '
                    'genmros mros2-pc-ros -- ros2 topic list') in open(log_path).read()
            texts = ['hello %d' % index for index in range(5)]
            peer = subprocess.run(
                genmros + ['mros2-pc-ros', '--',
                           os.path.join(mros2_pc.WHEELS_VENV, 'bin', 'python'),
                           mros2_pc.PEER_SCRIPT], input=json.dumps(echo_job(typestore, texts)),
                capture_output=True, text=True, env=env, timeout=mros2_pc.EVENT_CAP)
            assert peer.returncode == 0, peer.stderr[-3000:]
            report = json.loads(peer.stdout)
            report['received'] = {topic: [bytes.fromhex(sample) for sample in samples]
                                  for topic, samples in report['received'].items()}
            check_echoes(report, typestore, texts)
            # A ROS-side command still running when the board stops is stopped, saying why.
            lingering = subprocess.Popen(
                genmros + ['mros2-pc-ros', '--', 'sh', '-c', 'echo started; exec sleep 600'],
                stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=env)
            assert lingering.stdout.readline() == 'started\n'
            board.send_signal(signal.SIGINT)
            try:
                assert board.wait(timeout=mros2_pc.EVENT_CAP) == 0
            except subprocess.TimeoutExpired:
                pytest.fail('the board did not stop on SIGINT; its log ends:\n%s'
                            % open(log_path).read()[-3000:])
            assert lingering.wait(timeout=mros2_pc.EVENT_CAP) == 128 + signal.SIGTERM
            assert lingering.stderr.read() == 'genmros: the board stopped: stopping sh\n'
        finally:
            if board.poll() is None:
                board.kill()
                board.wait()
        # The state file `genmros mros2-pc-ros` reads goes with the board.
        assert not [name for name in os.listdir(work) if name.startswith('genmros-mros2-pc')]
    assert mros2_pc.host_network() == before


def test_every_stand_in_symbol_is_one_the_link_needs(apps, posix_root, tmp_path):
    """mros2 and an app that publishes and subscribes need every symbol the stand-ins
    define: they stand in for what the link needs and nothing more."""
    program = mros2_pc.build(os.path.join(apps, 'echoreply_string'), str(tmp_path / 'build'),
                             MROS2_ROOT, config_of(posix_root), target='native')
    obj_dir = os.path.join(os.path.dirname(program.path), 'obj')
    board = [os.path.join(obj_dir, name) for name in os.listdir(obj_dir)
             if name.startswith(('lib_', 'app_')) and name.endswith('.o')]
    stand_ins = [os.path.join(obj_dir, name) for name in os.listdir(obj_dir)
                 if name.startswith('pc_') and name.endswith('.o')]
    needed = set(subprocess.run(['nm', '-u'] + board, capture_output=True, text=True,
                                check=True).stdout.split())
    assert mros2_pc.defined_c_symbols(stand_ins) - needed == set()


def test_app_defines_reach_the_apps_sources_alone(apps, posix_root, tmp_path):
    """-D as an app's Filelists.cmake options give it: MROS2_LOG_MIN_SEVERITY 5 (none) takes
    every log line out of the app's code, and mros2's own keeps its lines."""
    build_dir = str(tmp_path / 'build')
    result = subprocess.run(
        [sys.executable, '-m', 'colcon_mros', 'mros2-pc', os.path.join(apps, 'pub_twist'),
         '--rtps-config', config_of(posix_root), '--mros2-root', MROS2_ROOT, '--prefix',
         mros2_pc.WHEELS_VENV, '--target', 'native', '-o', build_dir, '--build-only',
         '-D', 'MROS2_LOG_MIN_SEVERITY=5', '-j2'],
        capture_output=True, text=True, env=dict(os.environ, PYTHONPATH=REPO))
    assert result.returncode == 0, result.stderr[-3000:]
    assert result.stdout.splitlines()[-1] == 'genmros: built %s' % os.path.join(build_dir,
                                                                                'pub_twist')

    def undefined(name):
        return subprocess.run(['nm', '-u', os.path.join(build_dir, 'obj', name)],
                              capture_output=True, text=True, check=True).stdout.split()
    assert 'mros2_pc_log' not in undefined('app_app.o')
    assert 'mros2_pc_log' in undefined('lib_mros2.o')


@pytest.mark.parametrize('hardened', [False, True], ids=['as-it-is', 'hardened'])
def test_echoing_a_long_string_reads_the_message_after_it_is_gone(apps, posix_root, tmp_path,
                                                                  typestore, hardened):
    """mros2 v0.5.4 sends a sample over its 100-byte buffer from the writer thread, through a
    reference to the message: echoreply_string's echo of its callback's message is read after
    the callback freed it. publish-keeps-a-copy (in --hardened) keeps a copy for the writer."""
    patches = {'hardened': True} if hardened else {'patches': DISCOVERY}
    program = mros2_pc.build(os.path.join(apps, 'echoreply_string'), str(tmp_path / 'build'),
                             MROS2_ROOT, config_of(posix_root), target='native', sanitize=True,
                             **patches)
    texts = ['long %d %s' % (index, 'x' * 200) for index in range(3)]
    with mros2_pc.Session(program, str(tmp_path)) as session:
        session.start_board()
        assert session.wait_for_output('ready to pub/sub message')
        peer = session.peer(echo_job(typestore, texts))
        if hardened:
            check_echoes(peer.result(), typestore, texts)
            output = session.stop_board()
            assert [word for word in SANITIZER_REPORTS if word in output] == []
        else:
            assert session.wait_for_output('heap-use-after-free')
            assert session.wait_for_exit() != 0
            peer.result(stop=True)
            assert 'copyToFragBuf' in session.output()


def test_an_unbounded_subscribed_type_is_warned_of_and_arm_builds_without_notes(
        posix_root, tmp_path):
    """The fit check's warning for a uint8[] the board subscribes to, with the fragment
    buffer and queue a size needs, from the build itself; and no note of GCC's on the
    std::vector<double> the app passes (the ABI of GCC 7.1 is no concern of a static build)."""
    build_dir = str(tmp_path / 'build')
    result = subprocess.run(
        [sys.executable, '-m', 'colcon_mros', 'mros2-pc',
         os.path.join(FIXTURE_APPS, 'unbounded'), '--rtps-config', config_of(posix_root),
         '--mros2-root', MROS2_ROOT, '--prefix', mros2_pc.WHEELS_VENV, '--hardened',
         '-o', build_dir, '--build-only', '-j2'],
        capture_output=True, text=True, env=dict(os.environ, PYTHONPATH=REPO))
    assert result.returncode == 0, result.stderr[-3000:]
    assert 'std_msgs/msg/UInt8MultiArray: a sample has no largest size (unbounded)' in \
        result.stderr
    assert re.search(r'genmros: warning: .*config\.h, which sets no FRAGMENT_BUFFER_SIZE .*'
                     r'UInt8MultiArray: .* needs FRAGMENT_BUFFER_SIZE >= S \+ 4 and '
                     r'THREAD_POOL_WORKLOAD_QUEUE_LENGTH >= \(S \+ 4\) / 65324, rounded up: '
                     r'with 0 and 20, up to 0 bytes;', result.stderr), result.stderr
    assert 'note:' not in result.stdout + result.stderr.replace('genmros: note:', '')
