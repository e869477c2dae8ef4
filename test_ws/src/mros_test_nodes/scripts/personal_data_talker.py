#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""The ROS side of the paper's evaluation (Fig. 9), in rospy: publishes
mros_test/PersonalData ("Charlie", "Parker", 32, score counting up) on
test_msg five times a second."""
import rospy
from mros_test.msg import PersonalData


def main():
    rospy.init_node('rospy_personal_talker')
    pub = rospy.Publisher('test_msg', PersonalData, queue_size=1)
    msg = PersonalData(first_name='Charlie', last_name='Parker', age=32, score=100100)
    rate = rospy.Rate(5)
    while not rospy.is_shutdown():
        pub.publish(msg)
        rospy.loginfo('published %s %s age:%u score:%d', msg.first_name, msg.last_name,
                      msg.age, msg.score)
        msg.score += 1
        rate.sleep()


if __name__ == '__main__':
    try:
        main()
    except rospy.ROSInterruptException:
        pass
