"""A real mros2-posix app on genmros' headers exchanges samples with a real rclpy node.

Opt-in: MROS2_POSIX_ROOT names an assembled mros2-posix checkout (docs/mros2.md), and the
run needs root (network namespaces) and the ROS 2 wheels' venv, build/ros2-wheels (rclpy
on Fast DDS 3). A copy of the checkout gets testing/mros2_posix_app with the headers and
templates.hpp of genmros mros2-export, is built without build.bash, and runs in a network
namespace as 192.168.11.3, a veth pair away from an rclpy node at 192.168.11.2. The node
asks for 20 test images (0 to 323 bytes of pixels: the larger ones go out as DATA_FRAG)
and sends 20 strings (6 to 140 characters) that the app decodes and echoes; each answer
is the bytes rosbags writes for the values the app put in, zero-padded to 4 as mros2 pads.

mros2 v0.4.1, which mros2-posix pins, sends every message through its last publisher, so
its app answers everything on one Image publisher; with MROS2_ROOT (mros2 v0.5.4) patched
by genmros mros2-harden in its place, the app has two publishers, and images and String
echoes arrive each on their own topic. Both runs change embeddedRTPS in the copy so that
it discovers a Fast DDS 3 participant at all (testing/mros2_posix.py,
accept_fast_dds_3_discovery).
"""

import os

import pytest

from conftest import REPO
from testing import mros2_posix

pytestmark = pytest.mark.slow

WHEELS_VENV = os.path.join(REPO, 'build', 'ros2-wheels')
EXCHANGES = 20
IMAGE_TOPIC, ECHO_TOPIC, REQUEST_TOPIC = 'images', 'echo', 'requests'
IMAGE_TYPE, STRING_TYPE = 'sensor_msgs/msg/Image', 'std_msgs/msg/String'
# Echoed strings grow by this many characters: the later ones go over mros2's 100-byte
# buffer, and so out in fragments.
ECHO_GROWTH = 7


@pytest.fixture(scope='module')
def posix_checkout():
    """The user's mros2-posix checkout; skips, saying why, when a run cannot be made."""
    root = os.environ.get('MROS2_POSIX_ROOT')
    problem = mros2_posix.checkout_problem(root)
    if problem:
        pytest.skip(problem)
    if os.geteuid() != 0:
        pytest.skip('needs root for the network namespace')
    if not os.path.isfile(os.path.join(WHEELS_VENV, 'bin', 'python')):
        pytest.skip('no %s (rclpy): run scripts/setup.sh --tests' % WHEELS_VENV)
    return root


@pytest.fixture
def network(posix_checkout):
    pair = mros2_posix.NetworkPair()
    try:
        yield pair.create()
    finally:
        pair.remove()


@pytest.fixture
def start_app(network):
    """Starts a program in the app's namespace; stops it before the namespace goes."""
    started = []

    def start(program, log_path):
        started.append(mros2_posix.AppProcess(program, network.app_namespace, log_path))
        return started[-1]

    yield start
    for app in started:
        app.stop()


@pytest.fixture(scope='module')
def typestore():
    from rosbags.typesys import Stores, get_typestore
    return get_typestore(Stores.ROS2_HUMBLE)


def _requests(typestore, echo_topic, echo_type):
    """(text, serialized String, answer topic, answer type) of the image requests,
    then of the echo requests."""
    string = typestore.types[STRING_TYPE]
    texts = [('image %d' % index, IMAGE_TOPIC, 'Image') for index in range(EXCHANGES)]
    texts += [('echo %d %s' % (index, 'x' * (ECHO_GROWTH * index)), echo_topic,
               echo_type) for index in range(EXCHANGES)]
    return [(text, bytes(typestore.serialize_cdr(string(data=text), STRING_TYPE)), topic,
             type_name) for text, topic, type_name in texts]


def _run_exchange(tmp_path, checkout, network, start_app, typestore, app_options,
                  echo_topic, echo_type):
    """Builds and runs the app, lets the peer ask; returns the requests, the answers'
    bytes (None: not answered) and the peer's report."""
    mros2_posix.write_app(checkout, WHEELS_VENV,
                          publish=['%s:%s' % (IMAGE_TOPIC, IMAGE_TYPE)]
                          + (['%s:%s' % (ECHO_TOPIC, STRING_TYPE)] if echo_type == 'String'
                             else []),
                          subscribe=['%s:%s' % (REQUEST_TOPIC, STRING_TYPE)])
    program, warnings = mros2_posix.build_app(checkout, str(tmp_path / 'build.log'),
                                              app_options)
    assert warnings == []
    app = start_app(program, str(tmp_path / 'app.log'))
    requests = _requests(typestore, echo_topic, echo_type)
    report = mros2_posix.run_peer(WHEELS_VENV, network.peer_namespace, requests,
                                  str(tmp_path / 'ros_log'))
    assert 'app ready' in app.output()
    answers = [bytes.fromhex(answer['sample']) if answer else None
               for answer in report['answers']]
    return requests, answers, report


def _expected_images(typestore):
    return [mros2_posix.wire_bytes(
        typestore, mros2_posix.requested_image(typestore, index, 'image %d' % index),
        IMAGE_TYPE) for index in range(EXCHANGES)]


def _answered(answers, expected):
    """How many answers are the expected bytes; asserts the others are missing."""
    for answer, wanted in zip(answers, expected):
        assert answer is None or answer == wanted, (answer.hex(), wanted.hex())
    return sum(answer == wanted for answer, wanted in zip(answers, expected))


def test_one_publisher_on_the_pinned_mros2(tmp_path, posix_checkout, network, start_app,
                                           typestore):
    checkout = mros2_posix.prepare_checkout(posix_checkout, str(tmp_path / 'mros2-posix'))
    requests, answers, report = _run_exchange(tmp_path, checkout, network, start_app,
                                              typestore, (), IMAGE_TOPIC, 'Image')
    images, echoes = answers[:EXCHANGES], answers[EXCHANGES:]
    assert _answered(images, _expected_images(typestore)) == EXCHANGES
    expected_echoes = [mros2_posix.wire_bytes(
        typestore, mros2_posix.echo_image(typestore, text), IMAGE_TYPE)
        for text, _, _, _ in requests[EXCHANGES:]]
    assert _answered(echoes, expected_echoes) == EXCHANGES
    assert max(len(image) for image in images) > 300
    assert max(len(echo) for echo in echoes) > 100
    print('requests sent: %d for %d answers; answers no request waited for: %d'
          % (sum(answer['sent'] for answer in report['answers']), 2 * EXCHANGES,
             len(report['unmatched'])))


def test_two_publishers_on_patched_mros2(tmp_path, posix_checkout, network, start_app,
                                         typestore):
    mros2_root = os.environ.get('MROS2_ROOT')
    if not mros2_root or not os.path.isfile(os.path.join(mros2_root, 'src', 'mros2.cpp')):
        pytest.skip('MROS2_ROOT is not set to an mros2 v0.5.4 checkout')
    checkout = mros2_posix.prepare_checkout(posix_checkout, str(tmp_path / 'mros2-posix'),
                                            mros2_root)
    requests, answers, report = _run_exchange(
        tmp_path, checkout, network, start_app, typestore,
        ('APP_ECHO_PUBLISHER', 'APP_SETS_RTPS_ADDRESS'), ECHO_TOPIC, 'String')
    images, echoes = answers[:EXCHANGES], answers[EXCHANGES:]
    assert _answered(images, _expected_images(typestore)) == EXCHANGES
    string = typestore.types[STRING_TYPE]
    expected_echoes = [mros2_posix.wire_bytes(typestore, string(data=text), STRING_TYPE)
                       for text, _, _, _ in requests[EXCHANGES:]]
    assert _answered(echoes, expected_echoes) == EXCHANGES
    assert max(len(echo) for echo in echoes) > 100
    print('requests sent: %d for %d answers; answers no request waited for: %d'
          % (sum(answer['sent'] for answer in report['answers']), 2 * EXCHANGES,
             len(report['unmatched'])))
