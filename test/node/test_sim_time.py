#!/usr/bin/env python3
"""With /use_sim_time the node steps on /clock: simulated time follows the published clock and stands
still while the clock does."""
import time
import unittest

import rospy
import rosunit
from cable_msgs.msg import CableState
from rosgraph_msgs.msg import Clock

CYCLE = 0.01  # 1 / ros.rate [s] (test/node/node_test.yaml)
STEP = 0.002  # simulation.dt [s]


class SimTime(unittest.TestCase):
    def test_simulated_time_follows_the_clock(self):
        clock_pub = rospy.Publisher("/clock", Clock, queue_size=10)
        latest = {}
        rospy.Subscriber("/sim_cable/cable_state", CableState, lambda m: latest.update(state=m))
        now = rospy.Time(1000.0)

        def advance(seconds, step=0.01):
            nonlocal now
            for _ in range(int(round(seconds / step))):
                now += rospy.Duration(step)
                clock_pub.publish(Clock(clock=now))
                time.sleep(step)  # paces the clock; nothing below depends on how fast the node follows it

        def caught_up(timeout=30.0):
            """Waits (at most `timeout` s of wall time) until the node has published the clock's last
            instant: its cable_state is stamped with the ROS time of the simulated instant, within one
            cycle (10 ms at ros.rate 100 Hz) and one step (2 ms) of the clock."""
            deadline = time.time() + timeout
            while time.time() < deadline:
                if "state" in latest and latest["state"].header.stamp.to_sec() >= now.to_sec() - CYCLE - STEP - 1e-6:
                    return True
                time.sleep(0.02)
            return False

        advance(2.0)  # let the node start on the clock
        deadline = time.time() + 20.0
        while "state" not in latest and time.time() < deadline:
            advance(0.1)
        self.assertIn("state", latest, "no cable_state on simulated time")
        self.assertTrue(caught_up(), "the node did not follow the clock")
        start = latest["state"].sim_time
        advance(3.0)
        self.assertTrue(caught_up(), "the node did not follow the clock")
        elapsed = latest["state"].sim_time - start
        print("simulated %.4f s while the clock advanced 3 s" % elapsed)
        # Judged once the node has caught up with the clock, so the machine's speed does not enter: 3 s of
        # clock are 3 s of simulated time, to a cycle at either end.
        self.assertAlmostEqual(elapsed, 3.0, delta=2 * (CYCLE + STEP))
        # The clock stops: so does the simulation, exactly.
        held = latest["state"].sim_time
        time.sleep(1.5)
        self.assertEqual(latest["state"].sim_time, held)

if __name__ == "__main__":
    rospy.init_node("test_sim_time", anonymous=True)
    rosunit.unitrun("cable_dynamics", "sim_time", SimTime)
