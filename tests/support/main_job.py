# SPDX-License-Identifier: BSD-3-Clause
"""The main job (evaluation/run.py) as the README's command runs it, with
this checkout installed (support/checkout_install.py), and the rows its
table has."""

import os
import re
import subprocess
import sys

from support.checkout import REPO
from support.checkout_install import checkout_install
from testing.ros_paths import ROS2_WHEELS_VARIABLE

ROS2_ROWS = [
    "ROS 2: colcon build --mros-export of test_ws_ros2 (the ROS 2 wheels' "
    'rosidl_default_generators and the mros2 generator)',
    'ROS 2: firmware (CMake, mros2_import_messages) for 32-bit ARM Linux '
    '(arm-linux-gnueabihf-g++, static)',
    'ROS 2: firmware (CMake, mros2_import_messages) for Cortex-M4F (arm-none-eabi-g++, newlib '
    'nano)',
    "ROS 2: the fit check's verdict (genmros mros2-fit, the board's endpoints)",
    'ROS 2: board -> rclpy: chatter',
    'ROS 2: board -> rclpy: image',
    'ROS 2: board -> rclpy: reading',
    'ROS 2: rclpy -> board -> rclpy: command_echo',
    'ROS 2: rclpy -> board -> rclpy: twist_echo',
    'ROS 2: rclpy -> board -> rclpy: reading_in_echo',
    'ROS 2: in sync by construction: a field added, colcon build, firmware rebuilt',
]
# What else in the environment the main job would use: the user's checkouts, and another
# venv of ROS 2 wheels.
MAIN_JOB_VARIABLES = ('MROS_V1_ROOT', 'MROS2_ROOT', 'MROS2_POSIX_ROOT', ROS2_WHEELS_VARIABLE)
TABLE_ROW = re.compile(r'^(.*?) {2,}(PASS|FAIL.*)$')


def run_main_job(build_dir, arguments, variables):
    """The main job with arguments, in an environment with none of
    MAIN_JOB_VARIABLES but those in variables ({name: value}); it must pass.
    What it printed, and its table's rows as (step, verdict)."""
    environment = checkout_install().environment(os.environ)
    for variable in MAIN_JOB_VARIABLES:
        environment.pop(variable, None)
    environment.update(variables)
    result = subprocess.run([sys.executable, os.path.join(REPO, 'evaluation', 'run.py'),
                             '--build-dir', str(build_dir)] + list(arguments),
                            env=environment, capture_output=True, text=True, timeout=1200)
    table = result.stdout.split('==== the main job ====\n')[-1].splitlines()
    assert table[-1] == 'RESULT: PASS' and result.returncode == 0, result.stdout[-5000:]
    return result.stdout, [TABLE_ROW.match(line).groups() for line in table[:-1]]
