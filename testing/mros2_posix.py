# SPDX-License-Identifier: BSD-3-Clause
"""A genmros app on a real mros2-posix, run against an rclpy node over a veth pair.

tests/integrations/test_mros2_posix.py uses it: :func:`prepare_checkout` copies a user's
assembled mros2-posix checkout (MROS2_POSIX_ROOT) and makes what a run against ROS 2's
Fast DDS 3 needs of its embeddedRTPS (:func:`accept_fast_dds_3_discovery`), optionally with
another mros2 (v0.5.4, patched by genmros mros2-harden) in place of the pinned one;
:func:`write_app` puts testing/mros2_posix_app and genmros' headers and templates.hpp into
workspace/<app>; :func:`build_app` builds it as mros2-posix' build.bash does, minus the
downloads and mros2's templates generator. :class:`NetworkPair` gives the app its address
(192.168.11.3, in a network namespace of its own) and the peer a second one (192.168.11.2);
:func:`run_peer` runs testing/mros2_posix_app/rclpy_peer.py there in the ROS 2 wheels' venv.
:func:`requested_image`, :func:`echo_image` and :func:`wire_bytes` are what the app should
send, from rosbags. :func:`exchange` is the whole run, as the test and the main job make
it: the app on the pinned mros2 (one publisher: every answer an Image) or on mros2 v0.5.4
patched (two publishers: images, and String echoes on their own topic).
"""

import json
import os
import re
import shutil
import signal
import subprocess
import sys

import numpy

from colcon_mros.library_tools.mros2.patches import mros2_patches
from colcon_mros.library_tools.patch_series import apply_patches

APP_SOURCES = os.path.join(os.path.dirname(os.path.abspath(__file__)), 'mros2_posix_app')
PEER_SCRIPT = os.path.join(APP_SOURCES, 'rclpy_peer.py')
APP_NAME = 'genmros_app'
# mros2-posix' include/netif.h and rtps/config.h fix the app's address.
APP_ADDRESS = '192.168.11.3'
PEER_ADDRESS = '192.168.11.2'
PREFIX_LENGTH = 24
# app.cpp's test image: width and data bytes per index.
IMAGE_BYTES_PER_INDEX = 17
BUILD_JOBS = '2'
# Build products of a checkout that was built before: a copy starts from sources.
BUILD_DIRECTORIES = ('cmake_build', 'public')
FAST_DDS_3_PATCH = 'accept-fast-dds-3-discovery'


def checkout_problem(root):
    """Why root is no assembled mros2-posix checkout, or None."""
    if not root:
        return 'MROS2_POSIX_ROOT is not set (an assembled mros2-posix checkout, docs/mros2.md)'
    needed = ['CMakeLists.txt', 'include/rtps/config.h', 'mros2/src/mros2.cpp',
              'mros2/embeddedRTPS/src/discovery/ParticipantProxyData.cpp',
              'cmsis-posix/Third_Party/FreeRTOS/Source/CMSIS_RTOS_V2/cmsis_os2.h',
              'lwip-posix/lwip/src/core/udp.c']
    missing = [path for path in needed if not os.path.isfile(os.path.join(root, path))]
    if missing:
        return 'MROS2_POSIX_ROOT=%s is no assembled mros2-posix checkout (no %s)' % (
            root, ', '.join(missing))
    return None


def accept_fast_dds_3_discovery(mros2_dir):
    """What embeddedRTPS (as mros2 v0.4.1 and v0.5.4 pin it) needs to discover a
    participant of Fast DDS 3 (rclpy 9.1 on rmw_fastrtps_cpp), without which the app
    never answers: genmros' patch accept-fast-dds-3-discovery, the one of its mros2
    series that applies to v0.4.1 too, applied alone by the series' driver."""
    patches = [patch for patch in mros2_patches() if patch.name == FAST_DDS_3_PATCH]
    apply_patches(mros2_dir, patches)


def prepare_checkout(root, destination, mros2_root=None):
    """A copy of the checkout root at destination, its build products left out, ready
    for Fast DDS 3. With mros2_root, that mros2, patched by genmros mros2-harden, in
    place of the pinned one, and the copy's rtps/config.h made to fit it: mros2 >= 0.5
    defines rtps::Config::IP_ADDRESS itself (set at run time), so the board's config only
    declares it."""
    shutil.copytree(root, destination, symlinks=True,
                    ignore=shutil.ignore_patterns(*BUILD_DIRECTORIES))
    if mros2_root:
        mros2_dir = os.path.join(destination, 'mros2')
        shutil.rmtree(mros2_dir)
        shutil.copytree(mros2_root, mros2_dir, symlinks=True)
        # accept-fast-dds-3-discovery among them
        run_genmros('mros2-harden', '--mros2-root', mros2_dir)
        config = os.path.join(destination, 'include', 'rtps', 'config.h')
        with open(config) as stream:
            text = stream.read()
        text, count = re.subn(r'const std::array<uint8_t, 4> IP_ADDRESS = \{[^}]*\};[^\n]*',
                              'extern std::array<uint8_t, 4> IP_ADDRESS;', text)
        if count != 1:
            raise AssertionError('%s: no IP_ADDRESS definition to turn into a declaration'
                                 % config)
        with open(config, 'w') as stream:
            stream.write(text)
    else:
        accept_fast_dds_3_discovery(os.path.join(destination, 'mros2'))
    return destination


def run_genmros(*arguments):
    repository = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    result = subprocess.run([sys.executable, '-m', 'colcon_mros'] + list(arguments),
                            capture_output=True, text=True, cwd=repository)
    if result.returncode != 0:
        raise AssertionError('genmros %s failed:\n%s' % (' '.join(arguments), result.stderr))
    return result


def write_app(checkout, ros_prefix, publish, subscribe):
    """workspace/<APP_NAME>: the app's sources and genmros' headers and templates.hpp
    for publish and subscribe (TOPIC:TYPE each), fit-checked against the copy's
    rtps/config.h and lwIP's receive limit."""
    app_dir = os.path.join(checkout, 'workspace', APP_NAME)
    os.makedirs(app_dir)
    for name in ('app.cpp', 'Filelists.cmake'):
        shutil.copy(os.path.join(APP_SOURCES, name), app_dir)
    arguments = ['mros2-export', '--prefix', ros_prefix, '-o', app_dir,
                 '--rtps-config', os.path.join(checkout, 'include', 'rtps', 'config.h'),
                 '--receive-limit',
                 os.path.join(checkout, 'lwip-posix', 'src', 'core', 'udp.c')
                 + ':MAX_RECV_PACKET_SIZE']
    for endpoint in publish:
        arguments += ['--publish', endpoint]
    for endpoint in subscribe:
        arguments += ['--subscribe', endpoint]
    run_genmros(*arguments)
    return app_dir


def _build_step(command, cwd, log):
    log.write('$ %s  (in %s)\n' % (' '.join(command), cwd))
    log.flush()
    result = subprocess.run(command, cwd=cwd, stdout=subprocess.PIPE,
                            stderr=subprocess.STDOUT, text=True, timeout=900)
    log.write(result.stdout)
    if result.returncode != 0:
        raise AssertionError('%s failed in %s:\n%s'
                             % (' '.join(command), cwd, result.stdout[-6000:]))
    return result.stdout


def build_app(checkout, log_path, app_options=()):
    """Builds workspace/<APP_NAME> (app_options: Filelists.cmake's, e.g.
    'APP_ECHO_PUBLISHER'); returns the program and the compiler's warnings about app.cpp
    and genmros' headers (none expected)."""
    with open(log_path, 'w') as log:
        # The top-level CMakeLists.txt finds cmsis and lwip installed into <lib>/public.
        for library in ('cmsis-posix', 'lwip-posix'):
            build = os.path.join(checkout, library, 'cmake_build')
            os.makedirs(build)
            _build_step(['cmake', '..'], build, log)
            _build_step(['make', '-j' + BUILD_JOBS], build, log)
            _build_step(['make', 'install'], build, log)
        build = os.path.join(checkout, 'cmake_build')
        os.makedirs(build)
        _build_step(['cmake', '..', '-DCMAKE_APPNAME=' + APP_NAME]
                    + ['-D%s=ON' % option for option in app_options], build, log)
        output = _build_step(['make', '-j' + BUILD_JOBS], build, log)
    ours = os.path.join(checkout, 'workspace', APP_NAME) + os.sep
    warnings = [line for line in output.splitlines()
                if line.startswith(ours) and ': warning:' in line]
    return os.path.join(build, 'mros2-posix'), warnings


class NetworkPair:
    """Two network namespaces joined by a veth pair: the app's (APP_ADDRESS) and the
    peer's (PEER_ADDRESS), each with a multicast route over the veth for DDS discovery
    (239.255.0.1). Names carry the process id so parallel runs do not meet."""

    def __init__(self):
        self._suffix = str(os.getpid())
        self.app_namespace = 'gm_app' + self._suffix
        self.peer_namespace = 'gm_peer' + self._suffix
        self._created = []

    def create(self):
        # A link name has at most 15 characters.
        app_link, peer_link = 'gma' + self._suffix, 'gmp' + self._suffix
        for namespace in (self.app_namespace, self.peer_namespace):
            _ip('netns', 'add', namespace)
            self._created.append(namespace)
            _ip('-n', namespace, 'link', 'set', 'lo', 'up')
        _ip('link', 'add', app_link, 'netns', self.app_namespace, 'type', 'veth',
            'peer', 'name', peer_link, 'netns', self.peer_namespace)
        for namespace, link, address in ((self.app_namespace, app_link, APP_ADDRESS),
                                         (self.peer_namespace, peer_link, PEER_ADDRESS)):
            _ip('-n', namespace, 'addr', 'add', '%s/%d' % (address, PREFIX_LENGTH),
                'dev', link)
            _ip('-n', namespace, 'link', 'set', link, 'up')
            _ip('-n', namespace, 'route', 'add', '224.0.0.0/4', 'dev', link)
        return self

    def remove(self):
        """Deleting a namespace deletes its end of the veth, and so the pair."""
        problems = []
        for namespace in reversed(self._created):
            result = subprocess.run(['ip', 'netns', 'delete', namespace],
                                    capture_output=True, text=True)
            if result.returncode != 0:
                problems.append(result.stderr.strip())
        self._created = []
        if problems:
            raise AssertionError('; '.join(problems))


def _ip(*arguments):
    result = subprocess.run(('ip',) + arguments, capture_output=True, text=True)
    if result.returncode != 0:
        raise AssertionError('ip %s: %s' % (' '.join(arguments), result.stderr.strip()))


class AppProcess:
    """The app running in a namespace, its output line-buffered into log_path."""

    def __init__(self, program, namespace, log_path):
        self.log_path = log_path
        self._log = open(log_path, 'w')
        # A session of its own, so stop() reaches the app and nothing else.
        self._process = subprocess.Popen(
            ['ip', 'netns', 'exec', namespace, 'stdbuf', '-oL', program],
            stdout=self._log, stderr=subprocess.STDOUT, start_new_session=True)

    def output(self):
        with open(self.log_path, errors='replace') as stream:
            return stream.read()

    def stop(self):
        if self._process.poll() is None:
            os.killpg(self._process.pid, signal.SIGINT)
            try:
                self._process.wait(timeout=5)
            except subprocess.TimeoutExpired:
                os.killpg(self._process.pid, signal.SIGKILL)
                self._process.wait(timeout=5)
        self._log.close()


def run_peer(venv, namespace, requests, log_dir, first_timeout=30, timeout=5):
    """rclpy_peer.py in namespace: requests are (text, serialized String, answer topic,
    'Image' or 'String'); returns its report (see the script)."""
    job = {'requests': [{'text': text, 'sample': sample.hex(), 'topic': topic,
                         'type': type_name}
                        for text, sample, topic, type_name in requests],
           'first_timeout': first_timeout, 'timeout': timeout}
    env = {key: value for key, value in os.environ.items()
           if not key.startswith(('ROS_', 'RMW_', 'FASTRTPS_', 'FASTDDS_', 'AMENT_'))}
    env.update(RMW_IMPLEMENTATION='rmw_fastrtps_cpp', ROS_DOMAIN_ID='0', ROS_LOG_DIR=log_dir)
    limit = first_timeout + timeout * len(requests) + 30
    result = subprocess.run(['ip', 'netns', 'exec', namespace,
                             os.path.join(venv, 'bin', 'python'), PEER_SCRIPT],
                            input=json.dumps(job), capture_output=True, text=True, env=env,
                            timeout=limit)
    if result.returncode != 0:
        raise AssertionError('the rclpy peer failed (%d):\n%s'
                             % (result.returncode, result.stderr[-4000:]))
    return json.loads(result.stdout)


def requested_image(typestore, index, frame_id):
    """app.cpp's test image index (fill_test_image) as a rosbags message."""
    types = typestore.types
    width = IMAGE_BYTES_PER_INDEX * index
    header = types['std_msgs/msg/Header'](
        stamp=types['builtin_interfaces/msg/Time'](sec=index, nanosec=1000003 * index),
        frame_id=frame_id)
    data = numpy.array([(7 * index + i) % 256 for i in range(width)], dtype=numpy.uint8)
    return types['sensor_msgs/msg/Image'](header=header, height=1, width=width,
                                          encoding='mono8', is_bigendian=0, step=width,
                                          data=data)


def echo_image(typestore, text):
    """app.cpp's echo of text as an Image (mros2 0.4: one writer for all publishers)."""
    types = typestore.types
    header = types['std_msgs/msg/Header'](
        stamp=types['builtin_interfaces/msg/Time'](sec=0, nanosec=0), frame_id=text)
    return types['sensor_msgs/msg/Image'](header=header, height=0, width=0, encoding='echo',
                                          is_bigendian=0, step=0,
                                          data=numpy.array([], dtype=numpy.uint8))


def wire_bytes(typestore, message, type_name):
    """What mros2 sends for message: the encapsulation header and the CDR image
    (rosbags'), zero-padded to a multiple of 4 (Publisher::publish pads, and counts the
    padding in the sample's size)."""
    data = bytes(typestore.serialize_cdr(message, type_name))
    return data + bytes(-len(data) % 4)


# The run of exchange(): 20 image requests (0 to 323 bytes of pixels: the larger ones go
# out as DATA_FRAG) and 20 strings the app echoes, growing by 7 characters, so the later
# echoes go over mros2's 100-byte buffer too.
EXCHANGES = 20
IMAGE_TOPIC, ECHO_TOPIC, REQUEST_TOPIC = 'images', 'echo', 'requests'
IMAGE_TYPE, STRING_TYPE = 'sensor_msgs/msg/Image', 'std_msgs/msg/String'
ECHO_GROWTH = 7
# Filelists.cmake's options for mros2 v0.5.4: a String echo publisher, and the RTPS
# address set at run time (mros2 >= 0.5 defines rtps::Config::IP_ADDRESS).
TWO_PUBLISHER_OPTIONS = ('APP_ECHO_PUBLISHER', 'APP_SETS_RTPS_ADDRESS')


class Exchanged:
    """What a run showed: per kind ('images', 'echoes'), the answers that came (bytes,
    or None) and what each should be; the requests the peer sent; the app's output."""

    def __init__(self, answers, expected, requests_sent, app_output):
        self.answers = answers
        self.expected = expected
        self.requests_sent = requests_sent
        self.app_output = app_output

    def exact(self, kind):
        return sum(answer == wanted
                   for answer, wanted in zip(self.answers[kind], self.expected[kind]))

    def wrong(self, kind):
        """The answers that came and are not what they should be: (got, wanted) hex."""
        return [(answer.hex(), wanted.hex())
                for answer, wanted in zip(self.answers[kind], self.expected[kind])
                if answer is not None and answer != wanted]


def _requests(typestore, echo_topic, echo_type):
    string = typestore.types[STRING_TYPE]
    texts = [('image %d' % index, IMAGE_TOPIC, 'Image') for index in range(EXCHANGES)]
    texts += [('echo %d %s' % (index, 'x' * (ECHO_GROWTH * index)), echo_topic, echo_type)
              for index in range(EXCHANGES)]
    return [(text, bytes(typestore.serialize_cdr(string(data=text), STRING_TYPE)), topic,
             type_name) for text, topic, type_name in texts]


def exchange(posix_root, venv, work_dir, typestore, mros2_root=None):
    """The app on a copy of posix_root (with mros2_root, mros2 v0.5.4 patched, two
    publishers) against rclpy_peer.py; returns (Exchanged, the build's warnings)."""
    checkout = prepare_checkout(posix_root, os.path.join(work_dir, 'mros2-posix'), mros2_root)
    two_publishers = mros2_root is not None
    echo_topic, echo_type = (ECHO_TOPIC, 'String') if two_publishers else (IMAGE_TOPIC, 'Image')
    write_app(checkout, venv, publish=['%s:%s' % (IMAGE_TOPIC, IMAGE_TYPE)]
              + (['%s:%s' % (ECHO_TOPIC, STRING_TYPE)] if two_publishers else []),
              subscribe=['%s:%s' % (REQUEST_TOPIC, STRING_TYPE)])
    program, warnings = build_app(checkout, os.path.join(work_dir, 'build.log'),
                                  TWO_PUBLISHER_OPTIONS if two_publishers else ())
    requests = _requests(typestore, echo_topic, echo_type)
    network = NetworkPair()
    app = None
    try:
        network.create()
        app = AppProcess(program, network.app_namespace, os.path.join(work_dir, 'app.log'))
        report = run_peer(venv, network.peer_namespace, requests,
                          os.path.join(work_dir, 'ros_log'))
    finally:
        if app is not None:
            app.stop()
        network.remove()
    answers = [bytes.fromhex(answer['sample']) if answer else None
               for answer in report['answers']]
    string = typestore.types[STRING_TYPE]
    images = [wire_bytes(typestore, requested_image(typestore, index, 'image %d' % index),
                         IMAGE_TYPE) for index in range(EXCHANGES)]
    echoes = [wire_bytes(typestore, string(data=text), STRING_TYPE) if two_publishers else
              wire_bytes(typestore, echo_image(typestore, text), IMAGE_TYPE)
              for text, _, _, _ in requests[EXCHANGES:]]
    return Exchanged({'images': answers[:EXCHANGES], 'echoes': answers[EXCHANGES:]},
                     {'images': images, 'echoes': echoes},
                     sum(answer['sent'] for answer in report['answers']),
                     app.output()), warnings
