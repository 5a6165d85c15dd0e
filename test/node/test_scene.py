#!/usr/bin/env python3
"""The rviz scene (test/scene.test, test/node/scene_test.yaml).

Markers: 5 of the line, 8 of the bodies, one CYLINDER per link (ns cable_tube) whose scale.x = scale.y is the
diameter of the link's section (0.04 m for links 1-4, 0.02 m for 5-10: the config's numbers), whose length is
the distance between the line's points k and k+1 and whose axis runs between them (the line marker is
computed from the same snapshot, so they agree to rounding: 1e-9 m); the vessel's hull and the ROV's body
at the configured sizes in their own frames, the hull afloat on the vessel's origin, the A-frame from the deck to
the hang-off point; every number finite; with a winch, the drum's slots deleted (action DELETE).
Interactive marker: it starts at the ROV's TF pose, and a moved marker (a POSE_UPDATE on its feedback topic,
as rviz sends one) is published on rov_pose and becomes the ROV frame's pose."""
import math
import time
import unittest

import numpy as np
import rospy
import rosunit
import tf2_ros
from geometry_msgs.msg import PoseStamped
from visualization_msgs.msg import InteractiveMarkerFeedback, InteractiveMarkerInit, Marker, MarkerArray

NS = "/scene"
LINKS = 10
DIAMETERS = [0.04] * 4 + [0.02] * 6  # [m], test/node/scene_test.yaml
HANG_OFF = np.array([-12.0, 0.5, 6.0])
VESSEL_SIZE, ROV_SIZE = [24.0, 7.0, 3.0], [1.6, 1.0, 0.9]


def wait_for(predicate, timeout):
    deadline = time.time() + timeout
    while not predicate() and time.time() < deadline and not rospy.is_shutdown():
        time.sleep(0.05)
    return predicate()


def finite_marker(m):
    numbers = [m.pose.position.x, m.pose.position.y, m.pose.position.z, m.pose.orientation.x, m.pose.orientation.y,
               m.pose.orientation.z, m.pose.orientation.w, m.scale.x, m.scale.y, m.scale.z, m.color.r, m.color.g,
               m.color.b, m.color.a]
    numbers += [v for p in m.points for v in (p.x, p.y, p.z)]
    numbers += [v for c in m.colors for v in (c.r, c.g, c.b, c.a)]
    return all(math.isfinite(v) for v in numbers)


def z_axis(q):
    """The third column of the rotation matrix of quaternion q (x, y, z, w)."""
    x, y, z, w = q.x, q.y, q.z, q.w
    return np.array([2 * (x * z + w * y), 2 * (y * z - w * x), 1 - 2 * (x * x + y * y)])


class Scene(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.markers = None
        cls.count = 0
        cls.poses = []
        cls.update = None

        def on_markers(m):
            cls.markers = m
            cls.count += 1

        rospy.Subscriber(NS + "/cable_markers", MarkerArray, on_markers)
        rospy.Subscriber(NS + "/rov_pose", PoseStamped, lambda m: cls.poses.append(m))
        rospy.Subscriber(NS + "/rov_target_marker/update_full", InteractiveMarkerInit,
                         lambda m: setattr(cls, "update", m))
        cls.tf = tf2_ros.Buffer()
        cls.listener = tf2_ros.TransformListener(cls.tf)
        assert wait_for(lambda: cls.count > 10, 30.0), "no cable_markers"

    def by_ns(self, ns):
        return sorted((m for m in self.markers.markers if m.ns == ns), key=lambda m: m.id)

    def test_cable_cylinders_have_the_sections_diameters(self):
        markers = self.markers.markers
        self.assertEqual(len(markers), 5 + 8 + LINKS)
        self.assertTrue(all(finite_marker(m) for m in markers), "a non-finite number in cable_markers")
        line = self.by_ns("cable")[0]
        tube = self.by_ns("cable_tube")
        self.assertEqual([m.id for m in tube], list(range(LINKS)))
        for k, m in enumerate(tube):
            self.assertEqual(m.type, Marker.CYLINDER)
            self.assertEqual(m.action, Marker.ADD)
            self.assertEqual(m.header.frame_id, "scene/cable_paper")
            self.assertEqual(m.scale.x, DIAMETERS[k])  # the config's number, copied: exact
            self.assertEqual(m.scale.y, DIAMETERS[k])
            a = np.array([line.points[k].x, line.points[k].y, line.points[k].z])
            b = np.array([line.points[k + 1].x, line.points[k + 1].y, line.points[k + 1].z])
            self.assertAlmostEqual(m.scale.z, np.linalg.norm(b - a), delta=1e-9)
            self.assertAlmostEqual(m.scale.z, 2.0, delta=1e-6)  # 20 m in 10 links (inextensible)
            centre = np.array([m.pose.position.x, m.pose.position.y, m.pose.position.z])
            np.testing.assert_allclose(centre, 0.5 * (a + b), atol=1e-9)
            np.testing.assert_allclose(z_axis(m.pose.orientation), (b - a) / np.linalg.norm(b - a), atol=1e-9)
            self.assertTrue(0.0 <= m.color.r <= 1.0 and 0.0 <= m.color.g <= 1.0 and 0.0 <= m.color.b <= 1.0)

    def test_drum_slots_have_no_cylinder(self):
        got = {}
        sub = rospy.Subscriber("/scene_winch/cable_markers", MarkerArray, lambda m: got.update(m=m))
        self.assertTrue(wait_for(lambda: "m" in got, 30.0), "no cable_markers from the winch's node")
        sub.unregister()
        markers = got["m"].markers
        self.assertEqual(len(markers), 5 + 8 + 21)
        self.assertTrue(all(finite_marker(m) for m in markers))
        tube = sorted((m for m in markers if m.ns == "cable_tube"), key=lambda m: m.id)
        self.assertEqual([m.action for m in tube], [Marker.DELETE] * 11 + [Marker.ADD] * 10)
        for m in tube[11:]:
            self.assertEqual(m.scale.x, 0.03)  # winch_test.yaml's diameter
            self.assertAlmostEqual(m.scale.z, 2.0, delta=1e-6)

    def test_vessel_and_rov_shapes(self):
        hull, = self.by_ns("vessel_hull")
        self.assertEqual((hull.type, hull.header.frame_id), (Marker.CUBE, "scene/vessel"))
        self.assertEqual([hull.scale.x, hull.scale.y, hull.scale.z], VESSEL_SIZE)
        house, = self.by_ns("vessel_deckhouse")
        self.assertEqual((house.type, house.header.frame_id), (Marker.CUBE, "scene/vessel"))
        aframe, = self.by_ns("vessel_aframe")
        self.assertEqual((aframe.type, aframe.header.frame_id, len(aframe.points)), (Marker.LINE_LIST, "scene/vessel", 6))
        tops = np.array([[p.x, p.y, p.z] for p in aframe.points[4:6]])
        np.testing.assert_allclose(tops.mean(axis=0), HANG_OFF, atol=1e-12)  # the sheave: the cable's base
        # Afloat: the vessel's origin on the waterline, 40 % of the hull below it; the A-frame's feet on the deck.
        self.assertAlmostEqual(hull.pose.position.z - 0.5 * hull.scale.z, -0.4 * VESSEL_SIZE[2], delta=1e-12)
        deck = hull.pose.position.z + 0.5 * hull.scale.z
        self.assertAlmostEqual(aframe.points[0].z, deck, delta=1e-12)
        self.assertAlmostEqual(aframe.points[2].z, deck, delta=1e-12)
        body, = self.by_ns("rov_body")
        self.assertEqual((body.type, body.header.frame_id), (Marker.CUBE, "scene/rov"))
        self.assertEqual([body.scale.x, body.scale.y, body.scale.z], ROV_SIZE)
        thrusters = self.by_ns("rov_thrusters")
        self.assertEqual([m.id for m in thrusters], [0, 1, 2, 3])
        self.assertTrue(all(m.type == Marker.CYLINDER and m.header.frame_id == "scene/rov" for m in thrusters))
        # The vessel's origin: the cable's base (world frame, the cable's first link frame) less the hang-off.
        t = self.tf.lookup_transform("world", "scene/vessel", rospy.Time(0), rospy.Duration(10.0)).transform.translation
        base = self.tf.lookup_transform("world", "scene/link_1", rospy.Time(0), rospy.Duration(10.0)).transform.translation
        np.testing.assert_allclose([base.x - t.x, base.y - t.y, base.z - t.z], HANG_OFF, atol=1e-9)

    def test_interactive_marker_drives_the_rov(self):
        self.assertTrue(wait_for(lambda: self.update is not None and self.update.markers, 30.0), "no update_full")
        marker = self.update.markers[0]
        self.assertEqual(marker.name, "rov_target")
        self.assertEqual(marker.header.frame_id, "world")
        rov = self.tf.lookup_transform("world", "scene/rov", rospy.Time(0), rospy.Duration(10.0)).transform
        start = np.array([marker.pose.position.x, marker.pose.position.y, marker.pose.position.z])
        # Starts at the ROV's pose (constant until a pose arrives: the configured target).
        np.testing.assert_allclose(start, [rov.translation.x, rov.translation.y, rov.translation.z], atol=1e-9)
        self.assertEqual(self.poses, [], "nothing is published before the marker is moved")

        feedback_pub = rospy.Publisher(NS + "/rov_target_marker/feedback", InteractiveMarkerFeedback, queue_size=10)
        wait_for(lambda: feedback_pub.get_num_connections() > 0, 10.0)
        target = start + np.array([1.5, -1.0, 2.0])  # [m]
        yaw = 0.4  # [rad]
        fb = InteractiveMarkerFeedback()
        fb.client_id = "test_scene"
        fb.marker_name = "rov_target"
        fb.control_name = "move_3d"
        fb.event_type = InteractiveMarkerFeedback.POSE_UPDATE
        fb.header.frame_id = "world"
        fb.pose.position.x, fb.pose.position.y, fb.pose.position.z = target
        fb.pose.orientation.z, fb.pose.orientation.w = math.sin(yaw / 2), math.cos(yaw / 2)
        # As rviz does while the box is dragged: a POSE_UPDATE every 0.1 s (the server ignores a new client's
        # feedback within 1 s of the marker's creation, so the first ones may be dropped).
        deadline = time.time() + 10.0
        while not self.poses and time.time() < deadline:
            fb.header.stamp = rospy.Time.now()
            feedback_pub.publish(fb)
            time.sleep(0.1)
        self.assertTrue(wait_for(lambda: len(self.poses) > 5, 10.0), "rov_pose not published after a move")
        last = self.poses[-1]
        self.assertEqual(last.header.frame_id, "world")
        np.testing.assert_allclose([last.pose.position.x, last.pose.position.y, last.pose.position.z], target)
        # Republished with fresh stamps (the node would call an old pose stale).
        self.assertGreater(self.poses[-1].header.stamp, self.poses[0].header.stamp)

        # The cable node takes it: the ROV frame goes to the marker's pose.
        def rov_at_target():
            t = self.tf.lookup_transform("world", "scene/rov", rospy.Time(0)).transform
            return (np.linalg.norm(np.array([t.translation.x, t.translation.y, t.translation.z]) - target) < 1e-6
                    and abs(t.rotation.z - math.sin(yaw / 2)) < 1e-6)
        self.assertTrue(wait_for(rov_at_target, 10.0), "the ROV frame did not follow the marker")


if __name__ == "__main__":
    rospy.init_node("test_scene", anonymous=True)
    rosunit.unitrun("cable_dynamics", "scene", Scene)
