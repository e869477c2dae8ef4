# SPDX-License-Identifier: BSD-3-Clause
"""The ROS 2 main job: a colcon build of ROS 2 interface packages gives an
mros2 firmware every type it uses, in the same build.

A fresh copy of test_ws_ros2 (mros2_base_msgs, and mros2_test_msgs, whose
Reading contains mros2_base_msgs/Stamp) is built with ``colcon build
--mros-export DIR`` as a Debian user builds it, with this checkout installed
as a user installs it (the rosidl generator, the colcon extension and the
CMake package from that install). Then a firmware's CMake project imports
DIR/mros2 with mros2_import_messages(), builds against the stand-in of
mros2's runtime calls (testing/mros2_runtime) and publishes a Reading whose
bytes Fast-CDR reads. A field added to Reading.msg reaches the export and
the firmware with the next builds. The steps share one workspace and run in
file order.
"""

import os
import shutil

import pytest

from support.checkout import REPO
from support.build_integration import run, unwrapped
from testing import fastcdr

pytestmark = pytest.mark.slow

TEST_WS_ROS2 = os.path.join(REPO, 'test_ws_ros2')
RUNTIME = os.path.join(REPO, 'testing', 'mros2_runtime')

FIRMWARE_CMAKE = '''cmake_minimum_required(VERSION 3.16)
project(firmware CXX)
set(CMAKE_CXX_STANDARD 14)
find_package(genmros REQUIRED)
add_executable(firmware main.cpp {runtime}/mros2_runtime_check.cpp)
target_include_directories(firmware PRIVATE {runtime})
target_compile_options(firmware PRIVATE -Wall -Wextra -Werror)
mros2_import_messages(TARGET firmware EXPORT_DIR {export}
                      PUBLISH reading:mros2_test_msgs/msg/Reading
                      SUBSCRIBE stamp:mros2_base_msgs/msg/Stamp
                      TYPES mros2_test_msgs/srv/Query RTPS_CONFIG rtps/config.h
                      RECEIVE_LIMIT lwip/udp_limits.h:MAX_RECV_PACKET_SIZE)
'''
# The board's rtps/config.h as embeddedRTPS writes its configs; mros2-posix'
# keeps type names in 40 bytes.
RTPS_CONFIG = '''namespace rtps {
namespace Config {
const uint8_t NUM_STATELESS_WRITERS = 3;
const uint8_t NUM_STATELESS_READERS = 3;
const uint8_t NUM_WRITERS_PER_PARTICIPANT = 4;
const uint8_t NUM_READERS_PER_PARTICIPANT = 4;
const uint8_t MAX_TYPENAME_LENGTH = 40;
const uint8_t MAX_TOPICNAME_LENGTH = 20;
}
}
'''
FIRMWARE_MAIN = r'''#include <stdio.h>
#include "mros2.h"
#include "mros2_test_msgs/msg/reading.hpp"
#include "mros2_test_msgs/srv/query.hpp"

int main() {
  mros2::Node node;
  mros2::Publisher pub = node.create_publisher<mros2_test_msgs::msg::Reading>("reading", 10);
  mros2_test_msgs::msg::Reading reading;
  reading.stamp.sec = 7;
  reading.sensor = "imu";
  reading.samples.push_back(-3);
  NEW_FIELD_LINE
  pub.publish(reading);
  printf("%s\n", g_type_name);
  for (uint32_t i = 0; i < g_sent_size; ++i) printf("%02x", g_sent[i]);
  printf("\n");
  mros2_test_msgs::srv::Query::Request request;
  (void)request;
  return 0;
}
'''


class Ros2Workspace:
    def __init__(self, root):
        # The firmware beside the workspace: colcon would build it as a package.
        self.root = os.path.join(root, 'ws')
        shutil.copytree(os.path.join(TEST_WS_ROS2, 'src'), os.path.join(self.root, 'src'))
        self.export_dir = os.path.join(self.root, 'mros_export')
        self.firmware = os.path.join(root, 'firmware')
        os.makedirs(self.firmware)
        with open(os.path.join(self.firmware, 'CMakeLists.txt'), 'w') as stream:
            stream.write(FIRMWARE_CMAKE.format(runtime=RUNTIME, export=self.export_dir))
        self.write_config(RTPS_CONFIG)
        self.write_receive_limit(4096)
        self.write_main('')

    def write_receive_limit(self, size):
        """The port's setting, as lwip-posix' udp.c has it."""
        os.makedirs(os.path.join(self.firmware, 'lwip'), exist_ok=True)
        with open(os.path.join(self.firmware, 'lwip', 'udp_limits.h'), 'w') as stream:
            stream.write('#define MAX_RECV_PACKET_SIZE %d\n' % size)

    def write_config(self, text):
        os.makedirs(os.path.join(self.firmware, 'rtps'), exist_ok=True)
        with open(os.path.join(self.firmware, 'rtps', 'config.h'), 'w') as stream:
            stream.write(text)

    def write_main(self, new_field_line):
        with open(os.path.join(self.firmware, 'main.cpp'), 'w') as stream:
            stream.write(FIRMWARE_MAIN.replace('NEW_FIELD_LINE', new_field_line))

    def colcon_build(self):
        return run(['colcon', 'build', '--event-handlers', 'console_direct+', '--mros-export',
                    self.export_dir], self.root)

    def build_firmware(self):
        build = os.path.join(self.firmware, 'build')
        if not os.path.isdir(build):
            run(['cmake', '-S', self.firmware, '-B', build], self.root)
        run(['cmake', '--build', build], self.root)
        return run([os.path.join(build, 'firmware')], self.root).stdout.split()


@pytest.fixture(scope='module')
def workspace(tmp_path_factory):
    workspace = Ros2Workspace(str(tmp_path_factory.mktemp('ros2_main_job')))
    workspace.colcon_build()
    return workspace


def test_the_export_holds_the_built_types_and_their_definitions(workspace):
    mros2 = os.path.join(workspace.export_dir, 'mros2')
    for relative in ('include/mros2_test_msgs/msg/reading.hpp',
                     'include/mros2_test_msgs/srv/query.hpp',
                     'include/mros2_base_msgs/msg/stamp.hpp',
                     'include/mros2_message_wire.hpp', 'include/mros_message_containers.h',
                     'share/mros2_test_msgs/msg/Reading.msg',
                     'share/mros2_test_msgs/srv/Query.srv',
                     'share/mros2_base_msgs/msg/Stamp.msg', 'share/mros2_test_msgs/package.xml',
                     'share/ament_index/resource_index/packages/mros2_base_msgs'):
        assert os.path.isfile(os.path.join(mros2, relative)), relative


def test_the_firmware_publishes_what_fastcdr_writes(workspace, tmp_path):
    type_name, sent = workspace.build_firmware()
    assert type_name == 'mros2_test_msgs::msg::dds_::Reading_'
    program = fastcdr.build(str(tmp_path / 'fastcdr'))
    # stamp (sec, nanosec), sensor, position[3], samples[], scale (default 1.5)
    expected = fastcdr.encode(program, [
        ('int32', 7), ('uint32', 0), ('string', b'imu'), ('float32', 0.0), ('float32', 0.0),
        ('float32', 0.0), ('count', 1), ('int16', -3), ('float64', 1.5)])
    assert bytes.fromhex(sent) == expected + bytes(-len(expected) % 4)


def test_a_field_added_reaches_the_export_and_the_firmware(workspace):
    with open(os.path.join(workspace.root, 'src', 'mros2_test_msgs', 'msg', 'Reading.msg'),
              'a') as stream:
        stream.write('uint32 sequence_number\n')
    workspace.colcon_build()
    with open(os.path.join(workspace.export_dir, 'mros2', 'include', 'mros2_test_msgs', 'msg',
                           'reading.hpp')) as stream:
        assert 'uint32_t sequence_number = 0u;' in stream.read()
    workspace.write_main('reading.sequence_number = 0x01020304u;')
    _, sent = workspace.build_firmware()
    assert sent.endswith('04030201')


def test_the_export_dirs_mros2_half_is_refused_naming_its_parent(workspace, tmp_path):
    firmware = tmp_path / 'firmware'
    shutil.copytree(workspace.firmware, str(firmware), ignore=shutil.ignore_patterns('build'))
    half = os.path.join(workspace.export_dir, 'mros2')
    cmake = firmware / 'CMakeLists.txt'
    cmake.write_text(cmake.read_text().replace('EXPORT_DIR %s' % workspace.export_dir,
                                               'EXPORT_DIR %s' % half))
    result = run(['cmake', '-S', str(firmware), '-B', str(firmware / 'build')], workspace.root,
                 check=False)
    assert result.returncode != 0
    assert ("mros2_import_messages(): EXPORT_DIR '%s' is the mros2 half of an export dir: give "
            "the dir colcon build --mros-export wrote, '%s'" % (half, workspace.export_dir)) \
        in unwrapped(result.stdout), result.stdout[-3000:]


def test_bad_topic_names_stop_the_configure_step_one_line_each(workspace, tmp_path):
    firmware = tmp_path / 'firmware'
    shutil.copytree(workspace.firmware, str(firmware), ignore=shutil.ignore_patterns('build'))
    cmake = firmware / 'CMakeLists.txt'
    cmake.write_text(cmake.read_text().replace(
        'PUBLISH reading:mros2_test_msgs/msg/Reading',
        'PUBLISH 9reading:mros2_test_msgs/msg/Reading').replace(
        'SUBSCRIBE stamp:mros2_base_msgs/msg/Stamp', 'SUBSCRIBE st-amp:mros2_base_msgs/msg/Stamp'))
    result = run(['cmake', '-S', str(firmware), '-B', str(firmware / 'build')], workspace.root,
                 check=False)
    assert result.returncode != 0
    output = unwrapped(result.stdout)
    assert ("--publish topic '9reading' (in '9reading:mros2_test_msgs/msg/Reading'): ROS 2 "
            "refuses a name with '9reading' starting with a digit, so no ROS node would match "
            'it') in output, result.stdout[-3000:]
    assert ("--subscribe topic 'st-amp' (in 'st-amp:mros2_base_msgs/msg/Stamp'): ROS 2 refuses "
            "a name with '-' (a ROS 2 name holds only A-Z, a-z, 0-9, _ and /), so no ROS node "
            'would match it') in output
    assert not (firmware / 'build' / 'mros2_messages').exists()


def test_a_board_config_too_small_stops_the_configure_step(workspace):
    """The fit check runs in mros2_import_messages(); the config is a
    configure dependency, so editing it configures again."""
    workspace.write_config(RTPS_CONFIG.replace(
        'MAX_TYPENAME_LENGTH = 40', 'MAX_TYPENAME_LENGTH = 30'))
    try:
        result = run(['cmake', '--build', os.path.join(workspace.firmware, 'build')],
                     workspace.root, check=False)
    finally:
        workspace.write_config(RTPS_CONFIG)
    assert result.returncode != 0
    config = os.path.join(workspace.firmware, 'rtps', 'config.h')
    for name, needed in (('mros2_base_msgs::msg::dds_::Stamp_', 35),
                         ('mros2_test_msgs::msg::dds_::Reading_', 37)):
        assert ('%s:7: %s: its DDS type name and its NUL needs MAX_TYPENAME_LENGTH >= %d (it is '
                '30)' % (config, name, needed)) in unwrapped(result.stdout), result.stdout[-3000:]
    workspace.build_firmware()


def test_a_receive_limit_too_small_stops_the_configure_step(workspace):
    """RECEIVE_LIMIT FILE:NAME, FILE relative to the project as the config is,
    and a configure dependency too: Stamp's samples need 84 bytes a datagram."""
    workspace.write_receive_limit(80)
    try:
        result = run(['cmake', '--build', os.path.join(workspace.firmware, 'build')],
                     workspace.root, check=False)
    finally:
        workspace.write_receive_limit(4096)
    assert result.returncode != 0
    limits = os.path.join(workspace.firmware, 'lwip', 'udp_limits.h')
    assert ('%s:1: mros2_base_msgs/msg/Stamp: a sample of up to 8 bytes in one datagram, RTPS '
            'around it needs MAX_RECV_PACKET_SIZE >= 84 (it is 80)' % limits) \
        in unwrapped(result.stdout), result.stdout[-3000:]
    workspace.build_firmware()


def test_a_service_and_a_client_count_in_the_fit_check(workspace, tmp_path):
    """SERVE and CALL reach genmros: each service and client takes a reliable writer and a
    reliable reader of the board's, which the config must hold beside SEDP's."""
    firmware = tmp_path / 'firmware'
    shutil.copytree(workspace.firmware, str(firmware), ignore=shutil.ignore_patterns('build'))
    cmake = firmware / 'CMakeLists.txt'
    cmake.write_text(cmake.read_text().replace(
        'TYPES mros2_test_msgs/srv/Query',
        'SERVE query:mros2_test_msgs/srv/Query CALL ask:mros2_test_msgs/srv/Query'))
    config = firmware / 'rtps' / 'config.h'
    config.write_text(config.read_text().replace(
        '}\n}\n', 'const uint8_t NUM_STATEFUL_WRITERS = 3;\n'
                  'const uint8_t NUM_STATEFUL_READERS = 4;\n'
                  'const uint8_t HISTORY_SIZE_STATEFUL = 10;\n}\n}\n'))
    result = run(['cmake', '-S', str(firmware), '-B', str(firmware / 'build')], workspace.root,
                 check=False)
    assert result.returncode != 0
    assert ("%s:9: the firmware: its 2 writers of services and clients (one each), reliable, "
            "and the participant's 2 SEDP ones needs NUM_STATEFUL_WRITERS >= 4 (it is 3)"
            % config) in unwrapped(result.stdout), result.stdout[-3000:]
    assert 'NUM_STATEFUL_READERS' not in unwrapped(result.stdout)
