#!/usr/bin/env python3
"""Drag the ROV in rviz: an interactive marker (Debian's interactive_markers) whose pose is published as the
ROV's pose (geometry_msgs/PoseStamped on rov_pose, in the world frame), so the cable can be tried without an
ROV simulator.

The marker starts at the ROV's present pose (the TF frame ~rov_frame, default "<namespace>/rov", as the
cable node broadcasts it; ~initial_position [m] if that frame does not appear within ~wait s). Nothing is
published until the marker is first moved, so it never fights another pose source; from then on the last
pose is republished at ~rate Hz with fresh stamps (the cable node treats an old pose as stale). Drag the
translucent box in the view plane, the arrows along the world axes, the ring to turn the ROV about the vertical.

Parameters: ~world_frame (default: the cable node's ros.world_frame in the same namespace, else "world"), ~rov_frame, ~initial_position ([x, y, z], default [0, 0, -50]),
~wait (s, default 10), ~rate (Hz, default 20), ~scale (m, default 3: the marker's size).
Topics: rov_pose (out), rov_target_marker/update, /update_full, /feedback (the interactive marker's)."""
import math

import rospy
import tf2_ros
from geometry_msgs.msg import Pose, PoseStamped
from interactive_markers.interactive_marker_server import InteractiveMarkerServer
from visualization_msgs.msg import InteractiveMarker, InteractiveMarkerControl, InteractiveMarkerFeedback, Marker


def default_rov_frame():
    ns = rospy.get_namespace().strip("/")
    return (ns + "/" if ns else "") + "rov"


def start_pose(world_frame, rov_frame, initial_position, wait):
    """The ROV's pose from TF, or the fallback position (upright) when the frame does not appear in time."""
    buffer = tf2_ros.Buffer()
    tf2_ros.TransformListener(buffer)
    pose = Pose()
    pose.orientation.w = 1.0
    try:
        t = buffer.lookup_transform(world_frame, rov_frame, rospy.Time(0), rospy.Duration(wait)).transform
        pose.position.x, pose.position.y, pose.position.z = t.translation.x, t.translation.y, t.translation.z
        pose.orientation = t.rotation
        rospy.loginfo("rov_target_marker: starting at %s's pose (%.2f, %.2f, %.2f) m", rov_frame, t.translation.x,
                      t.translation.y, t.translation.z)
    except (tf2_ros.LookupException, tf2_ros.ExtrapolationException, tf2_ros.ConnectivityException,
            tf2_ros.TransformException) as e:
        pose.position.x, pose.position.y, pose.position.z = initial_position
        rospy.logwarn("rov_target_marker: no transform %s -> %s within %.1f s (%s); starting at ~initial_position "
                      "%s m", world_frame, rov_frame, wait, e, list(initial_position))
    return pose


def axis_control(name, mode, x, y, z):
    c = InteractiveMarkerControl()
    c.name = name
    c.interaction_mode = mode
    c.orientation.w, c.orientation.x, c.orientation.y, c.orientation.z = 1.0 / math.sqrt(2.0), x, y, z
    c.orientation_mode = InteractiveMarkerControl.FIXED  # world axes, whatever the ROV's yaw
    return c


def make_marker(world_frame, pose, scale):
    m = InteractiveMarker()
    m.header.frame_id = world_frame
    m.name = "rov_target"
    m.description = "ROV target (drag me)"
    m.pose = pose
    m.scale = scale
    box = Marker()
    box.type = Marker.CUBE
    # A translucent shell a little larger than the ROV's default shape (ros.rov_size 2 x 1.4 x 1.2 m at the
    # default scale of 3 m), so the ROV stays visible inside the handle.
    box.scale.x, box.scale.y, box.scale.z = 0.8 * scale, 0.55 * scale, 0.5 * scale
    box.color.r, box.color.g, box.color.b, box.color.a = 0.3, 0.8, 1.0, 0.3
    drag = InteractiveMarkerControl()
    drag.name = "move_3d"
    drag.interaction_mode = InteractiveMarkerControl.MOVE_3D
    drag.always_visible = True
    drag.markers.append(box)
    m.controls.append(drag)
    s = 1.0 / math.sqrt(2.0)
    m.controls.append(axis_control("move_x", InteractiveMarkerControl.MOVE_AXIS, s, 0.0, 0.0))
    m.controls.append(axis_control("move_y", InteractiveMarkerControl.MOVE_AXIS, 0.0, 0.0, s))
    m.controls.append(axis_control("move_z", InteractiveMarkerControl.MOVE_AXIS, 0.0, s, 0.0))
    m.controls.append(axis_control("yaw", InteractiveMarkerControl.ROTATE_AXIS, 0.0, s, 0.0))
    return m


class RovTargetMarker:
    def __init__(self):
        self.world_frame = rospy.get_param("~world_frame", rospy.get_param("cable_dynamics_node/ros/world_frame", "world"))
        rov_frame = rospy.get_param("~rov_frame", default_rov_frame())
        initial = [float(v) for v in rospy.get_param("~initial_position", [0.0, 0.0, -50.0])]
        wait = float(rospy.get_param("~wait", 10.0))
        rate = float(rospy.get_param("~rate", 20.0))
        scale = float(rospy.get_param("~scale", 3.0))
        if len(initial) != 3 or not all(math.isfinite(v) for v in initial):
            raise ValueError(f"~initial_position = {initial}: expected three finite numbers [m]")
        if not (0.0 < rate <= 1000.0 and math.isfinite(rate)):
            raise ValueError(f"~rate = {rate}: expected a rate in (0, 1000] Hz")
        if not (0.0 < scale <= 1000.0 and math.isfinite(scale)):
            raise ValueError(f"~scale = {scale}: expected a size in (0, 1000] m")
        self.pose = None  # nothing published until the marker is moved
        self.pub = rospy.Publisher("rov_pose", PoseStamped, queue_size=10)
        self.server = InteractiveMarkerServer("rov_target_marker")
        self.server.insert(make_marker(self.world_frame, start_pose(self.world_frame, rov_frame, initial, wait), scale),
                           self.on_feedback)
        self.server.applyChanges()
        self.timer = rospy.Timer(rospy.Duration(1.0 / rate), self.republish)

    def on_feedback(self, feedback):
        if feedback.event_type not in (InteractiveMarkerFeedback.POSE_UPDATE, InteractiveMarkerFeedback.MOUSE_UP):
            return
        p, q = feedback.pose.position, feedback.pose.orientation
        if not all(math.isfinite(v) for v in (p.x, p.y, p.z, q.x, q.y, q.z, q.w)):
            rospy.logwarn_throttle(5.0, "rov_target_marker: ignored a non-finite pose")
            return
        self.pose = feedback.pose
        self.server.applyChanges()  # the marker's new pose to every rviz (the dragging one has it already)
        self.publish()

    def republish(self, _event):
        if self.pose is not None:
            self.publish()

    def publish(self):
        msg = PoseStamped()
        msg.header.stamp = rospy.Time.now()
        msg.header.frame_id = self.world_frame
        msg.pose = self.pose
        self.pub.publish(msg)


def main():
    rospy.init_node("rov_target_marker")
    RovTargetMarker()
    rospy.spin()


if __name__ == "__main__":
    main()
