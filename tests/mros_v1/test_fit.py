# SPDX-License-Identifier: BSD-3-Clause
"""The fit check (colcon_mros.mros_v1.fit, rules): one line per misfit and
the warnings, against the small settings headers in
tests/fixtures/mros_v1_settings and the real library's; the connection
header sizes it counts with held against what real rospy and roscpp nodes
send. The expected values come from the settings files and rospy's own
definition texts, not from genmros."""

import os
import subprocess

import pytest

from colcon_mros.core.settings import read_settings
from colcon_mros.errors import GenmrosProblems
from colcon_mros.export.firmware_export import firmware_messages
from colcon_mros.mros_v1.fit import Fit
from colcon_mros.mros_v1.rules import (PEER_NAME_MAX, PUBLISHER_HEADER_FIXED,
                                       SUBSCRIBER_HEADER_FIXED, FirmwareNeeds)
from testing.ros_paths import ros1_package_dir, ros1_prefixes
from testing.ros_graph import PYTHON, RosGraph
from testing.tcpros_peer import HostilePublisher, RawSubscriber
from support.checkout import TEST_WS
from support.user_checkouts import MROS_V1_ROOT
from support.settings_headers import define, header_paths, small_settings

USR_CONFIG = os.path.join(MROS_V1_ROOT, 'mros_ws', 'custom_pubsub', 'mros_config',
                          'mros_usr_config.h')
PACKET_CONFIG = os.path.join(MROS_V1_ROOT, 'mros-lib', 'mros-src', 'packet', 'cimpl', 'version',
                             'kinetic', 'mros_packet_config.h')


def _messages(*type_names, storage='heap', option_files=()):
    return firmware_messages(type_names, [TEST_WS] + ros1_prefixes(), storage, option_files)


def _needs(*type_names):
    return FirmwareNeeds(_messages(*type_names))


def _where(define):
    """(value, 'FILE:LINE') of settings_headers.define's answer."""
    value, path, line = define
    return value, '%s:%d' % (path, line)


def _genpy_full_text(type_name):
    """rospy's message_definition of a type: its class's _full_text."""
    package, name = type_name.split('/')
    return subprocess.run([PYTHON, '-c', 'import sys; from %s.msg import %s as T; '
                           'sys.stdout.write(T._full_text)' % (package, name)],
                          capture_output=True, text=True, check=True).stdout


def _genmsg_full_text(type_name):
    """genmsg's full text of a test_ws type, what genpy and gencpp carry."""
    from genmsg import gentools, msg_loader
    search = {'std_msgs': [ros1_package_dir('std_msgs')]}
    for package in ('mros_test', 'mros_test_base'):
        search[package] = [os.path.join(TEST_WS, 'src', package, 'msg')]
    context = msg_loader.MsgContext.create_default()
    spec = msg_loader.load_msg_by_type(context, type_name, search)
    msg_loader.load_depends(context, spec, search)
    return gentools.compute_full_text(context, spec)


def _header_size(fields):
    """The bytes of a TCPROS connection header after its length."""
    return sum(4 + len(('%s=%s' % item).encode()) for item in fields.items())


def test_a_type_name_fits_the_name_fields_up_to_the_last_byte():
    settings = header_paths(small_settings())
    typename_max, where = _where(define(settings, 'MROS_TOPIC_TYPENAME_MAXLEN'))
    assert len('mros_test_base/Vector3i') + 1 == typename_max
    fit = Fit(_messages('mros_test_base/Vector3i', 'geometry_msgs/Quaternion'),
              read_settings(settings))
    assert [misfit.line() for misfit in fit.misfits] == [
        '%s: geometry_msgs/Quaternion: its name with its NUL needs MROS_TOPIC_TYPENAME_MAXLEN '
        '>= %d (it is %d)' % (where, len('geometry_msgs/Quaternion') + 1, typename_max)]


def test_a_bounded_frame_needs_the_largest_pool_within_the_pool_count(tmp_path):
    settings = header_paths(small_settings())
    publishing, _, _ = define(settings, 'ROS_INNER_TOPIC_PUBLISHER_MEMPOOL2_SIZE')
    receiving, receiving_at = _where(define(settings, 'ROS_OUTER_TOPIC_PUBLISHER_MEMPOOL1_SIZE'))
    # A string of up to n bytes: its 4-byte length and n bytes, in a block
    # with the library's 4-byte frame header.
    options = tmp_path / 'bounds.options'
    for size in (receiving - 8, publishing - 8):
        options.write_text('std_msgs/String.data max_size:%d\n' % size)
        fit = Fit(_messages('std_msgs/String', storage='bounded', option_files=[str(options)]),
                  read_settings(settings))
        assert [misfit.line() for misfit in fit.misfits] == ([] if size == receiving - 8 else [
            '%s: std_msgs/String: a frame of up to %d bytes, receiving from ROS nodes, needs '
            'ROS_OUTER_TOPIC_PUBLISHER_MEMPOOL1_SIZE >= %d (it is %d)'
            % (receiving_at, size + 4, size + 8, receiving)])
        assert fit.warnings == []
    # One byte more than the second publishing pool: the third, beyond
    # ROS_INNER_TOPIC_PUBLISHER_CONFIG_NUM, does not count.
    options.write_text('std_msgs/String.data max_size:%d\n' % (publishing - 7))
    fit = Fit(_messages('std_msgs/String', storage='bounded', option_files=[str(options)]),
              read_settings(settings))
    assert [misfit.setting.name for misfit in fit.misfits] == [
        'ROS_INNER_TOPIC_PUBLISHER_MEMPOOL2_SIZE', 'ROS_OUTER_TOPIC_PUBLISHER_MEMPOOL1_SIZE']


def test_the_publishing_blocks_need_a_frame_slot_each_where_the_library_passes_no_size(tmp_path):
    # The small settings' two publishing pools hold 16 + 8 blocks, within
    # on-board delivery's 32 slots; with 17 + 16 there is one block too many.
    messages = _messages('std_msgs/String')
    assert Fit(messages, read_settings(header_paths(small_settings())),
               frame_table=True).misfits == []
    settings = header_paths(small_settings(tmp_path / 'more',
                                           ROS_INNER_TOPIC_PUBLISHER_MEMPOOL1_QUELEN=17,
                                           ROS_INNER_TOPIC_PUBLISHER_MEMPOOL2_QUELEN=16))
    _, path, line = define(settings, 'ROS_INNER_TOPIC_PUBLISHER_MEMPOOL2_QUELEN')
    expected = ("%s:%d: the publishing pools hold 33 blocks "
                '(ROS_INNER_TOPIC_PUBLISHER_MEMPOOL1_QUELEN 17, '
                'ROS_INNER_TOPIC_PUBLISHER_MEMPOOL2_QUELEN 16), each of which can hold a frame '
                'waiting for on-board delivery: MROS_ONBOARD_FRAME_SLOTS needs >= 33 '
                "in every file (it is not defined: mros_v1_delivery.h's default is 32), "
                "or the library passes the frame's size (genmros' patch set)" % (path, line))
    as_is = Fit(messages, read_settings(settings), frame_table=True)
    assert [misfit.line() for misfit in as_is.misfits] == [expected]
    with pytest.raises(GenmrosProblems) as refused:
        as_is.refuse()
    assert str(refused.value) == expected
    # The patched library keeps no table; a library not known here gets a warning.
    assert Fit(messages, read_settings(settings), frame_table=False).misfits == []
    unknown = Fit(messages, read_settings(settings))
    assert (unknown.misfits, unknown.warnings[-1:]) == (
        [], [expected + ' (whether this library does, is not known here)'])
    # The firmware's own MROS_ONBOARD_FRAME_SLOTS, read where it is set.
    with open(settings[0], 'a') as stream:
        stream.write('#define MROS_ONBOARD_FRAME_SLOTS 33\n')
    assert Fit(messages, read_settings(settings), frame_table=True).misfits == []


def test_a_connection_header_fits_for_certain_only_with_room_for_the_shortest_names(tmp_path):
    text = len(_genmsg_full_text('mros_test/PersonalData').encode())
    subscriber = SUBSCRIBER_HEADER_FIXED + text + len('mros_test/PersonalData') + 1
    publisher = PUBLISHER_HEADER_FIXED + text + len('mros_test/PersonalData')
    topic_max, _, _ = define(header_paths(small_settings()), 'MROS_TOPIC_NAME_MAXLEN')
    # Room for '/a' and '/a' exactly: fits, with a warning of how short the
    # names must be; one byte less: refused, with the value for the longest names.
    settings = header_paths(small_settings(
        tmp_path / 'settings', MROS_PACKET_MAXSIZE_REQ_TCPROS=subscriber + 4,
        MROS_PACKET_MAXSIZE_RES_TCPROS=publisher + 3))
    request, request_at = _where(define(settings, 'MROS_PACKET_MAXSIZE_REQ_TCPROS'))
    reply, reply_at = _where(define(settings, 'MROS_PACKET_MAXSIZE_RES_TCPROS'))
    fit = Fit(_messages('mros_test/PersonalData'), read_settings(settings))
    assert [misfit.line() for misfit in fit.misfits] == [
        "%s: mros_test/PersonalData: a ROS publisher's connection header needs "
        'MROS_PACKET_MAXSIZE_RES_TCPROS >= %d (it is %d; even with the shortest topic and caller '
        'id it needs %d)'
        % (reply_at, publisher + topic_max + PEER_NAME_MAX, reply, publisher + 4)]
    assert fit.warnings[0] == (
        "mros_test/PersonalData: a ROS subscriber's connection header (definition text %d bytes, "
        'a topic of up to %d and a caller id of up to %d, and the NUL) needs '
        "MROS_PACKET_MAXSIZE_REQ_TCPROS >= %d; %s sets %d, which holds it only while the topic "
        "and the peer's caller id take at most 4 bytes together"
        % (text, topic_max, PEER_NAME_MAX, subscriber + topic_max + PEER_NAME_MAX, request_at,
           request))
    assert fit.warnings[1].startswith('mros_test/PersonalData: no largest frame')
    with pytest.raises(GenmrosProblems) as refused:
        fit.refuse(strict=True)
    assert str(refused.value).splitlines() == [fit.misfits[0].line()] + fit.warnings


def test_settings_without_a_rule_s_setting_are_named(tmp_path):
    header = tmp_path / 'mros_usr_config.h'
    header.write_text('#define MROS_TOPIC_NAME_MAXLEN 32\n')
    with pytest.raises(Exception) as refused:
        Fit(_messages('std_msgs/String'), read_settings([str(header)]))
    assert str(refused.value) == (
        "the mROS v1 settings given define no MROS_PACKET_MAXSIZE_REQ_TCPROS (give the "
        "library's mros_packet_config.h and the app's mros_usr_config.h)")


@pytest.mark.parametrize('headers', [
    pytest.param(lambda: header_paths(small_settings()), id='small settings'),
    pytest.param(lambda: [USR_CONFIG, PACKET_CONFIG], id='the samples\' settings',
                 marks=pytest.mark.needs_mros_v1)])
def test_a_long_definition_text_misfits_with_one_line_each(headers):
    settings = read_settings(headers())
    fit = Fit(_messages('sensor_msgs/JointState', 'std_msgs/String'), settings)
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
            len(fields[key].encode())
            for key in ('topic', 'type', 'callerid', 'message_definition'))
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
