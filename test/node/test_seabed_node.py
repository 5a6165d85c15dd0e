#!/usr/bin/env python3
"""The node with a seabed (test/seabed.test): the ROV sits on the bottom, then drives away at 0.5 m/s;
the tether lies on the bottom at first and lifts off as the ROV pulls it straight. cable_state reports
the grounded length, the touchdown and the contact forces, all finite, within the allowed penetration;
the bottom's marker is latched and the links on it are marked."""
import math
import time
import unittest

import rospy
import rosunit
from cable_msgs.msg import CableState
from geometry_msgs.msg import PoseStamped
from visualization_msgs.msg import Marker

NS = "/seabed_test/"
DEPTH = 20.0
ALLOWED = 0.0125  # seabed.penetration's default: half the diameter [m]


def finite(values):
    return all(math.isfinite(v) for v in values)


class SeabedNode(unittest.TestCase):
    def test_rov_on_the_bottom_drives_away(self):
        states = []
        markers = {}
        rospy.Subscriber(NS + "cable_state", CableState, states.append)
        rospy.Subscriber(NS + "seabed_marker", Marker, lambda m: markers.update(bed=m))
        rospy.Subscriber(NS + "seabed_contact_marker", Marker, lambda m: markers.update(contact=m))
        rov = rospy.Publisher(NS + "rov_pose", PoseStamped, queue_size=10)

        def drive(x, seconds):
            """Holds the ROV at x (world, on the bottom), or moves it there at 0.5 m/s, for `seconds`."""
            msg = PoseStamped()
            msg.header.frame_id = "world"
            msg.pose.orientation.w = 1.0
            msg.pose.position.z = -19.8
            end = time.time() + seconds
            while time.time() < end and not rospy.is_shutdown():
                current = msg.pose.position.x if msg.pose.position.x else 5.0
                msg.pose.position.x = min(x, current + 0.5 * 0.02) if x > current else x
                msg.header.stamp = rospy.Time.now()
                rov.publish(msg)
                time.sleep(0.02)

        deadline = time.time() + 30.0
        while not states and time.time() < deadline:
            time.sleep(0.1)
        self.assertTrue(states, "no cable_state")
        drive(5.0, 3.0)  # on the bottom, 5 m from the TMS
        sitting = states[-1]
        self.assertTrue(sitting.seabed)
        self.assertGreater(sitting.grounded_length, 3.0)
        self.assertGreater(sitting.touchdown_arc_length, 15.0)  # it first touches after ~20 m of drop
        self.assertLess(sitting.touchdown.z, -DEPTH + 0.05)
        self.assertGreater(max(sitting.seabed_force), 0.0)
        drive(22.0, 40.0)  # drives 17 m away at 0.5 m/s (34 s) and stops
        away = states[-1]
        rospy.loginfo("grounded %.2f m sitting, %.2f m after driving away; touchdown %.2f -> %.2f m",
                      sitting.grounded_length, away.grounded_length, sitting.touchdown_arc_length,
                      away.touchdown_arc_length)
        # 30 m of tether to a point 29.5 m away: almost straight, far less of it on the bottom.
        self.assertLess(away.grounded_length, 0.5 * sitting.grounded_length)
        for s in states:
            self.assertTrue(finite([s.grounded_length, s.touchdown_arc_length, s.max_penetration, s.contact_energy,
                                    s.touchdown.x, s.touchdown.y, s.touchdown.z] + list(s.seabed_force)))
            self.assertLessEqual(s.max_penetration, ALLOWED)
        self.assertEqual(away.diverged_steps, 0)
        self.assertEqual(markers.get("bed").type, Marker.CUBE)
        self.assertAlmostEqual(markers["bed"].pose.position.z, -DEPTH - 0.01, places=6)
        self.assertIn("contact", markers)


if __name__ == "__main__":
    rospy.init_node("test_seabed_node")
    rosunit.unitrun("cable_dynamics", "seabed_node", SeabedNode)
