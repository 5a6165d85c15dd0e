#!/usr/bin/env python3
"""Item 6 of issue 11: a cable the node cannot step in real time (test/node/slow_test.yaml: on any machine,
its step count per cycle caps the real-time factor at 0.4). The node keeps publishing (the rate, the
machine's, is printed); the real-time factor it reports matches the simulated time it publishes and stays
below the step count's cap; the lag stays bounded by ros.max_lag; diagnostics say so.
Starting commit: one cycle took ~0.8 s (2000 steps), cable_state came at ~1.8 Hz and the lag grew."""
import time
import unittest

import rospy
import rosunit
from cable_msgs.msg import CableState
from diagnostic_msgs.msg import DiagnosticArray, DiagnosticStatus

MAX_LAG = 1.0  # ros.max_lag, its default in slow_test.yaml [s]
MAX_RTF = 40 * 1.0e-4 * 100.0  # ros.max_steps_per_cycle x simulation.dt x ros.rate: the most it can simulate [-]


class CatchUp(unittest.TestCase):
    def test_publishing_keeps_its_rate_and_the_lag_is_reported(self):
        states, diagnostics = [], []
        rospy.Subscriber("/slow/cable_state", CableState, lambda m: states.append((time.time(), m)), queue_size=1000)
        rospy.Subscriber("/diagnostics", DiagnosticArray,
                         lambda m: diagnostics.extend(s for s in m.status if s.name == "cable_dynamics: slow/"))
        deadline = time.time() + 30.0
        while len(states) < 50 and time.time() < deadline:
            time.sleep(0.05)
        self.assertGreaterEqual(len(states), 50, "cable_state came at %d messages in 30 s" % len(states))
        time.sleep(2.0)  # past the first rate window
        first = len(states)
        start_wall, start_state = time.time(), states[-1][1]
        time.sleep(4.0)
        end_wall, end_state = time.time(), states[-1][1]
        rate = (len(states) - first) / (end_wall - start_wall)
        measured_rtf = (end_state.sim_time - start_state.sim_time) / (end_wall - start_wall)
        print("catch-up: cable_state at %.1f Hz, real-time factor measured %.3f, reported %.3f, lag %.3f s" %
              (rate, measured_rtf, end_state.real_time_factor, end_state.lag))
        # How many cycles a second the timer fires is the machine's (29 Hz on a loaded 2-core machine,
        # near 100 on an idle one): printed above, not judged. That a cycle stops at its wall-time budget
        # is checked without the machine's speed in test_node_parts (CycleStepper); that it is bounded by
        # its step count, by the real-time factor below.
        # Honest timing: simulated seconds per wall second, measured here, against what the node reports.
        measured = (end_state.sim_time - start_state.sim_time) / (end_wall - start_wall)
        self.assertGreater(measured, 0.0)
        # At most 40 steps of 0.1 ms per 10 ms cycle (slow_test.yaml): 0.4 at best on any machine.
        self.assertLess(measured, MAX_RTF + 0.05, "more simulated time than the step bound allows")
        # The node reports its factor over its last window (>= 1 s); the load on a shared machine changes
        # it from one second to the next, so the comparison is over the same span: the mean of what it
        # reported for windows inside these 4 s (the messages from their second second on).
        reported = [m.real_time_factor for t, m in states[first:] if t >= start_wall + 1.0]
        self.assertTrue(reported, "no cable_state in the window")
        mean_reported = sum(reported) / len(reported)
        print("catch-up: reported real-time factor %.3f on average over the window, measured %.3f"
              % (mean_reported, measured))
        self.assertAlmostEqual(mean_reported, measured, delta=0.3 * measured)
        lags = [m.lag for _, m in states[first:]]
        self.assertLessEqual(max(lags), MAX_LAG + 0.05)
        self.assertGreater(min(lags), 0.5 * MAX_LAG)
        # The stamp is the simulated instant's ROS time: about a lag behind now, never ahead.
        behind = rospy.Time.now().to_sec() - end_state.header.stamp.to_sec()
        self.assertGreater(behind, 0.0)
        self.assertLess(behind, MAX_LAG + 0.5)
        self.assertTrue(diagnostics, "no diagnostics")
        last = diagnostics[-1]
        self.assertEqual(last.level, DiagnosticStatus.ERROR, last.message)
        self.assertIn("cannot keep up", last.message)
        values = {kv.key: kv.value for kv in last.values}
        self.assertGreater(float(values["dropped time [s]"]), 0.0)
        self.assertLess(float(values["real-time factor"]), MAX_RTF + 0.05)


if __name__ == "__main__":
    rospy.init_node("test_catch_up", anonymous=True)
    rosunit.unitrun("cable_dynamics", "catch_up", CatchUp)
