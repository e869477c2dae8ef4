"""The fit check (colcon_mros.export.library_fit, generator.library_needs):
settings read from C headers, one line per misfit, and the connection
header sizes it counts with held against what real rospy and roscpp nodes
send."""

import os
import subprocess

import pytest

from colcon_mros.export.firmware_export import ExportRequest, FirmwareTypes
from colcon_mros.export.library_fit import Fit, read_settings
from colcon_mros.generator.library_needs import (PEER_NAME_MAX, PUBLISHER_HEADER_FIXED,
                                                 SUBSCRIBER_HEADER_FIXED, LibraryNeeds)
from colcon_mros.targets.mros_v1_pc.ros_graph import PYTHON, RosGraph
from conftest import TEST_WS
from mros_v1_checkout import MROS_V1_ROOT
from tcpros_peer import HostilePublisher, RawSubscriber

USR_CONFIG = os.path.join(MROS_V1_ROOT, 'mros_ws', 'custom_pubsub', 'mros_config',
                          'mros_usr_config.h')
PACKET_CONFIG = os.path.join(MROS_V1_ROOT, 'mros-lib', 'mros-src', 'packet', 'cimpl', 'version',
                             'kinetic', 'mros_packet_config.h')


def _needs(*type_names):
    request = ExportRequest(output_dir=None, prefixes=['/usr'], workspaces=[TEST_WS],
                            type_names=type_names)
    return LibraryNeeds(FirmwareTypes(request).firmware_messages)


def _genpy_full_text(type_name):
    """rospy's message_definition of a type: its class's _full_text."""
    package, name = type_name.split('/')
    return subprocess.run([PYTHON, '-c', 'import sys; from %s.msg import %s as T; '
                           'sys.stdout.write(T._full_text)' % (package, name)],
                          capture_output=True, text=True, check=True).stdout


def _header_size(fields):
    """The bytes of a TCPROS connection header after its length."""
    return sum(4 + len(('%s=%s' % item).encode()) for item in fields.items())


def test_settings_are_read_as_the_preprocessor_reads_numbers(tmp_path):
    first = tmp_path / 'first.h'
    first.write_text('#define A 512\n#define B\t50U  /* comment */\n#define C (1024U) // c\n'
                     '#define D A\n#define E "text"\n#define F(x) x\n  #  define G 7\n')
    second = tmp_path / 'second.h'
    second.write_text('#define A 4096\n#define H 3\n')
    settings = read_settings([str(first), str(second)])
    assert {name: (s.value, s.line) for name, s in settings.items()} == {
        'A': (512, 1), 'B': (50, 2), 'C': (1024, 3), 'D': (512, 4), 'G': (7, 7), 'H': (3, 2)}
    assert settings['A'].where() == '%s:1' % first


@pytest.mark.needs_mros_v1
def test_a_long_definition_text_misfits_the_samples_settings_with_one_line_each():
    settings = read_settings([USR_CONFIG, PACKET_CONFIG])
    fit = Fit(_needs('sensor_msgs/JointState', 'std_msgs/String'), settings)
    text = len(_genpy_full_text('sensor_msgs/JointState').encode())
    topic = settings['MROS_TOPIC_NAME_MAXLEN'].value
    # The header's own fields, then the topic and the peer's caller id:
    # the longest the settings allow, and the shortest there are ('/a').
    fields = text + len('sensor_msgs/JointState')
    longest, shortest = topic + PEER_NAME_MAX, 2 + 2
    request = settings['MROS_PACKET_MAXSIZE_REQ_TCPROS']
    reply = settings['MROS_PACKET_MAXSIZE_RES_TCPROS']
    assert [misfit.line() for misfit in fit.misfits] == [
        "%s: sensor_msgs/JointState: a ROS subscriber's connection header (definition text %d "
        'bytes, a topic of up to %d and a caller id of up to %d, and the NUL) needs '
        'MROS_PACKET_MAXSIZE_REQ_TCPROS >= %d (it is %d; even with the shortest topic and caller '
        'id it needs %d)'
        % (request.where(), text, topic, PEER_NAME_MAX, SUBSCRIBER_HEADER_FIXED + fields + longest
           + 1, request.value, SUBSCRIBER_HEADER_FIXED + fields + shortest + 1),
        "%s: sensor_msgs/JointState: a ROS publisher's connection header needs "
        'MROS_PACKET_MAXSIZE_RES_TCPROS >= %d (it is %d; even with the shortest topic and caller '
        'id it needs %d)'
        % (reply.where(), PUBLISHER_HEADER_FIXED + fields + longest, reply.value,
           PUBLISHER_HEADER_FIXED + fields + shortest)]
    # Heap storage gives neither type a largest frame: a warning each, not an error.
    assert [warning.split(':')[0] for warning in fit.warnings] == [
        'sensor_msgs/JointState', 'std_msgs/String']


SUBSCRIBER_NODE = '''
import rospy
from sensor_msgs.msg import JointState
rospy.init_node('fit_probe_listener')
rospy.Subscriber('/fit_probe', JointState, lambda message: None)
rospy.spin()
'''
PUBLISHER_NODE = '''
import rospy
from sensor_msgs.msg import JointState
rospy.init_node('fit_probe_talker')
publisher = rospy.Publisher('/fit_probe', JointState, queue_size=1)
rospy.spin()
'''


@pytest.mark.slow
def test_the_header_sizes_are_those_rospy_and_roscpp_send(ros_workspace):
    joint_state = _needs('sensor_msgs/JointState').types[0]
    with RosGraph(ros_workspace.environment()) as graph:
        # A rospy subscriber's header, as a publisher receives it.
        with HostilePublisher(graph, '/fit_probe_publisher', '/fit_probe',
                              'sensor_msgs/JointState') as publisher:
            graph.start('rospy subscriber', [PYTHON, '-c', SUBSCRIBER_NODE])
            connection, fields = publisher.accept(timeout=30)
            connection.close()
        assert len(fields['message_definition'].encode()) == joint_state.text_bytes
        assert _header_size(fields) == SUBSCRIBER_HEADER_FIXED + sum(
            len(fields[key].encode()) for key in ('topic', 'type', 'callerid', 'message_definition'))
        # A rospy and a roscpp publisher's replies, as a subscriber receives them.
        graph.start('rospy publisher', [PYTHON, '-c', PUBLISHER_NODE])
        graph.start('roscpp publisher', ros_workspace.roscpp('personal_data_talker'))
        graph.wait_for_graph(publishers=[('/fit_probe', '/fit_probe_talker'),
                                         ('/test_msg', '/ros_personal_talker')])
        personal_data = _needs('mros_test/PersonalData').types[0]
        for node, topic, needed in (('/fit_probe_talker', '/fit_probe', joint_state),
                                    ('/ros_personal_talker', '/test_msg', personal_data)):
            code, _, slave_uri = graph.master_proxy().lookupNode('/test', node)
            assert code == 1
            subscriber = RawSubscriber(slave_uri, topic, needed.full_name, '*')
            fields = subscriber.header
            subscriber.close()
            assert len(fields['message_definition'].encode()) == needed.text_bytes, node
            assert _header_size(fields) == PUBLISHER_HEADER_FIXED + sum(
                len(fields[key].encode())
                for key in ('topic', 'type', 'callerid', 'message_definition')), node
