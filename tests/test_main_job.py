# SPDX-License-Identifier: BSD-3-Clause
"""The README's main command's driver (evaluation/run.py) as it runs, with
this checkout installed (tests/support/checkout_install.py): every step of the main
job passes and its table says so, ROS 1's and then ROS 2's, with no mROS
checkout; with the user's (MROS_V1_ROOT), the paper's five directions on the
real library pass too, within the board's task stacks."""

import re

import pytest

from support.main_job import ROS2_ROWS, run_main_job
from support.user_checkouts import MROS_V1_ROOT
from testing.ros_paths import KILTED_WHEELS

pytestmark = [pytest.mark.slow, pytest.mark.needs_qemu]

ROWS = [
    'catkin_make of test_ws (genmros beside gencpp and genpy)',
    'colcon build --mros-export of the same packages',
    'firmware (CMake, mros_import_messages) for 32-bit ARM Linux (arm-linux-gnueabihf-g++, '
    'static)',
    'firmware (CMake, mros_import_messages) for Cortex-M0 (arm-none-eabi-g++, newlib nano)',
    'firmware (CMake, mros_import_messages) for Cortex-M4F (arm-none-eabi-g++, newlib nano)',
    'TCPROS connection header of the board',
    'board -> rospy listener',
    'board -> roscpp listener',
    'rospy talker -> board',
    'roscpp talker -> board',
    'rospy -> board -> rospy, byte for byte',
    'rospy -> board -> roscpp -> board -> rospy, byte for byte',
]
MROS_V1_ROWS = [
    'the evaluation app on the mROS v1 library of %s (genmros mros-v1-pc)' % MROS_V1_ROOT,
    'mROS v1 -> rospy listener',
    'mROS v1 -> roscpp listener',
    'mROS v1 -> mROS v1 on board',
    'rospy talker -> mROS v1',
    'roscpp talker -> mROS v1',
]
SYNC_ROW = 'in sync by construction: a field added, catkin_make, firmware rebuilt'


def _main_job(tmp_path, mros_v1_root):
    """What the main job printed, and its table's rows as (step, verdict)."""
    return run_main_job(tmp_path / 'build', ['--messages', '5'],
                        {'MROS_V1_ROOT': mros_v1_root} if mros_v1_root else {})


def test_the_main_job_needs_no_mros(tmp_path):
    output, rows = _main_job(tmp_path, '')
    assert rows == [(row, 'PASS') for row in ROWS + [SYNC_ROW] + ROS2_ROWS], output
    assert 'ROS 2: the ROS 2 wheels of %s\n' % KILTED_WHEELS in output
    assert 'frames carried between qemu-arm and the ROS graph by evaluation/board_bridge.py' \
        in output
    assert 'samples carried between qemu-arm and the ROS 2 graph by evaluation/ros2_bridge.py' \
        in output
    assert len(re.findall(r'^  PASS: \w+: 20 of 20 samples came, 20 byte for byte as '
                          r'(?:rosbags|rclpy) ', output, re.M)) == 6, output
    # Each firmware's sizes (ROS 1's three, mros2's two), and what the fields added did.
    assert len(re.findall(r'^  PASS \(\d+ s\): flash \d+ B \(text \d+ \+ data \d+\), static RAM '
                          r'\d+ B', output, re.M)) == 5, output
    assert "field 'uint32 sequence_number' added to Reading.msg: in the firmware's reading.hpp " \
        "and in rclpy's Reading" in output
    assert 'the real mros2-posix app was not run: MROS2_POSIX_ROOT is not set' in output
    assert re.search(r"field 'float32 height_m' added: PersonalData's MD5 db8764b0 -> \w{8} in "
                     r"the firmware, equal to rospy's", output), output
    assert ("the paper's evaluation on your mROS v1 library was not run: MROS_V1_ROOT is not "
            'set.') in output


@pytest.mark.needs_mros_v1
def test_the_main_job_runs_the_papers_evaluation_on_the_users_library(tmp_path):
    output, rows = _main_job(tmp_path, MROS_V1_ROOT)
    assert rows == [(row, 'PASS') for row in ROWS + MROS_V1_ROWS + [SYNC_ROW] + ROS2_ROWS], \
        output
    # Within the board's stacks (an overflow would have stopped the board),
    # every task of app.cfg and the library's mros.cfg reported.
    stacks = re.findall(r'(\w+) (\d+) of (\d+)', output.split(
        "the board's task stacks, the deepest of its runs (bytes): ")[1].splitlines()[0])
    assert sorted(task for task, _, _ in stacks) == [
        'MAIN_TASK', 'PUB_TASK', 'SUB_TASK', 'USR_TASK1', 'USR_TASK2', 'XML_MAS_TASK',
        'XML_SLV_TASK'], output
    assert all(64 <= int(peak) <= int(size) for _, peak, size in stacks), stacks
