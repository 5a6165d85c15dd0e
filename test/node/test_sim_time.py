#!/usr/bin/env python3
"""With /use_sim_time the node steps on /clock: simulated time follows the published clock and stands
still while the clock does."""
import time
import unittest

import rospy
import rosunit
from cable_msgs.msg import CableState
from rosgraph_msgs.msg import Clock


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
                time.sleep(step)  # wall time paces the clock 1:1

        advance(2.0)  # let the node start on the clock
        deadline = time.time() + 20.0
        while "state" not in latest and time.time() < deadline:
            advance(0.1)
        self.assertIn("state", latest, "no cable_state on simulated time")
        start = latest["state"].sim_time
        advance(3.0)
        elapsed = latest["state"].sim_time - start
        self.assertGreater(elapsed, 2.5)
        self.assertLess(elapsed, 3.3)
        # The clock stops: so does the simulation.
        held = latest["state"].sim_time
        time.sleep(1.5)
        self.assertAlmostEqual(latest["state"].sim_time, held, delta=0.05)


if __name__ == "__main__":
    rospy.init_node("test_sim_time", anonymous=True)
    rosunit.unitrun("cable_dynamics", "sim_time", SimTime)
