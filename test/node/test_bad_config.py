#!/usr/bin/env python3
"""A bad or missing parameter stops cable_dynamics_node at start: non-zero exit, the key named."""
import subprocess
import unittest

import rosgraph
import roslib.packages
import rospy
import rosunit

GOOD = {"cable": {"links": 3, "length": 6.0, "diameter": 0.02, "mass_per_length": 0.5}}

CASES = {
    # namespace: (parameters, key expected in the error)
    "bad_links": ({"cable": dict(GOOD["cable"], links=0)}, "cable.links"),
    "bad_length": ({"cable": dict(GOOD["cable"], length=-1.0)}, "cable.length"),
    "unknown_key": ({"cable": dict(GOOD["cable"], lenght=3.0)}, "cable.lenght"),
    "bad_rate": ({"cable": GOOD["cable"], "ros": {"rate": 0.0}}, "ros.rate"),
    "missing_cable": ({"gravity": 9.81}, "cable"),
    "paper_torsion": ({"cable": dict(GOOD["cable"], stiffness={"model": "paper", "torsion": 1.0})},
                      "cable.stiffness.torsion"),
}


def node_binary():
    found = roslib.packages.find_node("cable_dynamics", "cable_dynamics_node")
    assert found, "cable_dynamics_node is not built"
    return found[0]


def run_node(namespace):
    cmd = [node_binary(), "__ns:=/" + namespace]
    return subprocess.run(cmd, capture_output=True, text=True, timeout=60)


class BadConfig(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        assert rosgraph.is_master_online(), "rostest starts a master"
        for namespace, (params, _) in CASES.items():
            rospy.set_param("/%s/cable_dynamics_node" % namespace, params)
        rospy.set_param("/good/cable_dynamics_node", GOOD)

    def test_each_bad_parameter_stops_the_node_with_its_key(self):
        for namespace, (_, key) in CASES.items():
            with self.subTest(namespace=namespace):
                done = run_node(namespace)
                self.assertNotEqual(done.returncode, 0, done.stdout + done.stderr)
                output = done.stdout + done.stderr
                self.assertIn(key, output)
                self.assertIn("expected", output)

    def test_a_good_config_keeps_running(self):
        process = subprocess.Popen([node_binary(), "__ns:=/good"],
                                   stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        try:
            with self.assertRaises(subprocess.TimeoutExpired):
                process.wait(timeout=5)  # still running after 5 s
        finally:
            process.terminate()
            process.wait(timeout=20)


if __name__ == "__main__":
    rospy.init_node("test_bad_config", anonymous=True)
    rosunit.unitrun("cable_dynamics", "bad_config", BadConfig)
