#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# The main job (evaluation/run.py), on a fresh Debian 12 machine: installs
# what is needed (scripts/setup.sh --tests), builds test_ws with catkin_make
# (genmros beside gencpp and genpy, writing the export dir) and with colcon
# build --mros-export, builds a firmware's CMake project on that export for
# 32-bit ARM Linux, Cortex-M0 and Cortex-M4, runs the ARM program under
# qemu-arm against a real rosmaster and rospy and roscpp nodes, and shows that
# a field added to a message reaches the firmware through the next builds.
# Then the same for ROS 2 and mros2: colcon build --mros-export of
# test_ws_ros2 with the ROS 2 wheels' rosidl, an mros2 firmware's CMake
# project (mros2_import_messages()) for 32-bit ARM Linux and Cortex-M4F, the
# fit check's verdict, the ARM program under qemu-arm with real rclpy nodes
# (samples byte for byte both ways), and a field added. With MROS_V1_ROOT naming the user's mROS v1 checkout it also runs the
# paper's evaluation on that library. One line per step, a PASS/FAIL table
# at the end; stops everything it started; exits 0 only if every step passed.
#
#   [MROS_V1_ROOT=<checkout>] scripts/run-evaluation.sh [--messages N] [--build-dir DIR]
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"

"$here/scripts/setup.sh" --tests
exec /usr/bin/python3 "$here/evaluation/run.py" "$@"
