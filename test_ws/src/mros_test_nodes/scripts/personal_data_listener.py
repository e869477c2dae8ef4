#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""The ROS side of the paper's evaluation (Fig. 8), in rospy: prints the
mros_test/PersonalData messages that the mROS node publishes on mros_str."""
import rospy
from mros_test.msg import PersonalData


def heard(msg):
    rospy.loginfo('I heard from mROS: %s %s age:%u score:%d', msg.first_name, msg.last_name,
                  msg.age, msg.score)


def main():
    rospy.init_node('rospy_personal_listener')
    rospy.Subscriber('mros_str', PersonalData, heard, queue_size=10)
    rospy.spin()


if __name__ == '__main__':
    main()
