#!/usr/bin/env python3
"""A small ROV simulator to drive the cable node with physics: a 6-DOF rigid body in Fossen's form that
applies the cable's wrench (rov_wrench) and publishes its pose (rov_pose), as an ROV simulator beside the
node does. The demo runs it so that rviz shows a two-way coupling; the tests run it as the pose-only client
of docs/ROV_COUPLING.md.

The body (Fossen, Handbook of Marine Craft Hydrodynamics and Motion Control, 2011, ch. 6-7), body frame
x forward, y left, z up (REP-103), velocities nu = [v; w] in body axes:

    (M_RB + M_A) nu' + C_RB(nu) nu + (D_l + D_q |nu|) nu + g(eta) = tau_thrust + tau_cable

with M_RB = diag(m, m, m, Ixx, Iyy, Izz) (centre of gravity at the origin), M_A and the dampings diagonal,
C_RB nu = [m w x v; w x (I w)], the added mass's Coriolis term left out (second order at station-keeping
speeds), g(eta) the weight at the centre of gravity and the buoyancy at the centre of buoyancy. The thrust is
a PID station keeper on the position (world axes) and a PD on the attitude, no saturation. It integrates
with semi-implicit Euler at `substep` (1 ms) and holds the received wrench between messages, as a
simulator that only reads poses and wrenches would.

Parameters (private): ~rate [Hz] (pose exchange, default 50), ~preset (bluerov2 | workclass, default
bluerov2), ~mass [kg] (overrides the preset's, scaling its other terms), ~initial_position [x, y, z] world
[m] (default: the cable's load frame from TF), ~target [x, y, z] (default: the initial position),
~world_frame (default world), ~load_frame (default <ns>/cable_load, the cable node's load frame).
Topics: rov_wrench (in, geometry_msgs/WrenchStamped, body axes about the ROV's origin), rov_target (in,
geometry_msgs/PoseStamped, world frame: the station keeper's target position, e.g. scripts/fake_rov.py's
path), rov_pose (out, geometry_msgs/PoseStamped, world frame), rov_odom (out, nav_msgs/Odometry)."""
import math

import numpy as np

GRAVITY = 9.81  # m/s^2
WATER_DENSITY = 1025.0  # kg/m^3

# BlueROV2 (heavy-config-free, 8 thrusters off), identified by C.-J. Wu, "6-DoF modelling and control of a
# remotely operated vehicle", Flinders University 2018, as tabulated by von Benzon et al., "An open-source
# benchmark simulator: control of a BlueROV2 underwater robot", J. Mar. Sci. Eng. 10 (2022) 1898, Table 1.
# Added masses and dampings as positive magnitudes (Fossen's X_udot etc. with their signs turned).
BLUEROV2 = {
    "mass": 11.5,                                          # kg, in air
    "inertia": [0.16, 0.16, 0.16],                         # kg m^2 about the origin (= CG)
    "added_mass": [5.5, 12.7, 14.57, 0.12, 0.12, 0.12],    # kg, kg m^2
    "linear_damping": [4.03, 6.22, 5.18, 0.07, 0.07, 0.07],  # N s/m, N m s/rad
    "quadratic_damping": [18.18, 21.66, 36.99, 1.55, 1.55, 1.55],  # N s^2/m^2, N m s^2/rad^2
    "weight": 112.8,                                       # N
    "buoyancy": 114.8,                                     # N
    "cog": [0.0, 0.0, 0.0],                                # m, body frame
    "cob": [0.0, 0.0, 0.02],                               # m: 2 cm above the CG (Wu 2018: z_b - z_g)
}
# A work-class ROV of about 3000 kg: BlueROV2's coefficients scaled by mass (lengths by mass^(1/3)); for
# the coupling's tests and the armoured umbilical, not an identified vehicle.


def scaled(preset, mass):
    """The preset's body at another mass: masses and linear terms by the mass ratio r, inertias by r^(5/3),
    quadratic damping by r^(2/3) (area), as geometrically similar bodies of the same density scale."""
    r = mass / preset["mass"]
    out = dict(preset)
    out["mass"] = mass
    out["inertia"] = [i * r ** (5.0 / 3.0) for i in preset["inertia"]]
    out["added_mass"] = [a * r for a in preset["added_mass"][:3]] + [a * r ** (5.0 / 3.0) for a in preset["added_mass"][3:]]
    out["linear_damping"] = [d * r ** (2.0 / 3.0) for d in preset["linear_damping"]]
    out["quadratic_damping"] = [d * r ** (2.0 / 3.0) for d in preset["quadratic_damping"][:3]] + [
        d * r ** (4.0 / 3.0) for d in preset["quadratic_damping"][3:]]
    out["weight"] = preset["weight"] * r
    out["buoyancy"] = preset["buoyancy"] * r
    out["cob"] = [c * r ** (1.0 / 3.0) for c in preset["cob"]]
    return out


def quat_to_matrix(q):
    """Rotation matrix (world from body) of a unit quaternion [x, y, z, w]."""
    x, y, z, w = q
    return np.array([
        [1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
        [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
        [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)],
    ])


def quat_multiply(a, b):
    ax, ay, az, aw = a
    bx, by, bz, bw = b
    return np.array([aw * bx + ax * bw + ay * bz - az * by, aw * by - ax * bz + ay * bw + az * bx,
                     aw * bz + ax * by - ay * bx + az * bw, aw * bw - ax * bx - ay * by - az * bz])


class RovBody:
    """The ROV's state and dynamics (no ROS): position p (world, z up) [m], attitude q [x, y, z, w] (world
    from body), body velocities v [m/s] and w [rad/s]; a PID station keeper towards `target`."""

    def __init__(self, params, position, target=None, gains=None, current=None):
        self.p = np.array(position, dtype=float)
        # The water's velocity (world axes) [m/s]: the damping acts on the velocity relative to it.
        self.current = np.zeros(3) if current is None else np.array(current, dtype=float)
        self.q = np.array([0.0, 0.0, 0.0, 1.0])
        self.v = np.zeros(3)
        self.w = np.zeros(3)
        self.target = np.array(target if target is not None else position, dtype=float)
        m = params["mass"]
        self.m = m
        self.inertia = np.array(params["inertia"], dtype=float)
        self.M = np.concatenate([[m, m, m], self.inertia]) + np.array(params["added_mass"], dtype=float)
        self.Dl = np.array(params["linear_damping"], dtype=float)
        self.Dq = np.array(params["quadratic_damping"], dtype=float)
        self.W, self.B = params["weight"], params["buoyancy"]
        self.rg, self.rb = np.array(params["cog"], dtype=float), np.array(params["cob"], dtype=float)
        # Station keeping: a critically damped PID on the position at 1.5 rad/s for the heaviest direction's
        # inertia, integral time 4 s; a PD on the attitude at 2 rad/s.
        g = gains or {}
        m_eff = float(np.max(self.M[:3]))
        wn = g.get("bandwidth", 1.5)
        self.kp = g.get("kp", m_eff * wn * wn)
        self.kd = g.get("kd", 2.0 * m_eff * wn)
        self.ki = g.get("ki", self.kp / 4.0)
        i_eff = float(np.max(self.M[3:]))
        self.kr = g.get("kr", i_eff * 4.0)
        self.kw = g.get("kw", 2.0 * i_eff * 2.0)
        self.integral = np.zeros(3)
        self.work = 0.0  # [J] done on the ROV by the cable's wrench (force . velocity of the origin + torque . w)

    def preload(self, force_world):
        """Sets the station keeper's integral so that its thrust balances `force_world` [N] (the cable's pull
        at start): a bumpless start at a loaded equilibrium."""
        if self.ki > 0.0:
            self.integral = np.asarray(force_world, dtype=float) / self.ki

    def velocity_world(self):
        return quat_to_matrix(self.q) @ self.v

    def thrust(self, dt):
        """PID (world axes) and attitude PD, as body-frame force and torque [N, N m]."""
        R = quat_to_matrix(self.q)
        error = self.p - self.target
        self.integral += error * dt
        force_world = -self.kp * error - self.kd * (R @ self.v) - self.ki * self.integral
        # Attitude: towards upright with zero yaw (the small-angle vector of q).
        sign = 1.0 if self.q[3] >= 0 else -1.0
        torque = -self.kr * 2.0 * sign * self.q[:3] - self.kw * self.w
        return R.T @ force_world, R.T @ torque

    def restoring(self):
        """Weight at the CG and buoyancy at the CB, body axes [N, N m]."""
        R = quat_to_matrix(self.q)
        fw = R.T @ np.array([0.0, 0.0, -self.W])
        fb = R.T @ np.array([0.0, 0.0, self.B])
        return fw + fb, np.cross(self.rg, fw) + np.cross(self.rb, fb)

    def step(self, dt, cable_force_body, cable_torque_body):
        """One semi-implicit Euler step of dt [s] with the cable's wrench (body axes, about the origin)."""
        f_thr, t_thr = self.thrust(dt)
        f_g, t_g = self.restoring()
        nu = np.concatenate([self.v, self.w])
        relative = nu - np.concatenate([quat_to_matrix(self.q).T @ self.current, np.zeros(3)])
        damping = (self.Dl + self.Dq * np.abs(relative)) * relative
        coriolis = np.concatenate([self.m * np.cross(self.w, self.v), np.cross(self.w, self.inertia * self.w)])
        tau = np.concatenate([f_thr + f_g + cable_force_body, t_thr + t_g + cable_torque_body])
        nu = nu + dt * (tau - damping - coriolis) / self.M
        self.v, self.w = nu[:3], nu[3:]
        self.work += dt * (np.dot(cable_force_body, self.v) + np.dot(cable_torque_body, self.w))
        self.p = self.p + dt * (quat_to_matrix(self.q) @ self.v)
        angle = np.linalg.norm(self.w) * dt
        if angle > 0.0:
            axis = self.w / np.linalg.norm(self.w)
            dq = np.concatenate([axis * math.sin(angle / 2.0), [math.cos(angle / 2.0)]])
            self.q = quat_multiply(self.q, dq)
            self.q /= np.linalg.norm(self.q)


def main():
    import rospy
    import tf2_ros
    from geometry_msgs.msg import PoseStamped, WrenchStamped
    from nav_msgs.msg import Odometry

    rospy.init_node("simple_rov")
    rate = float(rospy.get_param("~rate", 50.0))
    preset = {"bluerov2": BLUEROV2, "workclass": scaled(BLUEROV2, 3000.0)}[rospy.get_param("~preset", "bluerov2")]
    if rospy.has_param("~mass"):
        preset = scaled(BLUEROV2, float(rospy.get_param("~mass")))
    world = rospy.get_param("~world_frame", "world")
    ns = rospy.get_namespace().strip("/")
    load_frame = rospy.get_param("~load_frame", (ns + "/" if ns else "") + "cable_load")
    if rospy.has_param("~initial_position"):
        start = [float(x) for x in rospy.get_param("~initial_position")]
    else:
        buffer = tf2_ros.Buffer()
        listener = tf2_ros.TransformListener(buffer)  # kept: it fills the buffer while it lives
        t = buffer.lookup_transform(world, load_frame, rospy.Time(0), rospy.Duration(30.0)).transform.translation
        start = [t.x, t.y, t.z]
        del listener
    target = [float(x) for x in rospy.get_param("~target", start)]
    body = RovBody(preset, start, target)
    wrench = {"f": np.zeros(3), "t": np.zeros(3)}

    def on_wrench(msg):
        f, t = msg.wrench.force, msg.wrench.torque
        values = np.array([f.x, f.y, f.z, t.x, t.y, t.z])
        if np.all(np.isfinite(values)):
            wrench["f"], wrench["t"] = values[:3], values[3:]

    def on_target(msg):
        p = msg.pose.position
        if all(math.isfinite(v) for v in (p.x, p.y, p.z)):
            body.target = np.array([p.x, p.y, p.z])

    rospy.Subscriber("rov_wrench", WrenchStamped, on_wrench, queue_size=1, tcp_nodelay=True)
    rospy.Subscriber("rov_target", PoseStamped, on_target, queue_size=1)
    pose_pub = rospy.Publisher("rov_pose", PoseStamped, queue_size=1, tcp_nodelay=True)
    odom_pub = rospy.Publisher("rov_odom", Odometry, queue_size=1)
    period = 1.0 / rate
    substeps = max(1, int(round(period / 0.001)))
    rospy.loginfo("simple_rov: %.1f kg at (%.2f, %.2f, %.2f) m, poses at %.0f Hz", body.m, *body.p, rate)
    timer_rate = rospy.Rate(rate)
    while not rospy.is_shutdown():
        for _ in range(substeps):
            body.step(period / substeps, wrench["f"], wrench["t"])
        now = rospy.Time.now()
        pose = PoseStamped()
        pose.header.stamp, pose.header.frame_id = now, world
        pose.pose.position.x, pose.pose.position.y, pose.pose.position.z = body.p
        pose.pose.orientation.x, pose.pose.orientation.y, pose.pose.orientation.z, pose.pose.orientation.w = body.q
        pose_pub.publish(pose)
        odom = Odometry()
        odom.header = pose.header
        odom.child_frame_id = (ns + "/" if ns else "") + "rov"
        odom.pose.pose = pose.pose
        odom.twist.twist.linear.x, odom.twist.twist.linear.y, odom.twist.twist.linear.z = body.v
        odom.twist.twist.angular.x, odom.twist.twist.angular.y, odom.twist.twist.angular.z = body.w
        odom_pub.publish(odom)
        try:
            timer_rate.sleep()
        except rospy.ROSInterruptException:
            break


if __name__ == "__main__":
    main()
