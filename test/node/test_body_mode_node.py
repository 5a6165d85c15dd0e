#!/usr/bin/env python3
"""The node with an ROV simulated here (test/body_mode.test: config/bluerov2_tether.yaml, load.mode body, the
station keeper holding the start pose). rov_odom comes in the world frame with the ROV's frame as child and
finite numbers; a forward rov_thrust on top of the keeper's pushes the ROV off its station; a thrust with a
NaN and one in a foreign frame are rejected (the ROV and every output stay finite); a thrust stream that
stops is dropped after ros.input_timeout, and the keeper brings the ROV back; with its target moved 2 m
forward by rov_target, the ROV follows."""
import math
import time
import unittest

import rospy
import rosunit
from cable_msgs.msg import CableState
from geometry_msgs.msg import PoseStamped, WrenchStamped
from nav_msgs.msg import Odometry

NS = "/body_mode/"


def finite(odom):
    p, q, v, w = odom.pose.pose.position, odom.pose.pose.orientation, odom.twist.twist.linear, odom.twist.twist.angular
    return all(math.isfinite(x) for x in (p.x, p.y, p.z, q.x, q.y, q.z, q.w, v.x, v.y, v.z, w.x, w.y, w.z))


class BodyModeNode(unittest.TestCase):
    def setUp(self):
        self.odoms, self.states = [], []
        rospy.Subscriber(NS + "rov_odom", Odometry, self.odoms.append)
        rospy.Subscriber(NS + "cable_state", CableState, self.states.append)
        self.thrust = rospy.Publisher(NS + "rov_thrust", WrenchStamped, queue_size=10)
        self.target = rospy.Publisher(NS + "rov_target", PoseStamped, queue_size=10)
        deadline = time.time() + 30.0
        while not self.odoms and time.time() < deadline:
            time.sleep(0.1)
        self.assertTrue(self.odoms, "no rov_odom within 30 s")

    def x(self):
        return self.odoms[-1].pose.pose.position.x

    def publish_thrust(self, force_x, seconds, frame="", nan=False):
        msg = WrenchStamped()
        msg.header.frame_id = frame
        msg.wrench.force.x = float("nan") if nan else force_x
        end = time.time() + seconds
        sent = 0
        while time.time() < end:
            msg.header.stamp = rospy.Time.now()
            self.thrust.publish(msg)
            sent += 1
            time.sleep(0.05)
        return sent

    def test_odometry_thrust_bad_thrust_and_target(self):
        first = self.odoms[-1]
        self.assertEqual(first.header.frame_id, "world")
        self.assertEqual(first.child_frame_id, "body_mode/rov")
        time.sleep(3.0)
        start = self.x()
        # A forward thrust of 30 N on top of the station keeper's: the ROV gives way forward.
        self.publish_thrust(30.0, 3.0)
        pushed = self.x()
        print(f"\n30 N forward for 3 s: {pushed - start:+.3f} m off the station", flush=True)
        self.assertGreater(pushed - start, 0.1)
        # Rejected: a NaN, a foreign frame (the 30 N stays in force until the stream counts as stopped), and
        # a target with a NaN: each counted in cable_state with the guarded streams' rejections.
        rejected, received = self.states[-1].rejected_inputs, self.states[-1].received_inputs
        bad = self.publish_thrust(0.0, 0.5, nan=True) + self.publish_thrust(100.0, 0.5, frame="not_the_rov")
        nan_target = PoseStamped()
        nan_target.header.frame_id = "world"
        nan_target.pose.position.x = float("nan")
        nan_target.pose.orientation.w = 1.0
        self.target.publish(nan_target)
        bad += 1
        time.sleep(0.5)
        self.assertEqual(self.states[-1].rejected_inputs - rejected, bad)
        self.assertEqual(self.states[-1].received_inputs - received, bad)
        self.assertTrue(all(finite(o) for o in self.odoms))
        # The stream stopped: its thrust is dropped after ros.input_timeout (1 s), and the keeper brings the
        # ROV back to its station.
        time.sleep(20.0)
        off = abs(self.x() - start)
        print(f"thrust stream stopped: {off:.3f} m off the station 20 s later", flush=True)
        self.assertLess(off, 0.5 * (pushed - start))
        # The station keeper's target 2 m forward (world x): the ROV follows it (the integral's windup on
        # so large a step overshoots a little).
        target = PoseStamped()
        target.header.frame_id = "world"
        target.pose.position.x = start + 2.0
        target.pose.position.y = first.pose.pose.position.y
        target.pose.position.z = first.pose.pose.position.z
        target.pose.orientation = first.pose.pose.orientation
        for _ in range(5):
            self.target.publish(target)
            time.sleep(0.1)
        time.sleep(15.0)
        moved = self.x() - start
        print(f"station moved 2 m: the ROV moved {moved:.3f} m in 15 s", flush=True)
        self.assertGreater(moved, 1.5)
        self.assertLess(moved, 2.6)
        self.assertTrue(all(finite(o) for o in self.odoms))


if __name__ == "__main__":
    rospy.init_node("test_body_mode_node", anonymous=True)
    rosunit.unitrun("cable_dynamics", "body_mode_node", BodyModeNode)
