# SPDX-License-Identifier: BSD-3-Clause
"""The fit check on the real mROS v1 library's settings: genmros mros-v1-pc
refuses before it builds, one line per setting with the value it needs;
mros_v1_fit_check.h refuses in ros.cpp's compile where no genmros check
ran; genmros mros-v1-fit reports; msg_max_size.h carries the needs.
The expected values come from the settings files and rospy's own
definition texts, not from genmros."""

import os
import re
import subprocess

import pytest

from colcon_mros.library_tools.mros_v1.pc_target.build import TARGET_DIR
from colcon_mros.mros_v1.app import app_variables
from testing.ros_graph import PYTHON
from support.checkout import run_genmros
from support.user_checkouts import MROS_V1_ROOT
from support.settings_headers import define
from testing.ros_paths import prefix_arguments, ros1_package_dir, ros1_prefixes

pytestmark = pytest.mark.needs_mros_v1

CUSTOM_PUBSUB = os.path.join(MROS_V1_ROOT, 'mros_ws', 'custom_pubsub')
USR_CONFIG = os.path.join(CUSTOM_PUBSUB, 'mros_config', 'mros_usr_config.h')
PACKET_CONFIG = os.path.join(MROS_V1_ROOT, 'mros-lib', 'mros-src', 'packet', 'cimpl', 'version',
                             'kinetic', 'mros_packet_config.h')


def _full_text_size(type_name):
    package, name = type_name.split('/')
    return int(subprocess.run([PYTHON, '-c', 'from %s.msg import %s as T; '
                               'print(len(T._full_text.encode()))' % (package, name)],
                              capture_output=True, text=True, check=True).stdout)


def test_a_frame_over_the_largest_pool_is_refused_before_the_build(tmp_path):
    options = tmp_path / 'bounds.options'
    options.write_text('std_msgs/String.data max_size:2000\n')
    result = run_genmros('mros-v1-pc', CUSTOM_PUBSUB, '--build-only', '-o',
                         str(tmp_path / 'build'),
                         '--type', 'std_msgs/String', '--storage', 'bounded',
                         '--options', str(options), check=False)
    assert result.returncode == 1
    frame = 4 + 2000  # the string's length, then its bytes
    lines = []
    for pool, use in (('ROS_INNER_TOPIC_PUBLISHER_MEMPOOL3_SIZE', 'publishing'),
                      ('ROS_OUTER_TOPIC_PUBLISHER_MEMPOOL3_SIZE', 'receiving from ROS nodes')):
        value, _, line = define([USR_CONFIG], pool)
        lines.append('genmros: error: %s:%d: std_msgs/String: a frame of up to %d bytes, %s, '
                     'needs %s >= %d (it is %d)' % (USR_CONFIG, line, frame, use, pool, frame + 4,
                                                    value))
    assert result.stderr.splitlines() == lines
    assert not os.path.exists(str(tmp_path / 'build' / 'obj'))


def test_the_sample_fits_and_is_told_how_short_its_names_must_be():
    # custom_pubsub's own type fits the samples' 512-byte header buffers only
    # while its topic and the ROS peer's name are short: a warning, not an error.
    report = run_genmros('mros-v1-fit', CUSTOM_PUBSUB).stdout
    text = _full_text_size_of_user_type()
    request, _, request_line = define([PACKET_CONFIG], 'MROS_PACKET_MAXSIZE_REQ_TCPROS')
    budget = request - (115 + text + len('custom_pubsub/UserTypeTest') + 1)
    row = [line for line in report.splitlines() if line.startswith('| custom_pubsub/UserTypeTest')]
    assert len(row) == 1 and '| names <= %d |' % budget in row[0], report
    assert 'Every type fits.' in report
    assert ('warning: custom_pubsub/UserTypeTest: a ROS subscriber\'s connection header '
            '(definition text %d bytes' % text) in report
    assert ('%s:%d sets %d, which holds it only while the topic and the peer\'s caller id take '
            'at most %d bytes together' % (PACKET_CONFIG, request_line, request, budget)) in report


def _report_row(report, type_name):
    rows = [line.strip('| ').split(' | ') for line in report.splitlines()
            if line.startswith('| %s |' % type_name)]
    assert len(rows) == 1, report
    return rows[0]


def test_the_report_of_the_sample_with_joint_state_before_and_after_the_fix(tmp_path):
    # custom_pubsub with sensor_msgs/JointState added: its 1649-byte
    # definition text is over the samples' 512-byte header buffers. The
    # values the report asks for, set in copies of the settings headers,
    # make every type fit.
    types = ['--type', 'custom_pubsub/UserTypeTest', '--type', 'sensor_msgs/JointState']
    before = run_genmros('mros-v1-fit', CUSTOM_PUBSUB, *types, check=False)
    assert before.returncode == 1, before.stderr
    text = _full_text_size('sensor_msgs/JointState')
    topic_max, _, _ = define([USR_CONFIG], 'MROS_TOPIC_NAME_MAXLEN')
    names = topic_max + 64  # a topic as long as the library allows, a caller id of 64
    request = 115 + text + len('sensor_msgs/JointState') + 1 + names
    reply = 112 + text + len('sensor_msgs/JointState') + names
    row = _report_row(before.stdout, 'sensor_msgs/JointState')
    assert row[1] == str(text)
    assert row[5:9] == ['needs %d' % request, 'needs %d' % reply, 'ok', 'ok'], before.stdout
    assert 'Tables (each type takes a topic per topic name, each ROS peer a connector): ' \
           'MROS_TOPIC_MAX_NUM 20, MROS_NODE_MAX_NUM 10, MROS_PUB_TOPIC_CONNECTOR_MAX_NUM 10, ' \
           'MROS_SUB_TOPIC_CONNECTOR_MAX_NUM 10; this firmware has 2 types.' in before.stdout
    stops = [line for line in before.stdout.splitlines() if line.startswith('error: ')]
    assert [re.sub(r' \(it is .*', '', line.split(': ', 3)[3]) for line in stops] == [
        "a ROS subscriber's connection header (definition text %d bytes, a topic of up to %d "
        'and a caller id of up to 64, and the NUL) needs MROS_PACKET_MAXSIZE_REQ_TCPROS >= %d'
        % (text, topic_max, request),
        "a ROS publisher's connection header needs MROS_PACKET_MAXSIZE_RES_TCPROS >= %d" % reply]

    fixed = tmp_path / 'mros_packet_config.h'
    with open(PACKET_CONFIG) as stream:
        settings = stream.read()
    for name, value in (('MROS_PACKET_MAXSIZE_REQ_TCPROS', request),
                        ('MROS_PACKET_MAXSIZE_RES_TCPROS', reply)):
        settings = re.sub(r'(#define %s\s+)\d+' % name, r'\g<1>%d' % value, settings)
    fixed.write_text(settings)
    after = run_genmros('mros-v1-fit', CUSTOM_PUBSUB, *types, '--mros-v1-settings', USR_CONFIG,
                        '--mros-v1-settings', str(fixed))
    for type_name in ('custom_pubsub/UserTypeTest', 'sensor_msgs/JointState'):
        # Heap storage: no largest frame, so the pools are 'unknown' and warned of.
        assert _report_row(after.stdout, type_name)[5:] == ['ok'] * 4 + ['unknown'] * 2
    assert 'Every type fits.' in after.stdout
    assert after.stdout.count('no largest frame') == 2


def _full_text_size_of_user_type():
    """UserTypeTest's full text as genmsg makes it (what rospy sends) from
    the sample's own .msg."""
    msg_dir = os.path.join(MROS_V1_ROOT, 'ros_catkin_ws', 'src', 'custom_pubsub', 'msg')
    code = ('from genmsg import msg_loader, gentools\n'
            'context = msg_loader.MsgContext.create_default()\n'
            'search = {"custom_pubsub": [%r], "std_msgs": [%r]}\n'
            'spec = msg_loader.load_msg_by_type(context, "custom_pubsub/UserTypeTest", search)\n'
            'msg_loader.load_depends(context, spec, search)\n'
            'print(len(gentools.compute_full_text(context, spec).encode()))\n'
            % (msg_dir, ros1_package_dir('std_msgs')))
    return int(subprocess.run([PYTHON, '-c', code], capture_output=True, text=True,
                              check=True).stdout)


@pytest.mark.parametrize('compiler', [[], ['-U__has_include']],
                         ids=['gcc', 'without __has_include'])
def test_ros_cpp_refuses_to_compile_where_no_genmros_check_ran(tmp_path, compiler):
    # Headers exported without the settings (as a board's make build that
    # never gave genmros the settings would have them); ros.cpp's includes
    # put the library's settings on the path, and the check in the
    # aggregate it includes stops the compile, also with a compiler that has
    # no __has_include (gcc-arm-none-eabi 4.9, which mROS v1's README lists).
    include = str(tmp_path / 'include')
    run_genmros('mros-v1-export', '--type', 'sensor_msgs/JointState', '-o', include,
                *prefix_arguments(ros1_prefixes()))
    source = tmp_path / 'ros_like.cpp'
    # ros.cpp's first two lines.
    source.write_text('#include "ros.h"\n#include "message_headers.h"\nint main() { return 0; }\n')
    # ros.cpp's include path in the PC target's build, as mros_v1_pc.mk has it.
    library = os.path.join(MROS_V1_ROOT, 'mros-lib')
    library_paths = app_variables(os.path.join(library, 'Makefile.m'),
                                  ['MROS_DIR=' + library])['MROS_INCLUDE_PATHS'].split()
    command = (['g++', '-std=gnu++98', '-fsyntax-only'] + compiler
               + ['-I', include, '-I', os.path.join(TARGET_DIR, 'config'),
                  '-I', os.path.join(CUSTOM_PUBSUB, 'mros_config')] + library_paths
               + ['-I', os.path.join(TARGET_DIR, 'asp'), '-I', os.path.join(TARGET_DIR, 'lwip'),
                  '-I', os.path.join(TARGET_DIR, 'mbed'), str(source)])
    refused = subprocess.run(command, capture_output=True, text=True)
    assert refused.returncode != 0
    errors = re.findall(r'error: #error "([^"]*)"', refused.stderr)
    assert errors == [
        "sensor_msgs/JointState: a ROS subscriber's connection header needs "
        "MROS_PACKET_MAXSIZE_REQ_TCPROS >= %d + the topic and caller id's bytes "
        '(mros_packet_config.h)' % (115 + _full_text_size('sensor_msgs/JointState')
                                    + len('sensor_msgs/JointState') + 1),
        "sensor_msgs/JointState: a ROS publisher's connection header needs "
        "MROS_PACKET_MAXSIZE_RES_TCPROS >= %d + the topic and caller id's bytes "
        '(mros_packet_config.h)' % (112 + _full_text_size('sensor_msgs/JointState')
                                    + len('sensor_msgs/JointState'))], refused.stderr
    skipped = subprocess.run(command + ['-DMROS_SKIP_FIT_CHECK'], capture_output=True, text=True)
    assert skipped.returncode == 0, skipped.stderr
