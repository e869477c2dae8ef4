# SPDX-License-Identifier: BSD-3-Clause
"""The main job's ROS 2 part: mros2 firmware against real rclpy nodes.

1. colcon build --mros-export of test_ws_ros2 with the ROS 2 wheels'
   rosidl (rosidl_default_generators: C, C++, Python; the mros2 generator
   beside them, found through rosidl's generator group): the export dir's
   mros2/ and rclpy's own classes of the same types.
2. evaluation/firmware_ros2 (find_package(genmros), mros2_import_messages()
   on that export and on the wheels' std_msgs, geometry_msgs, sensor_msgs,
   with the fit check on its rtps/config.h) for 32-bit ARM Linux and
   Cortex-M4F, with their sizes.
3. genmros mros2-fit's verdict on the firmware's endpoints (from the board
   itself: board --describe).
4. The ARM program under qemu-arm; evaluation/ros2_bridge.py (rclpy) carries
   its samples to and from the ROS 2 graph unread, and
   evaluation/ros2_peer.py (rclpy) checks them byte for byte.
5. In sync by construction: a field added to Reading.msg reaches the
   firmware's header and rclpy's class with the next colcon and firmware
   builds.
6. With MROS2_POSIX_ROOT (an assembled mros2-posix checkout, as root): the
   real mros2-posix app on genmros' headers against an rclpy node over a
   veth pair (testing/mros2_posix.py), and with MROS2_ROOT (mros2 v0.5.4)
   patched by genmros mros2-harden, its two publishers.

The ROS 2 nodes run in the venv of ROS 2 wheels that testing/ros_paths.py
names (scripts/setup.sh --tests: Kilted's build/ros2-wheels, or the one
GENMROS_ROS2_WHEELS names, such as Jazzy's build/ros2-wheels-jazzy), on Fast
DDS over loopback only, in a DDS domain of their own.
"""

import glob
import os
import re
import shutil
import signal
import subprocess
import time

from board import TARGETS, Failure, run_logged, sizes
from testing import mros2_posix
from testing.dds_peer import free_domain_id
from testing.ros_graph import Process
from testing.ros_paths import ros2_wheels

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(HERE)
WHEELS = ros2_wheels()
TEST_WS_ROS2_SRC = os.path.join(REPO, 'test_ws_ros2', 'src')
FIRMWARE = os.path.join(HERE, 'firmware_ros2')
RTPS_CONFIG = os.path.join(FIRMWARE, 'rtps', 'config.h')
# lwIP's receive limit on mros2-posix (lwip-posix src/core/udp.c: MAX_RECV_PACKET_SIZE).
RECEIVE_LIMIT = 4096
FIRMWARE_TARGETS = [target for target in TARGETS
                    if target.name in ('arm-linux-gnueabihf', 'cortex-m4')]
BRIDGE = os.path.join(HERE, 'ros2_bridge.py')
PEER = os.path.join(HERE, 'ros2_peer.py')
PEER_TIMEOUT = 120
# What the board publishes of each type (board_ros2.cpp, kSamples), and what the peer sends.
SAMPLES = 20
ADDED_FIELD = 'uint32 sequence_number  # added by the main job: the firmware must follow'
TRANSPORT = ("samples carried between qemu-arm and the ROS 2 graph by evaluation/ros2_bridge.py: "
             "an rclpy node that relays the board's bytes unread, under the DDS type names of "
             "the board's genmros headers")


def wheels_found():
    return os.path.isfile(os.path.join(WHEELS, 'bin', 'python'))


class Ros2Workspace:
    """A copy of test_ws_ros2, built with the ROS 2 wheels."""

    def __init__(self, root):
        self.root = root
        self.export_dir = os.path.join(root, 'mros_export')
        shutil.copytree(TEST_WS_ROS2_SRC, os.path.join(root, 'src'))

    def environment(self, domain=None):
        """A ROS 2 user's environment: the wheels, then the workspace's install."""
        installs = sorted(glob.glob(os.path.join(self.root, 'install', '*', '')))
        environment = dict(
            os.environ, PATH='%s/bin:/usr/bin:/bin' % WHEELS,
            AMENT_PREFIX_PATH=':'.join([path.rstrip('/') for path in installs] + [WHEELS, '/usr']),
            CMAKE_PREFIX_PATH=WHEELS, RMW_IMPLEMENTATION='rmw_fastrtps_cpp',
            ROS_AUTOMATIC_DISCOVERY_RANGE='LOCALHOST',
            PYTHONPATH=':'.join(glob.glob(os.path.join(self.root, 'install', '*', 'lib',
                                                       'python3*', 'site-packages'))),
            LD_LIBRARY_PATH=':'.join(os.path.join(path, 'lib') for path in installs))
        if domain is not None:
            environment['ROS_DOMAIN_ID'] = str(domain)
        return environment

    def build(self, log_path):
        run_logged(['colcon', 'build', '--mros-export', self.export_dir], log_path,
                   cwd=self.root, env=self.environment())


def colcon_build(root):
    """Step 1: the workspace, built; (Ros2Workspace, detail)."""
    workspace = Ros2Workspace(root)
    workspace.build(os.path.join(root, 'colcon_build.log'))
    headers = sorted(os.path.relpath(path, os.path.join(workspace.export_dir, 'mros2', 'include'))
                     for path in glob.glob(os.path.join(workspace.export_dir, 'mros2', 'include',
                                                        '*', '*', '*.hpp')))
    python = glob.glob(os.path.join(root, 'install', 'mros2_test_msgs', 'lib', 'python3*',
                                    'site-packages', 'mros2_test_msgs', 'msg', '_reading.py'))
    if 'mros2_test_msgs/msg/reading.hpp' not in headers or not python:
        raise Failure('no mros2 header or no Python class of Reading: see %s'
                      % os.path.join(root, 'colcon_build.log'))
    return workspace, ('export dir %s: %s; rclpy\'s classes of the same types installed'
                       % (workspace.export_dir, ', '.join(headers)))


def build_firmware(workspace, build_dir, target):
    """Step 2: the firmware for target; (program, its sizes)."""
    os.makedirs(os.path.dirname(build_dir), exist_ok=True)
    genmros_dir = subprocess.run(['genmros', 'cmake-dir'], check=True, capture_output=True,
                                 text=True).stdout.strip()
    run_logged(['cmake', '-S', FIRMWARE, '-B', build_dir,
                '-DMROS2_EXPORT_DIR=' + workspace.export_dir, '-DROS2_PREFIX=' + WHEELS,
                '-DBOARD_PORT=' + target.port,
                '-DCMAKE_TOOLCHAIN_FILE=%s/../firmware/toolchains/%s.cmake' % (FIRMWARE,
                                                                               target.name),
                '-Dgenmros_DIR=' + genmros_dir], build_dir + '.configure.log')
    run_logged(['cmake', '--build', build_dir, '-j2'], build_dir + '.build.log')
    program = os.path.join(build_dir, 'board')
    return program, sizes(target, program)


def board_endpoints(program):
    """[(topic, pkg/msg/Type, 'P' or 'S')] as the firmware's headers give them."""
    output = subprocess.run(['qemu-arm', program, '--describe'], check=True,
                            capture_output=True, text=True).stdout
    endpoints = []
    for line in output.splitlines():
        topic, dds_type_name, _, role = line.split(' ')
        package, kind, _, name = dds_type_name.split('::')
        endpoints.append((topic, '%s/%s/%s' % (package, kind, name[:-1]), role))
    return endpoints


def fit_verdict(workspace, program):
    """Step 3: genmros mros2-fit on the board's endpoints; (report, detail)."""
    arguments = ['genmros', 'mros2-fit', '--prefix', os.path.join(workspace.export_dir, 'mros2'),
                 '--prefix', WHEELS, '--rtps-config', RTPS_CONFIG,
                 '--receive-limit', str(RECEIVE_LIMIT)]
    endpoints = board_endpoints(program)
    for topic, type_name, role in endpoints:
        arguments += ['--publish' if role == 'P' else '--subscribe', '%s:%s' % (topic, type_name)]
    result = subprocess.run(arguments, capture_output=True, text=True)
    if result.returncode != 0 or 'Every endpoint fits.' not in result.stdout:
        raise Failure('genmros mros2-fit: %s' % ' | '.join(
            line for line in (result.stdout + result.stderr).splitlines()
            if line.startswith(('error', 'genmros')))[:600])
    settings = re.search(r'^Settings \(rtps/config.h\): (.*)$', result.stdout, re.M).group(1)
    return result.stdout, ('every one of the %d endpoints fits: %s; receive limit %d'
                           % (len(endpoints), settings, RECEIVE_LIMIT))


def exchange(workspace, program):
    """Step 4: the board and the rclpy nodes; [(title, detail, problem)], one per topic."""
    environment = workspace.environment(free_domain_id())
    python = os.path.join(WHEELS, 'bin', 'python')
    peer = Process('rclpy peer', [python, PEER, '--count', str(SAMPLES)], environment)
    bridge = Process('rclpy bridge', [python, BRIDGE, 'qemu-arm', program], environment)
    try:
        peer.popen.wait(timeout=PEER_TIMEOUT)
    except subprocess.TimeoutExpired:
        pass
    finally:
        peer.stop(signal.SIGTERM)
        bridge.stop(signal.SIGTERM)
    results = peer_rows(peer.lines(), 'board')
    if not results:
        raise Failure('the rclpy peer reported nothing; it printed: %s; the bridge: %s'
                      % (' | '.join(peer.lines()[-5:]), ' | '.join(bridge.lines()[-5:])))
    return results


def peer_rows(lines, board):
    """[(title, detail, problem)] of ros2_peer.py's lines, one per topic."""
    results = []
    for line in [line[len('peer: '):].strip() for line in lines if line.startswith('peer: ')]:
        match = re.match(r'(\S+): (\d+) of (\d+) samples came, (\d+) byte for byte', line)
        if not match:
            raise Failure('the rclpy peer said: %s' % line)
        topic = match.group(1)
        came, expected, exact = map(int, match.group(2, 3, 4))
        direction = 'rclpy -> %s -> rclpy' % board if topic.endswith('_echo') else \
            '%s -> rclpy' % board
        problem = None if came == exact == expected else line
        results.append(('%s: %s' % (direction, topic), line, problem))
    return results


def in_sync(workspace, firmware_build, log_path):
    """Step 5: a field added to Reading.msg; what the next builds showed."""
    definition = os.path.join(workspace.root, 'src', 'mros2_test_msgs', 'msg', 'Reading.msg')
    with open(definition, 'a') as stream:
        stream.write(ADDED_FIELD + '\n')
    started = time.monotonic()
    workspace.build(log_path + '.colcon')
    rebuilt = run_logged(['cmake', '--build', firmware_build, '-j2'], log_path + '.firmware')
    seconds = time.monotonic() - started
    header = os.path.join(firmware_build, 'mros2_messages', 'board', 'mros2_test_msgs', 'msg',
                          'reading.hpp')
    with open(header) as stream:
        in_header = 'uint32_t sequence_number = 0u;' in stream.read()
    if 'board_ros2.cpp.o' not in rebuilt or not in_header:
        raise Failure('the firmware did not follow the new field: see %s.firmware' % log_path)
    script = ('from mros2_test_msgs.msg import Reading; '
              'print("sequence_number" in Reading.get_fields_and_field_types())')
    rclpy_has = subprocess.run([os.path.join(WHEELS, 'bin', 'python'), '-c', script],
                               env=workspace.environment(), capture_output=True, text=True)
    if rclpy_has.stdout.strip() != 'True':
        raise Failure("rclpy's Reading has no sequence_number: %s" % rclpy_has.stderr[-300:])
    return ("field 'uint32 sequence_number' added to Reading.msg: in the firmware's "
            "reading.hpp and in rclpy's Reading (colcon build + firmware rebuild %.0f s)"
            % seconds)


def posix_run(posix_root, work_dir, mros2_root=None):
    """Step 6: the mros2-posix app and an rclpy node; its detail line."""
    from rosbags.typesys import Stores, get_typestore
    os.makedirs(work_dir, exist_ok=True)
    exchanged, warnings = mros2_posix.exchange(posix_root, WHEELS, work_dir,
                                               get_typestore(Stores.ROS2_HUMBLE), mros2_root)
    counts = ', '.join('%s %d of %d byte for byte' % (kind, exchanged.exact(kind),
                                                      mros2_posix.EXCHANGES)
                       for kind in ('images', 'echoes'))
    if warnings or any(exchanged.exact(kind) != mros2_posix.EXCHANGES
                       for kind in ('images', 'echoes')):
        raise Failure('%s; %d warnings; see %s' % (counts, len(warnings), work_dir))
    return None, '%s (images up to %d bytes, in fragments; %d requests for %d answers)' % (
        counts, max(len(image) for image in exchanged.answers['images']),
        exchanged.requests_sent, 2 * mros2_posix.EXCHANGES)


# The main job's mros2 app (evaluation/mros2_app) on mros2 itself: its endpoints, and the
# topics the peer checks of each build.
MROS2_APP = os.path.join(HERE, 'mros2_app')
MROS2_APP_CONFIG = os.path.join(MROS2_APP, 'rtps', 'config.h')
APP_SUBSCRIBES = ['command:std_msgs/msg/String', 'twist:geometry_msgs/msg/Twist',
                  'reading_in:mros2_test_msgs/msg/Reading']
APP_ALL_PUBLISHES = ['image:sensor_msgs/msg/Image', 'chatter:std_msgs/msg/String',
                     'reading:mros2_test_msgs/msg/Reading', 'command_echo:std_msgs/msg/String',
                     'twist_echo:geometry_msgs/msg/Twist',
                     'reading_in_echo:mros2_test_msgs/msg/Reading']
# Hardened, the app publishes chatter's samples from a reliable publisher too.
APP_RELIABLE_PUBLISH = 'chatter_reliable:std_msgs/msg/String:reliable:10'
# The app's node, as the ROS 2 graph lists it with the patch node-in-the-ros-graph.
APP_NODE = 'main_job_board'
# Hardened, the app serves one service and calls another (the patch services-both-ways), as
# testing/mros2_pc_services.py serves and calls them; the calls each way.
APP_SERVES = ['parameter_types:rcl_interfaces/srv/GetParameterTypes']
APP_CALLS = ['name_lengths:rcl_interfaces/srv/GetParameterTypes']
SERVICE_CALLS = 20


def mros2_pc_run(workspace, work_dir, mros2_root, hardened):
    """Step 7: evaluation/mros2_app on the user's mros2 (genmros mros2-pc, qemu-arm) and
    ros2_peer.py on its ROS side; [(title, detail, problem)], one per topic, and the board's
    output. As it is (with the discovery patch alone) the app has one publisher, image;
    hardened, all six."""
    from testing import mros2_pc
    os.makedirs(work_dir, exist_ok=True)
    installs = sorted(glob.glob(os.path.join(workspace.root, 'install', '*')))
    publishes = APP_ALL_PUBLISHES + [APP_RELIABLE_PUBLISH] if hardened else \
        APP_ALL_PUBLISHES[:1]
    options = {'hardened': True, 'app_defines': ('APP_ALL_PUBLISHERS',), 'serve': APP_SERVES,
               'call': APP_CALLS} if hardened else {'patches': mros2_pc.TALKING_PATCHES}
    program = mros2_pc.build(MROS2_APP, os.path.join(work_dir, 'build'), mros2_root,
                             MROS2_APP_CONFIG, prefixes=installs + [WHEELS],
                             publish=publishes, subscribe=APP_SUBSCRIBES, **options)
    environment = {key: value for key, value in workspace.environment().items()
                   if key != 'ROS_AUTOMATIC_DISCOVERY_RANGE'}
    topics = [endpoint.split(':')[0] for endpoint in publishes]
    graph_rows, service_rows = [], []
    with mros2_pc.Session(program, work_dir) as session:
        session.start_board()
        if not session.wait_for_output('app ready'):
            raise Failure('the board stopped: %s' % session.output()[-500:])
        if hardened:
            watcher = session.graph_watcher(APP_NODE, len(publishes), len(APP_SUBSCRIBES),
                                            wait=PEER_TIMEOUT)
            graph_rows.append(graph_row(watcher.seen(), publishes))
        peer = subprocess.Popen(
            session.network.ros_command([os.path.join(WHEELS, 'bin', 'python'), PEER, '--count',
                                         str(SAMPLES), '--timeout', str(PEER_TIMEOUT),
                                         '--best-effort', '--topics', ','.join(topics)] +
                                        (['--reliable-chatter'] if hardened else [])),
            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=environment)
        stdout, stderr = peer.communicate(timeout=PEER_TIMEOUT + 60)
        if hardened:
            service_rows = service_call_rows(session)
        output = session.stop_board()
        if hardened:
            watcher.stop()
    with open(os.path.join(work_dir, 'board.log'), 'w') as log:
        log.write(output)
    results = peer_rows(stdout.splitlines(), 'the board')
    if not results:
        raise Failure('the rclpy peer reported nothing: %s' % stderr[-500:])
    return graph_rows + results + service_rows, output


def service_call_rows(session):
    """(title, detail, problem) of the app's service called by rclpy and of the app calling
    rclpy's, SERVICE_CALLS each way (testing/mros2_pc_services.py, rclpy's default services
    QoS): every reply and request checked field by field."""
    from testing import mros2_pc
    job = {'serve': APP_CALLS[0].split(':')[0], 'call': APP_SERVES[0].split(':')[0],
           'node': APP_NODE, 'calls': SERVICE_CALLS, 'clients': 0, 'board_calls': SERVICE_CALLS,
           'wait': PEER_TIMEOUT}
    report = session.peer(job, script=mros2_pc.SERVICES_SCRIPT).result()
    session.wait_for_output('call %d ' % (SERVICE_CALLS - 1))
    right, calls = report.get('calls', [0, SERVICE_CALLS])
    listed = ['/' + job['call'], [APP_SERVES[0].split(':')[1]]] in report['services_by_node']
    called = '%d of %d replies right; %s by rclpy under %s' % (
        right, calls, 'listed' if listed else 'not listed', APP_NODE)
    board_ok = sum(1 for line in session.output().splitlines()
                   if line.startswith('call ') and line.endswith(' ok'))
    requests_right = sum(1 for i, names in enumerate(report['requests'][:SERVICE_CALLS])
                         if names == ['call %d' % i, 'x' * i])
    calling = '%d of %d replies right on the board; %d of its requests right at rclpy' % (
        board_ok, SERVICE_CALLS, requests_right)
    return [('a service called by rclpy (parameter_types)', called,
             None if right == calls == SERVICE_CALLS and listed else called),
            ('the board calling an rclpy service (name_lengths)', calling,
             None if board_ok == requests_right == SERVICE_CALLS else calling)]


def graph_row(seen, publishes):
    """(title, detail, problem) of what rclpy's graph API showed of the app's node: listed,
    with exactly the app's topics and types."""
    def names(endpoints):
        return sorted(['/' + endpoint.split(':')[0], [endpoint.split(':')[1]]]
                      for endpoint in endpoints)
    listed = [APP_NODE, '/'] in seen['nodes']
    detail = '%s in /, listed after %s s: publishers %s; subscribers %s' % (
        APP_NODE, 'never' if seen['seen_after'] is None else '%.1f' % seen['seen_after'],
        ', '.join(topic for topic, _ in seen['publishers']),
        ', '.join(topic for topic, _ in seen['subscribers']))
    exact = seen['publishers'] == names(publishes) and \
        seen['subscribers'] == names(APP_SUBSCRIBES)
    return ('the node listed by rclpy (get_node_names_and_namespaces, *_by_node)', detail,
            None if listed and exact else detail)
