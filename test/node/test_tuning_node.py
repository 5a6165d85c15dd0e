#!/usr/bin/env python3
"""Live tuning over ROS (issue 16): dynamic_reconfigure's client changes the node's values at
<node>/tuning and each change shows in the node's outputs; a value outside the config loader's range is
refused and the old one stays (the server's reply shows it). test/tuning.test runs the winch test cable
(test/node/winch_test.yaml: 20 m, a 40 kg clump weight, free, in still water, winch.max_speed 2 m/s)."""
import time
import unittest

import dynamic_reconfigure.client
import rospy
import rosunit
from cable_msgs.msg import CableState
from cable_msgs.srv import ResetToEquilibrium, SetPaused
from geometry_msgs.msg import TwistStamped
from sensor_msgs.msg import JointState
from std_msgs.msg import Float64

NS = "/tune_test"
SERVER = NS + "/cable_dynamics_node/tuning"


class Tuning(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.latest = {}
        cls.joint_stamps = []
        rospy.Subscriber(NS + "/cable_state", CableState, lambda m: cls.latest.update(state=m), queue_size=10)
        rospy.Subscriber(NS + "/joint_states", JointState,
                         lambda m: cls.joint_stamps.append(m.header.stamp.to_sec()), queue_size=1000)
        deadline = time.time() + 60.0
        while "state" not in cls.latest and time.time() < deadline:
            time.sleep(0.05)
        assert "state" in cls.latest, "no cable_state in 60 s"
        cls.client = dynamic_reconfigure.client.Client(SERVER, timeout=30.0)

    def state(self):
        return self.latest["state"]

    def shown(self, name, value, seconds=10.0):
        deadline = time.time() + seconds
        while self.client.get_configuration(timeout=seconds)[name] != value and time.time() < deadline:
            time.sleep(0.05)
        return self.client.get_configuration(timeout=seconds)[name] == value

    def update(self, **values):
        return self.client.update_configuration(values)

    def test_1_shows_the_node_values(self):
        c = self.client.get_configuration(timeout=10.0)
        self.assertEqual(c["rate"], 100.0)             # ros.rate
        self.assertEqual(c["drag_normal"], 1.2)        # fluid.drag_normal's default
        self.assertEqual(c["coupling_stiffness"], 2.0e4)
        self.assertEqual(c["winch_speed"], 0.0)        # winch.speed
        self.assertEqual([c["current_x"], c["current_y"], c["current_z"]], [0.0, 0.0, 0.0])
        self.assertFalse(c["paused"])

    def test_2_current_moves_the_cable_and_a_bad_one_is_refused(self):
        # Still water, at rest: the cable hangs straight, no horizontal force on the base.
        rospy.ServiceProxy(NS + "/reset_to_equilibrium", ResetToEquilibrium)()
        time.sleep(0.5)
        self.assertLess(abs(self.state().base_force.x), 1.0)
        reply = self.update(current_x=0.6)
        self.assertEqual(reply["current_x"], 0.6)
        # The equilibrium in that current: drag on 20 m of 30 mm cable (C_n 1.2) and the clump (C_d A
        # 0.1 m^2) at 0.6 m/s is 1/2 1025 0.36 (1.2 x 0.03 x 20 + 0.1) = 151 N when vertical; the
        # inclined cable feels less normal flow: more than a third of that, never more than all of it
        # plus the skin friction (C_t 0.01 over pi d: at most 1/2 1025 0.36 0.01 pi 0.03 20 = 3.5 N).
        rospy.ServiceProxy(NS + "/reset_to_equilibrium", ResetToEquilibrium)()
        time.sleep(0.5)
        pull_x = self.state().base_force.x
        self.assertGreater(pull_x, 50.0)
        self.assertLess(pull_x, 155.0)
        # Doubling C_n (live) pulls harder, as configuring it would.
        reply = self.update(drag_normal=2.4)
        self.assertEqual(reply["drag_normal"], 2.4)
        rospy.ServiceProxy(NS + "/reset_to_equilibrium", ResetToEquilibrium)()
        time.sleep(0.5)
        doubled = self.state().base_force.x
        print("equilibrium base force x: %.1f N at C_n 1.2, %.1f N at C_n 2.4 (0.6 m/s current)" % (pull_x, doubled))
        self.assertGreater(doubled, pull_x * 1.2)
        # Outside the loader's ranges: refused, the old values stay.
        reply = self.update(current_x=150.0)
        self.assertEqual(reply["current_x"], 0.6)
        reply = self.update(drag_normal=500.0)
        self.assertEqual(reply["drag_normal"], 2.4)
        reply = self.update(coupling_stiffness=0.0)  # the loader's range is open at 0
        self.assertEqual(reply["coupling_stiffness"], 2.0e4)
        # Back to still water.
        self.update(current_x=0.0, drag_normal=1.2)

    def test_3_rate(self):
        def median_spacing(count=41):
            """The median spacing of the stamps of the next `count` joint_states [s]. The stamps are the
            simulated instants published, one per cycle, so the spacing is the cycle's period whatever the
            machine's speed; a cycle a loaded machine delays (and the change of rate itself) moves a few
            spacings, not the median."""
            start = len(self.joint_stamps)
            deadline = time.time() + 60.0
            while len(self.joint_stamps) < start + count and time.time() < deadline:
                time.sleep(0.05)
            stamps = self.joint_stamps[start:start + count]
            self.assertEqual(len(stamps), count, "joint_states stopped")
            spacings = sorted(b - a for a, b in zip(stamps, stamps[1:]))
            return spacings[len(spacings) // 2]

        reply = self.update(rate=20.0)
        self.assertEqual(reply["rate"], 20.0)
        slow = median_spacing()
        reply = self.update(rate=5e4)  # beyond ros.rate's 10000 Hz
        self.assertEqual(reply["rate"], 20.0)
        reply = self.update(rate=100.0)
        fast = median_spacing()
        print("joint_states every %.4f s tuned to 20 Hz, every %.4f s tuned to 100 Hz (median stamp spacing)"
              % (slow, fast))
        # One cycle, to a step (simulation.dt = 1 ms in winch_test.yaml).
        self.assertAlmostEqual(slow, 1.0 / 20.0, delta=0.5e-3)
        self.assertAlmostEqual(fast, 1.0 / 100.0, delta=0.5e-3)

    def test_4_pause_through_tuning_and_through_the_service(self):
        self.assertTrue(self.update(paused=True)["paused"])
        time.sleep(0.3)
        held = self.state().sim_time
        time.sleep(1.0)
        self.assertTrue(self.state().paused)
        self.assertAlmostEqual(self.state().sim_time, held, delta=1e-9)
        self.assertFalse(self.update(paused=False)["paused"])
        time.sleep(1.0)
        self.assertGreater(self.state().sim_time, held + 0.5)
        # The service's pause shows in the tuning (the client's copy follows parameter_updates, which
        # arrive after the service's reply: polled, at most 10 s).
        set_paused = rospy.ServiceProxy(NS + "/set_paused", SetPaused)
        try:
            set_paused(paused=True)
            self.assertTrue(self.shown("paused", True))
        finally:
            set_paused(paused=False)
        self.assertTrue(self.shown("paused", False))

    def test_5_winch_speed(self):
        start = self.state().deployed_length
        reply = self.update(winch_speed=1.0)
        self.assertEqual(reply["winch_speed"], 1.0)
        time.sleep(4.0)  # ramps at 1 m/s^2 to 1 m/s: about 3.5 m in 4 s
        paid_out = self.state().deployed_length - start
        print("winch tuned to 1 m/s: %.2f m paid out in 4 s" % paid_out)
        self.assertGreater(paid_out, 2.0)
        self.assertLess(paid_out, 4.5)
        reply = self.update(winch_speed=2.5)  # beyond winch.max_speed = 2
        self.assertEqual(reply["winch_speed"], 1.0)
        # A winch/speed message replaces the tuned speed: the server shows the one in force (issue 27: it
        # kept showing the tuned 1.0).
        speed = rospy.Publisher(NS + "/winch/speed", Float64, queue_size=1, latch=True)
        speed.publish(Float64(0.5))
        self.assertTrue(self.shown("winch_speed", 0.5), "the server still shows the tuned winch speed")
        self.update(winch_speed=0.0)
        time.sleep(2.0)
        self.assertLess(abs(self.state().winch_speed), 1e-9)
        speed.unregister()

    def test_6_the_current_topic_shows_in_the_server(self):
        # While the current topic publishes, its current is in force: the server shows it, and a tuned
        # current is refused (the topic takes precedence).
        topic = rospy.Publisher(NS + "/current", TwistStamped, queue_size=1)
        time.sleep(0.5)  # the connection
        flow = TwistStamped()
        flow.header.frame_id = "world"
        flow.twist.linear.y = 0.25
        deadline = time.time() + 3.0
        while time.time() < deadline:
            flow.header.stamp = rospy.Time.now()
            topic.publish(flow)
            time.sleep(0.05)
        self.assertTrue(self.shown("current_y", 0.25), "the server does not show the topic's current")
        flow.header.stamp = rospy.Time.now()
        topic.publish(flow)
        reply = self.update(current_y=0.0)
        self.assertEqual(reply["current_y"], 0.25)
        # Silent for longer than ros.input_timeout: tuning sets it again.
        topic.unregister()
        time.sleep(2.5)
        reply = self.update(current_y=0.0)
        self.assertEqual(reply["current_y"], 0.0)


if __name__ == "__main__":
    rospy.init_node("test_tuning_node", anonymous=True)
    rosunit.unitrun("cable_dynamics", "tuning_node", Tuning)
