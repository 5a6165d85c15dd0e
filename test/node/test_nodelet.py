#!/usr/bin/env python3
"""The cable as a nodelet (test/nodelet.test): cable_dynamics/CableNodelet loaded into a manager publishes
cable_state and joint_states (test/node/node_test.yaml: 6 links, so 18 joints) from the manager's process,
and offers the same services and live tuning as the standalone node; a second nodelet with a bad
parameter in the same manager stays idle without stopping it."""
import time
import unittest

import rosgraph
import rospy
import rosunit
from cable_msgs.msg import CableState
from cable_msgs.srv import GetModel
from sensor_msgs.msg import JointState

NS = "/nodelet_test"


class Nodelet(unittest.TestCase):
    def test_publishes_from_the_manager(self):
        got = {}
        rospy.Subscriber(NS + "/cable_state", CableState, lambda m: got.setdefault("states", []).append(m))
        rospy.Subscriber(NS + "/joint_states", JointState, lambda m: got.update(joints=m))
        deadline = time.time() + 60.0
        while (len(got.get("states", [])) < 20 or "joints" not in got) and time.time() < deadline:
            time.sleep(0.05)
        self.assertGreaterEqual(len(got.get("states", [])), 20, "cable_state from the nodelet")
        self.assertIn("joints", got, "joint_states from the nodelet")
        joints = got["joints"]
        self.assertEqual(len(joints.name), 18)
        self.assertEqual(joints.name[0], "nodelet_test/joint_1_elevation")
        self.assertEqual(len(joints.position), 18)
        states = got["states"]
        self.assertGreater(states[-1].sim_time, states[0].sim_time)  # it steps
        self.assertEqual(len(states[-1].tension), 6)

        # Published by the manager's process, not by a node of its own.
        publishers, _, services = rosgraph.Master("/test_nodelet").getSystemState()
        by_topic = dict(publishers)
        self.assertEqual(by_topic.get(NS + "/cable_state"), [NS + "/manager"])
        self.assertEqual(by_topic.get(NS + "/joint_states"), [NS + "/manager"])
        providers = dict(services)
        self.assertEqual(providers.get(NS + "/get_model"), [NS + "/manager"])
        self.assertEqual(providers.get(NS + "/cable/tuning/set_parameters"), [NS + "/manager"])
        model = rospy.ServiceProxy(NS + "/get_model", GetModel)()
        self.assertEqual(len(model.q), 18)

        # The nodelet with cable.links = 0 (test/nodelet.test) runs nothing, in the same manager, which
        # goes on hosting the good one: nothing of it on the graph, cable_state still coming.
        self.assertNotIn("/bad_nodelet/cable_state", by_topic)
        self.assertNotIn("/bad_nodelet/get_model", providers)
        count = len(got["states"])
        time.sleep(1.0)
        self.assertGreater(len(got["states"]), count + 20)


if __name__ == "__main__":
    rospy.init_node("test_nodelet", anonymous=True)
    rosunit.unitrun("cable_dynamics", "nodelet", Nodelet)
