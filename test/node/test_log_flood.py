#!/usr/bin/env python3
"""Item 3 of issue 11: bad inputs on a per-message path give a throttled log line, never one per message,
and tf2 is not asked about invalid frame names (it prints a warning per call). The node runs as a
subprocess so that all its output (rosconsole and tf2's console_bridge) is counted. Starting commit: 200
poses in frame '/world' printed ~200 tf2 warnings."""
import signal
import subprocess
import time
import unittest

import rosgraph
import roslib.packages
import rospy
import rosunit
from cable_msgs.msg import CableState
from geometry_msgs.msg import PoseStamped

CONFIG = {"cable": {"links": 3, "length": 6.0, "diameter": 0.02, "mass_per_length": 0.5},
          "load": {"mode": "attached", "mass": 1.0}}
BAD_FRAMES = ["/world", "a b", "nowhere"]
PER_FRAME = 200
MAX_LINES = 6  # the start-up line, then at most one line per kind of refusal in the 5 s throttle period


class LogFlood(unittest.TestCase):
    def test_bad_frames_are_logged_with_a_throttle(self):
        assert rosgraph.is_master_online()
        rospy.set_param("/flood/cable_dynamics_node", CONFIG)
        binary = roslib.packages.find_node("cable_dynamics", "cable_dynamics_node")[0]
        node = subprocess.Popen([binary, "__ns:=/flood"], stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        try:
            state = rospy.wait_for_message("/flood/cable_state", CableState, timeout=20.0)
            rejected_before = state.rejected_inputs
            pub = rospy.Publisher("/flood/rov_pose", PoseStamped, queue_size=1000)
            deadline = time.time() + 10.0
            while pub.get_num_connections() == 0 and time.time() < deadline:
                time.sleep(0.05)
            rate = rospy.Rate(200.0)
            for frame in BAD_FRAMES:
                for _ in range(PER_FRAME):
                    msg = PoseStamped()
                    msg.header.stamp = rospy.Time.now()
                    msg.header.frame_id = frame
                    msg.pose.position.z = -6.0
                    msg.pose.orientation.w = 1.0
                    pub.publish(msg)
                    rate.sleep()
            time.sleep(1.0)
            state = rospy.wait_for_message("/flood/cable_state", CableState, timeout=5.0)
            self.assertEqual(state.rejected_inputs - rejected_before, len(BAD_FRAMES) * PER_FRAME)
        finally:
            node.send_signal(signal.SIGINT)  # a clean shutdown flushes the node's buffered stdout
            output, _ = node.communicate(timeout=20)
        lines = [line for line in output.splitlines() if line.strip()]
        print("log flood: %d messages in bad frames, %d lines of node output" % (len(BAD_FRAMES) * PER_FRAME, len(lines)))
        print("\n".join(lines))
        self.assertLessEqual(len(lines), MAX_LINES, "%d lines:\n%s" % (len(lines), "\n".join(lines[:20])))


if __name__ == "__main__":
    rospy.init_node("test_log_flood", anonymous=True)
    rosunit.unitrun("cable_dynamics", "log_flood", LogFlood)
