#!/usr/bin/env python3
"""Hostile commands (issue 27): thousands of winch/speed messages, winch/set_length requests, equilibrium
resets and live tuning changes, valid ones mixed with NaN, infinities and values out of range, against the
node on test/node/fuzz_commands.yaml (a winch paying out onto a seabed with static friction). Each command's
fate is known by construction from the documented rules (docs/NODE.md; the ranges of docs/CONFIG.md); the
test checks that the node's counters say the same (rejected_inputs for the topic, refused_commands for the
services and the tuning), that every reply says what is in force, that no output carries a non-finite
number, and that no step diverged."""
import math
import random
import time
import unittest

import dynamic_reconfigure.client
import rospy
import rosunit
from cable_msgs.msg import CableState
from cable_msgs.srv import ResetToEquilibrium, SetWinchLength
from sensor_msgs.msg import JointState
from std_msgs.msg import Float64
from visualization_msgs.msg import MarkerArray

NS = "/fuzz_commands"
MAX_SPEED, MIN_LENGTH, MAX_LENGTH = 2.0, 6.0, 40.0  # fuzz_commands.yaml's winch
COMMANDS = 3000       # winch/speed messages; every 10th also a set_length request, every 100th a reset
TUNE_EVERY = 50       # a tuning change every 50th


def numbers(msg):
    """Every float in a message, recursively."""
    if isinstance(msg, float):
        yield msg
    elif isinstance(msg, (list, tuple)):
        for item in msg:
            yield from numbers(item)
    elif hasattr(msg, "__slots__"):
        for slot in msg.__slots__:
            yield from numbers(getattr(msg, slot))


class Recorder:
    def __init__(self):
        self.state = None
        self.counts = {"state": 0, "joints": 0, "markers": 0}
        self.non_finite = ""
        rospy.Subscriber(NS + "/cable_state", CableState, self.on, callback_args="state", queue_size=100)
        rospy.Subscriber(NS + "/joint_states", JointState, self.on, callback_args="joints", queue_size=100)
        rospy.Subscriber(NS + "/cable_markers", MarkerArray, self.on, callback_args="markers", queue_size=100)

    def on(self, msg, kind):
        self.counts[kind] += 1
        if kind == "state":
            self.state = msg
        if not self.non_finite and not all(math.isfinite(x) for x in numbers(msg)):
            self.non_finite = "%s at %.3f s" % (kind, time.time())


def hostile_number(rng, low, high):
    """A value the node must refuse for a key allowed in [low, high]."""
    return rng.choice([float("nan"), float("inf"), -float("inf"), low - 1e-3 - rng.random(), high + 1e-3 + rng.random(),
                       -1e300, 1e300])


class FuzzCommands(unittest.TestCase):
    def test_hostile_commands_are_refused_counted_and_change_nothing_they_should_not(self):
        rec = Recorder()
        deadline = time.time() + 60.0
        while rec.state is None and time.time() < deadline:
            time.sleep(0.05)
        self.assertIsNotNone(rec.state, "no cable_state in 60 s")
        rospy.wait_for_service(NS + "/winch/set_length", 30.0)
        rospy.wait_for_service(NS + "/reset_to_equilibrium", 30.0)
        client = dynamic_reconfigure.client.Client(NS + "/cable_dynamics_node/tuning", timeout=30.0)
        speed_pub = rospy.Publisher(NS + "/winch/speed", Float64, queue_size=1000)
        set_length = rospy.ServiceProxy(NS + "/winch/set_length", SetWinchLength)
        reset = rospy.ServiceProxy(NS + "/reset_to_equilibrium", ResetToEquilibrium)
        deadline = time.time() + 10.0
        while speed_pub.get_num_connections() == 0 and time.time() < deadline:
            time.sleep(0.05)
        start = rec.state
        rng = random.Random(20261204)
        rejected = refused = 0
        tuned = {"drag_normal": (0.0, 100.0), "added_mass": (0.0, 100.0), "current_x": (-100.0, 100.0),
                 "winch_speed": (-MAX_SPEED, MAX_SPEED)}
        in_force = client.get_configuration(timeout=10.0)
        for i in range(COMMANDS):
            if rng.random() < 0.5:
                speed_pub.publish(Float64(rng.uniform(-MAX_SPEED, MAX_SPEED)))
            else:
                speed_pub.publish(Float64(hostile_number(rng, -MAX_SPEED, MAX_SPEED)))
                rejected += 1
            if i % 10 == 5:
                valid = rng.random() < 0.5
                length = rng.uniform(MIN_LENGTH, MAX_LENGTH) if valid else hostile_number(rng, MIN_LENGTH, MAX_LENGTH)
                reply = set_length(length)
                self.assertEqual(reply.success, valid, "set_length %r: %s" % (length, reply.message))
                self.assertTrue(math.isfinite(reply.deployed_length))
                refused += not valid
            if i % 100 == 50:
                reply = reset()
                refused += not reply.success
                self.assertTrue(all(math.isfinite(x) for x in (reply.residual, reply.line_pull)))
            if i % TUNE_EVERY == 25:
                key = rng.choice(sorted(tuned))
                low, high = tuned[key]
                # Valid values well inside the range (a tuned current below 0.5 m/s, C_n and C_a below 3).
                valid = rng.random() < 0.5
                value = rng.uniform(max(low, -0.5), min(high, 3.0) if key != "current_x" else 0.5) if valid \
                    else hostile_number(rng, low, high)
                reply = client.update_configuration({key: value})
                if valid:
                    self.assertEqual(reply[key], value, key)
                elif key == "winch_speed":
                    # The speed in force is the last command's, the topic's or the tuning's: the messages
                    # still on their way make it a race, so only its range is known here.
                    self.assertTrue(-MAX_SPEED <= reply[key] <= MAX_SPEED, "winch_speed %r: shown %r" % (value, reply[key]))
                    refused += 1
                else:
                    self.assertEqual(reply[key], in_force[key], "%s %r: the old value must stay" % (key, value))
                    refused += 1
                in_force = reply
            time.sleep(0.002)
        # Every message counted, then the counters against the construction.
        deadline = time.time() + 20.0
        while rec.state.received_inputs - start.received_inputs < COMMANDS and time.time() < deadline:
            time.sleep(0.05)
        time.sleep(0.5)
        end = rec.state
        print("fuzz_commands: %d winch speeds (%d hostile), %d set_length, %d resets, %d tunings; expected %d refused; "
              "node: %d received, %d rejected, %d refused; %s outputs; deployed %.2f m, %d steps retried"
              % (COMMANDS, rejected, COMMANDS // 10, COMMANDS // 100, COMMANDS // TUNE_EVERY, refused,
                 end.received_inputs - start.received_inputs, end.rejected_inputs - start.rejected_inputs,
                 end.refused_commands - start.refused_commands, rec.counts, end.deployed_length, end.retried_steps))
        self.assertEqual(end.received_inputs - start.received_inputs, COMMANDS, "winch speeds lost on the way")
        self.assertEqual(end.rejected_inputs - start.rejected_inputs, rejected)
        self.assertEqual(end.refused_commands - start.refused_commands, refused)
        self.assertGreater(rejected, 1000)
        self.assertGreater(refused, 100)
        self.assertEqual(rec.non_finite, "", "a non-finite number was published")
        self.assertEqual(end.diverged_steps, 0)
        self.assertTrue(MIN_LENGTH - 1e-6 <= end.deployed_length <= MAX_LENGTH + 1e-6)
        self.assertGreater(min(rec.counts.values()), 100)


if __name__ == "__main__":
    rospy.init_node("test_fuzz_commands")
    rosunit.unitrun("cable_dynamics", "fuzz_commands", FuzzCommands)
