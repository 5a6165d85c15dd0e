#!/usr/bin/env python3
"""Item 5 of issue 11: launch/umbilical.launch clears the node's private parameters (a stale key from an
earlier launch in the same namespace no longer stops the node), and a bad config stops the launch: the
node exits 2 naming the key, and roslaunch, for which the node is required, shuts down.
roslaunch 1.15 (Debian 12) exits 0 even when a required node dies (measured); the test checks its output
instead, which names the dead process and its exit code.
Issue 22: an argument that is not given (rate, world_frame) leaves the config's own ros.rate and
ros.world_frame; a given one replaces it."""
import os
import subprocess
import tempfile
import time
import unittest

import rosgraph
import roslib.packages
import rospy
import rosunit
from cable_msgs.msg import CableState

GOOD_CONFIG = "cable: {links: 3, length: 6.0, diameter: 0.02, mass_per_length: 0.5}\n"
BAD_CONFIG = "cable: {links: 0, length: 6.0, diameter: 0.02, mass_per_length: 0.5}\n"
# A config with its own ros section: neither value is umbilical.launch's or the node's default.
OWN_ROS_CONFIG = GOOD_CONFIG + "ros: {rate: 37.0, world_frame: sea}\n"


def roslaunch(namespace, config, *args):
    return subprocess.Popen(["roslaunch", "cable_dynamics", "umbilical.launch", "ns:=" + namespace,
                             "config:=" + config, "rviz:=false"] + list(args),
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)


class LaunchFile(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        assert rosgraph.is_master_online()
        cls.dir = tempfile.mkdtemp()
        cls.good = os.path.join(cls.dir, "good.yaml")
        cls.bad = os.path.join(cls.dir, "bad.yaml")
        cls.own_ros = os.path.join(cls.dir, "own_ros.yaml")
        with open(cls.own_ros, "w") as f:
            f.write(OWN_ROS_CONFIG)
        with open(cls.good, "w") as f:
            f.write(GOOD_CONFIG)
        with open(cls.bad, "w") as f:
            f.write(BAD_CONFIG)

    def test_stale_private_parameters_are_cleared(self):
        # What an earlier launch with a misspelt key would have left behind.
        rospy.set_param("/stale/cable_dynamics_node/cable/lenght", 3.0)
        states = []
        subscriber = rospy.Subscriber("/stale/cable_state", CableState, states.append, queue_size=10)
        launch = roslaunch("stale", self.good)
        try:
            # Judged by an event, not by a time it survives: the node runs (it publishes its cable_state
            # after loading its parameters) and roslaunch is still up. At most 60 s for a loaded machine.
            deadline = time.time() + 60.0
            while not states and launch.poll() is None and time.time() < deadline:
                time.sleep(0.1)
            self.assertIsNone(launch.poll(), "roslaunch ended: the stale key stopped the node")
            self.assertTrue(states, "the node published no cable_state within 60 s")
            self.assertFalse(rospy.has_param("/stale/cable_dynamics_node/cable/lenght"))
            self.assertEqual(rospy.get_param("/stale/cable_dynamics_node/cable/links"), 3)
        finally:
            subscriber.unregister()
            launch.terminate()
            output, _ = launch.communicate(timeout=30)
        self.assertNotIn("bad parameter", output)

    def running_ros_params(self, namespace, *args):
        """ros.rate and ros.world_frame on the node's parameters, while it runs from OWN_ROS_CONFIG."""
        launch = roslaunch(namespace, self.own_ros, *args)
        try:
            with self.assertRaises(subprocess.TimeoutExpired, msg="roslaunch ended: the node stopped"):
                launch.wait(timeout=8)
            node = "/" + namespace + "/cable_dynamics_node/ros/"
            return rospy.get_param(node + "rate"), rospy.get_param(node + "world_frame")
        finally:
            launch.terminate()
            launch.communicate(timeout=30)

    def test_arguments_not_given_leave_the_configs_ros_keys(self):
        self.assertEqual(self.running_ros_params("own_ros"), (37.0, "sea"))

    def test_arguments_given_replace_the_configs_ros_keys(self):
        self.assertEqual(self.running_ros_params("given_ros", "rate:=50.0", "world_frame:=map"), (50.0, "map"))

    def test_a_bad_config_stops_the_launch_with_the_key_and_exit_code_2(self):
        launch = roslaunch("bad_launch", self.bad)
        try:
            output, _ = launch.communicate(timeout=40)
        except subprocess.TimeoutExpired:
            launch.terminate()
            output, _ = launch.communicate(timeout=30)
            self.fail("roslaunch kept running after the required node failed:\n" + output)
        self.assertIn("'cable.links'", output)
        self.assertIn("REQUIRED process [bad_launch/cable_dynamics_node-1] has died", output)
        self.assertIn("exit code 2", output)


if __name__ == "__main__":
    rospy.init_node("test_launch_file", anonymous=True)
    rosunit.unitrun("cable_dynamics", "launch_file", LaunchFile)
