#!/usr/bin/env python3
"""Demo driver: a fake ROV pose (geometry_msgs/PoseStamped on rov_pose) that rises 6 m from the cable's
hanging tip and then circles, and a slowly varying current (geometry_msgs/TwistStamped on current), both
in the world frame. For launch/demo.launch; parameters ~world_frame (default: the cable node's ros.world_frame in
the same namespace, else "world"), ~depth (m, the tip's rest depth),
~radius (m), ~period (s), ~rate (Hz), ~pose_topic (default rov_pose; rov_target when an ROV simulator,
scripts/simple_rov.py, follows the path with its station keeper)."""
import math

import rospy
from geometry_msgs.msg import PoseStamped, TwistStamped


def main():
    rospy.init_node("fake_rov")
    frame = rospy.get_param("~world_frame", rospy.get_param("cable_dynamics_node/ros/world_frame", "world"))
    depth = float(rospy.get_param("~depth", 50.0))
    radius = float(rospy.get_param("~radius", 8.0))
    period = float(rospy.get_param("~period", 120.0))
    rate = rospy.Rate(float(rospy.get_param("~rate", 20.0)))
    pose_pub = rospy.Publisher(rospy.get_param("~pose_topic", "rov_pose"), PoseStamped, queue_size=10)
    current_pub = rospy.Publisher("current", TwistStamped, queue_size=10)
    start = rospy.Time.now()
    while not rospy.is_shutdown():
        now = rospy.Time.now()
        if start.is_zero():  # simulated time not started yet
            start = now
            rate.sleep()
            continue
        t = (now - start).to_sec()
        rise = 6.0 * min(t / 10.0, 1.0)
        phase = 2.0 * math.pi * max(t - 10.0, 0.0) / period
        pose = PoseStamped()
        pose.header.stamp = now
        pose.header.frame_id = frame
        pose.pose.position.x = radius * math.sin(phase)
        pose.pose.position.y = radius * (1.0 - math.cos(phase))
        pose.pose.position.z = -depth + rise
        pose.pose.orientation.w = 1.0
        pose_pub.publish(pose)
        current = TwistStamped()
        current.header.stamp = now
        current.header.frame_id = frame
        current.twist.linear.x = 0.3 + 0.2 * math.sin(2.0 * math.pi * t / 40.0)
        current.twist.linear.y = 0.1
        current_pub.publish(current)
        try:
            rate.sleep()
        except rospy.ROSInterruptException:
            break


if __name__ == "__main__":
    main()
