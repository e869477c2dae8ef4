# SPDX-License-Identifier: BSD-3-Clause
"""What the tests, the benchmarks and the main job (evaluation/) share, and
what is not installed. For mROS v1: a ROS graph on this machine (rosmaster,
ROS nodes, an app of the PC target as a board) and a raw TCPROS peer. For
mros2: Fast-CDR as a reference serializer (fastcdr), a real Fast DDS
participant (dds_peer), random ROS 2 instances and rosbags' definitions
(ros2_messages), the echo program of generated headers (mros2_harness), a
stand-in of mros2's runtime calls (mros2_runtime/), a stand-in of
embeddedRTPS and CMSIS to compile the user's own src/mros2.cpp
(mros2_library/), and a genmros app on the user's mros2-posix against an
rclpy node (mros2_posix, mros2_posix_app/). For both: where ROS is, read
from the environment as genmros reads it (ros_paths). Each of them imports this
package from the repository, and a few build on another of it (the soak on
mros2_pc, which takes the ROS 2 wheels' venv from ros_paths)."""
