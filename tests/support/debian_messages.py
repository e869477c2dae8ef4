# SPDX-License-Identifier: BSD-3-Clause
"""The Debian ROS 1 message packages genmros is held against."""

DEBIAN_MESSAGE_PACKAGES = [
    'std_msgs', 'geometry_msgs', 'sensor_msgs', 'nav_msgs', 'trajectory_msgs',
    'visualization_msgs', 'diagnostic_msgs', 'actionlib_msgs', 'shape_msgs',
    'stereo_msgs', 'tf2_msgs', 'map_msgs', 'pcl_msgs', 'std_srvs', 'rosgraph_msgs',
]
