# SPDX-License-Identifier: BSD-3-Clause
"""The soak of the mros2 PC target: fresh starts of one hardened board program against the
plain node (testing/mros2_pc_peer.py), every sample of every start to arrive, for
bench/mros2/soak.py (50 starts a case) and the suite (a few).

A case is an app, a target and the samples the plain node sends; its starts alternate
between mros2-posix' address and another one, and between the board starting first and the
node starting first. A start passes when the node matched and every reply came, exact, in
order (and, with --sanitize, the board reports nothing). The control runs an rclpy node
(testing/mros2_pc_control.py) in the board's place with the same node and samples.

The services soak (bench/mros2/service_soak.py) starts service_pair and the service peer
(testing/mros2_pc_services.py) afresh, in both orders; a start passes when every call both
ways came back right. The board's config copies (changed_config) serve the tests and the
benches alike.
"""

import dataclasses
import os
import re
import time

from testing import mros2_pc
from testing.mros2_posix import wire_bytes

APPS = os.path.join(os.path.dirname(os.path.abspath(__file__)), 'mros2_pc_apps')
CONTROL_SCRIPT = os.path.join(os.path.dirname(os.path.abspath(__file__)), 'mros2_pc_control.py')
ADDRESSES = ('192.168.11.3', '10.77.3.9')
ORDERS = ('board first', 'node first')
STRING, TWIST, POSE = 'std_msgs/msg/String', 'geometry_msgs/msg/Twist', 'geometry_msgs/msg/Pose'
SANITIZER_REPORTS = ('AddressSanitizer', 'LeakSanitizer', 'runtime error:')
# The board's own view of each match (mros2's pubMatch and subMatch callbacks).
MATCH_LINES = ('publisher matched with remote subscriber',
               'subscriber matched with remote publisher')
# The large cases' receive limit and the board's settings for them.
LARGE_LIMIT = 1472
LARGE_BUFFER = 32768
LARGE_QUEUE = 64
LARGE_SIZE = 30000
# Room for the DDS type names of ROS 2 services and of ros_discovery_info (52 characters with
# its NUL), which mros2-posix' 40 do not hold.
LONG_TYPE_NAMES = (r'MAX_TYPENAME_LENGTH = 40', 'MAX_TYPENAME_LENGTH = 64')


@dataclasses.dataclass
class Case:
    """One soak case: the app, its build and the exchange."""

    name: str
    app: str
    target: str
    large: bool

    def build_options(self):
        options = {'hardened': True, 'target': self.target, 'sanitize': self.target == 'native'}
        if self.large:
            options.update(receive_limit=str(LARGE_LIMIT), peer_max_message=LARGE_LIMIT)
        return options

    @property
    def max_message(self):
        """The ROS side's profile (genmros mros2-peer-profile), for the large cases."""
        return LARGE_LIMIT if self.large else None


CASES = {case.name: case for case in (
    Case('arm-small', 'three_echoes', 'arm', False),
    Case('native-small', 'three_echoes', 'native', False),
    Case('arm-large', 'fragment_echo', 'arm', True),
    Case('native-large', 'fragment_echo', 'native', True))}


def changed_config(posix_root, directory, changes):
    """A copy of the board's config (mros2-posix' rtps/config.h) in directory/rtps/config.h,
    each (pattern, text) of changes made once; its path."""
    with open(os.path.join(posix_root, 'include', 'rtps', 'config.h')) as stream:
        config = stream.read()
    for pattern, text in changes:
        config, made = re.subn(pattern, text, config)
        if made != 1:
            raise ValueError("mros2-posix' config.h is not the one expected: %s" % pattern)
    path = os.path.join(directory, 'rtps', 'config.h')
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, 'w') as stream:
        stream.write(config)
    return path


def board_config(posix_root, case, directory):
    """The board's rtps/config.h: mros2-posix' own; for the large cases with the fragment
    buffer and the reader thread's queue they need."""
    changes = [(r'THREAD_POOL_WORKLOAD_QUEUE_LENGTH = \d+',
                'THREAD_POOL_WORKLOAD_QUEUE_LENGTH = %d' % LARGE_QUEUE),
               (r'\}\s*//\s*namespace Config',
                'const DataSize_t FRAGMENT_BUFFER_SIZE = %d;\n} // namespace Config'
                % LARGE_BUFFER)] if case.large else []
    return changed_config(posix_root, os.path.join(directory, case.name), changes)


def build_programs(case, posix_root, mros2_root, work_dir, patches=None, addresses=ADDRESSES):
    """{address: program} of the case (patches: these of the series, not all of it)."""
    options = case.build_options()
    if patches is not None:
        options.update(hardened=False, patches=tuple(patches))
    config = board_config(posix_root, case, work_dir)
    return {address: mros2_pc.build(os.path.join(APPS, case.app),
                                    os.path.join(work_dir, case.name, 'build-' + address),
                                    mros2_root, config, board_address=address, **options)
            for address in addresses}


def exchange(case, typestore):
    """(the plain node's job, {topic: the replies expected, in order}, the control's job)."""
    types = typestore.types
    if case.large:
        texts = [chr(ord('a') + index) * LARGE_SIZE for index in range(10)]
        samples = [wire_bytes(typestore, types[STRING](data=text), STRING) for text in texts]
        job = mros2_pc.plain_job(publish=[('text', STRING, samples)],
                                 subscribe=[('text_back', STRING)], expect={'text_back': 10})
        control = [{'from': 'text', 'to': 'text_back', 'type': STRING, 'change': None}]
        return job, {'text_back': samples}, {'echo': control}
    vector, point = types['geometry_msgs/msg/Vector3'], types['geometry_msgs/msg/Point']
    quaternion = types['geometry_msgs/msg/Quaternion']

    def twist(index, shift=0.0, factor=1.0):
        return wire_bytes(typestore, types[TWIST](
            linear=vector(x=index + shift, y=-0.5, z=0.25),
            angular=vector(x=0.0, y=1.5, z=index * 0.5 * factor)), TWIST)

    def pose(index, shift=0.0):
        return wire_bytes(typestore, types[POSE](
            position=point(x=1.0, y=-2.0, z=index + shift),
            orientation=quaternion(x=0.0, y=0.0, z=0.5, w=0.75)), POSE)

    def text(data):
        return wire_bytes(typestore, types[STRING](data=data), STRING)
    indices = range(20)
    job = mros2_pc.plain_job(
        publish=[('text', STRING, [text('hello %d' % i) for i in indices]),
                 ('twist', TWIST, [twist(i) for i in indices]),
                 ('pose', POSE, [pose(i) for i in indices])],
        subscribe=[('text_echo', STRING), ('twist_echo', TWIST), ('pose_echo', POSE)],
        expect={'text_echo': 20, 'twist_echo': 20, 'pose_echo': 20})
    replies = {'text_echo': [text('echo: hello %d' % i) for i in indices],
               'twist_echo': [twist(i, 1.0, 2.0) for i in indices],
               'pose_echo': [pose(i, 1.0) for i in indices]}
    control = [{'from': 'text', 'to': 'text_echo', 'type': STRING, 'change': 'text'},
               {'from': 'twist', 'to': 'twist_echo', 'type': TWIST, 'change': 'twist'},
               {'from': 'pose', 'to': 'pose_echo', 'type': POSE, 'change': 'pose'}]
    return job, replies, {'echo': control}


@dataclasses.dataclass
class Start:
    """What one start showed."""

    passed: bool
    address: str
    order: str
    arrived: int
    expected: int
    # Seconds from the later of the node's start and the board's "app ready" until the node
    # saw every endpoint matched, and until the board had reported its side of each match
    # (None: not seen).
    node_matched_after: float
    board_matched_after: float
    problem: str = ''


def run_start(program, case, typestore, work_dir, index, control=False):
    """Start index of case (its address is program's): a fresh board, or the control, and
    a fresh plain node, in the order of the start's index."""
    job, replies, control_job = exchange(case, typestore)
    order = ORDERS[index // len(ADDRESSES) % len(ORDERS)]
    os.makedirs(work_dir, exist_ok=True)
    with mros2_pc.Session(program, work_dir) as session:
        def start_board():
            if control:
                session.start_board([os.path.join(mros2_pc.WHEELS_VENV, 'bin', 'python'),
                                     CONTROL_SCRIPT], control_job, case.max_message)
            else:
                session.start_board()
        if order == 'board first':
            start_board()
            session.wait_for_output('app ready')
            started = time.monotonic()
            peer = session.peer(job, case.max_message)
        else:
            peer = session.peer(job, case.max_message)
            start_board()
            session.wait_for_output('app ready')
            started = time.monotonic()
        node_matched_after = board_matched_after = None
        wanted = len(job['publish']) + len(job['subscribe'])
        while peer.running():
            if node_matched_after is None and peer.matched():
                node_matched_after = time.monotonic() - started
            output = session.output()
            if board_matched_after is None and \
                    sum(output.count(line) for line in MATCH_LINES) >= wanted:
                board_matched_after = time.monotonic() - started
            time.sleep(0.02)
        report = peer.result()
        output = session.stop_board()
    if control:
        # rclpy leaves the padding after a sample's last member as its buffer held it: the
        # control's replies are held to the values, the board's to every byte.
        types = {entry['topic']: entry['type'] for entry in job['subscribe']}
        report['received'] = {topic: [typestore.deserialize_cdr(sample, types[topic])
                                      for sample in samples]
                              for topic, samples in report['received'].items()}
        replies = {topic: [typestore.deserialize_cdr(sample, types[topic])
                           for sample in samples] for topic, samples in replies.items()}
    arrived = sum(len(samples) for samples in report['received'].values())
    expected = sum(len(samples) for samples in replies.values())
    problems = ['%s: %d of %d came back%s' % (
        topic, len(report['received'][topic]), len(samples),
        ', not as sent' if len(report['received'][topic]) == len(samples) else '')
        for topic, samples in replies.items() if report['received'][topic] != samples]
    if not report['matched']:
        problems.insert(0, 'the node never matched')
    problems += ['the board reports: %s' % word for word in SANITIZER_REPORTS if word in output]
    return Start(not problems, program.board_address, order, arrived, expected,
                 node_matched_after, board_matched_after, '; '.join(problems))


# The services soak: the app service_pair (it serves parameter_types and calls the ROS
# side's name_lengths SERVICE_PAIR_CALLS times) against the service peer.
SERVICE_PAIR = os.path.join(APPS, 'service_pair')
SERVICE_PAIR_CALLS = 100
SERVICE_TYPE = 'rcl_interfaces/srv/GetParameterTypes'
SERVICE_CLIENTS = 3


def service_job(calls, wait=60):
    """The service peer's job (testing/mros2_pc_services.py) against service_pair: calls
    calls one by one, and again after a client gone before its reply."""
    return {'serve': 'name_lengths', 'call': 'parameter_types', 'node': 'service_pair',
            'calls': calls, 'clients': SERVICE_CLIENTS, 'board_calls': SERVICE_PAIR_CALLS,
            'wait': wait}


def service_problems(report, output, calls):
    """What went wrong in one run of service_pair against the service peer (report, its
    report; output, the board's): [] when every call both ways came back right, no reply
    was refused and rclpy listed the service by its node."""
    problems = ['%s: %d of %d replies right' % (what, *report.get(key, [0, calls]))
                for key, what in (('calls', 'rclpy calling'),
                                  ('after_gone', 'rclpy calling after a client gone'))
                if report.get(key, [0, calls]) != [calls, calls]]
    clients = report.get('clients', [])
    if len(clients) != SERVICE_CLIENTS or any(right != of for right, of in clients):
        problems.append('clients at once: %s' % clients)
    refused = re.findall(r'requests \d+ \((\d+) replies refused\)', output)
    if refused[-1:] != ['0']:
        problems.append('replies refused: %s' % (refused[-1:] or ['no count']))
    ok = [line for line in output.splitlines() if line.startswith('call ')]
    if ok != ['call %d ok' % i for i in range(SERVICE_PAIR_CALLS)]:
        problems.append('the board calling: %d of %d ok' % (
            sum(line.endswith(' ok') for line in ok), SERVICE_PAIR_CALLS))
    if report.get('requests') != [['call %d' % i, 'x' * i] for i in range(SERVICE_PAIR_CALLS)]:
        problems.append('rclpy serving: %d of %d requests as sent' % (
            len(report.get('requests', [])), SERVICE_PAIR_CALLS))
    if report.get('services_by_node') != [['/parameter_types', [SERVICE_TYPE]]]:
        problems.append('by node: %s' % report.get('services_by_node'))
    return problems + ['the board reports: %s' % word for word in SANITIZER_REPORTS
                       if word in output]


@dataclasses.dataclass
class ServiceStart:
    """What one start of the services soak showed."""

    passed: bool
    order: str
    # Seconds from the second of the two starts until the board's calls were done.
    took: float
    problem: str = ''


def run_service_start(program, work_dir, index, calls):
    """Start index of the services soak: a fresh service_pair board and a fresh service
    peer, in the order of the start's index."""
    order = ORDERS[index % len(ORDERS)]
    job = service_job(calls)
    os.makedirs(work_dir, exist_ok=True)
    with mros2_pc.Session(program, work_dir) as session:
        if order == 'board first':
            session.start_board()
            session.wait_for_output('app ready')
            started = time.monotonic()
            peer = session.peer(job, script=mros2_pc.SERVICES_SCRIPT)
        else:
            peer = session.peer(job, script=mros2_pc.SERVICES_SCRIPT)
            started = time.monotonic()
            session.start_board()
        report = peer.result()
        session.wait_for_output('calls done')
        took = time.monotonic() - started
        output = session.stop_board()
    problems = service_problems(report, output, calls)
    return ServiceStart(not problems, order, took, '; '.join(problems))
