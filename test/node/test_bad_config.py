#!/usr/bin/env python3
"""A bad or missing parameter stops cable_dynamics_node at start: exit status 2, the key named, and the
allowed range ("expected"). Table-driven: each case sets one namespace's private parameters (as
rosparam would from a YAML file: a quoted YAML scalar arrives as a string) and starts the node there."""
import re
import subprocess
import unittest

import rosgraph
import roslib.packages
import rospy
import rosunit

GOOD_CABLE = {"links": 3, "length": 6.0, "diameter": 0.02, "mass_per_length": 0.5}
GOOD = {"cable": GOOD_CABLE}


def cable(**changes):
    c = dict(GOOD_CABLE, **changes)
    return {k: v for k, v in c.items() if v is not None}


def with_cable(extra):
    return dict({"cable": GOOD_CABLE}, **extra)


def ros(**keys):
    return with_cable({"ros": keys})


NAN, INF = float("nan"), float("inf")

# (name, parameters, key expected in the error)
CASES = [
    # cable.*: ranges, types, strings for numbers, fractional integers, NaN, unknown keys
    ("links_zero", {"cable": cable(links=0)}, "cable.links"),
    ("links_negative", {"cable": cable(links=-3)}, "cable.links"),
    ("links_fraction", {"cable": cable(links=2.5)}, "cable.links"),
    ("links_string", {"cable": cable(links="25")}, "cable.links"),
    ("links_too_many", {"cable": cable(links=100000)}, "cable.links"),
    ("links_bool", {"cable": cable(links=True)}, "cable.links"),
    ("links_list", {"cable": cable(links=[3])}, "cable.links"),
    ("length_negative", {"cable": cable(length=-1.0)}, "cable.length"),
    ("length_zero", {"cable": cable(length=0.0)}, "cable.length"),
    ("length_string", {"cable": cable(length="50.0")}, "cable.length"),
    ("length_nan", {"cable": cable(length=NAN)}, "cable.length"),
    ("length_inf", {"cable": cable(length=INF)}, "cable.length"),
    ("diameter_missing", {"cable": cable(diameter=None)}, "cable.diameter"),
    ("diameter_too_big", {"cable": cable(diameter=11.0)}, "cable.diameter"),
    ("diameter_word", {"cable": cable(diameter="thin")}, "cable.diameter"),
    ("mass_negative", {"cable": cable(mass_per_length=-0.5)}, "cable.mass_per_length"),
    ("both_densities", {"cable": cable(material_density=1000.0)}, "cable.mass_per_length"),
    ("link_lengths_count", {"cable": cable(link_lengths=[1.0, 2.0])}, "cable.link_lengths"),
    ("unknown_cable_key", {"cable": cable(lenght=3.0)}, "cable.lenght"),
    ("stiffness_model", {"cable": cable(stiffness={"model": "rubber"})}, "cable.stiffness.model"),
    ("stiffness_negative", {"cable": cable(stiffness={"model": "bending", "elevation": -1.0})},
     "cable.stiffness.elevation"),
    ("paper_torsion", {"cable": cable(stiffness={"model": "paper", "torsion": 1.0})}, "cable.stiffness.torsion"),
    ("damping_string", {"cable": cable(damping={"elevation": "0.1"})}, "cable.damping.elevation"),
    ("missing_cable", {"gravity": 9.81}, "cable"),
    ("cable_not_a_map", {"cable": 5}, "cable"),
    # other sections
    ("gravity_negative", with_cable({"gravity": -9.81}), "gravity"),
    ("load_mode", with_cable({"load": {"mode": "towed"}}), "load.mode"),
    ("load_mass_nan", with_cable({"load": {"mass": NAN}}), "load.mass"),
    ("coupling_zero", with_cable({"load": {"coupling": {"stiffness": 0.0}}}), "load.coupling.stiffness"),
    ("fluid_density", with_cable({"fluid": {"density": -1.0}}), "fluid.density"),
    ("current_size", with_cable({"fluid": {"current": [1.0, 0.0]}}), "fluid.current"),
    ("current_string", with_cable({"fluid": {"current": ["1", 0.0, 0.0]}}), "fluid.current[0]"),
    ("drag_points_fraction", with_cable({"fluid": {"drag_points": 2.5}}), "fluid.drag_points"),
    ("dt_zero", with_cable({"simulation": {"dt": 0.0}}), "simulation.dt"),
    ("dt_string", with_cable({"simulation": {"dt": "0.001"}}), "simulation.dt"),
    ("integrator", with_cable({"simulation": {"integrator": "euler"}}), "simulation.integrator"),
    ("initial_elevation", with_cable({"initial": {"elevation": 4.0}}), "initial.elevation"),
    ("unknown_section", with_cable({"cabel": {"links": 3}}), "cabel"),
    # ros.*
    ("rate_zero", ros(rate=0.0), "ros.rate"),
    ("rate_too_high", ros(rate=1e5), "ros.rate"),
    ("rate_string", ros(rate="100"), "ros.rate"),
    ("rate_nan", ros(rate=NAN), "ros.rate"),
    ("max_steps_fraction", ros(max_steps_per_cycle=1.5), "ros.max_steps_per_cycle"),
    ("max_steps_zero", ros(max_steps_per_cycle=0), "ros.max_steps_per_cycle"),
    ("max_steps_string", ros(max_steps_per_cycle="2000"), "ros.max_steps_per_cycle"),
    ("world_frame_slash", ros(world_frame="/world"), "ros.world_frame"),
    ("world_frame_space", ros(world_frame="a b"), "ros.world_frame"),
    ("world_frame_empty", ros(world_frame=""), "ros.world_frame"),
    ("frame_prefix_slash", ros(frame_prefix="/cable/"), "ros.frame_prefix"),
    ("input_timeout_negative", ros(input_timeout=-1.0), "ros.input_timeout"),
    ("input_timeout_inf", ros(input_timeout=INF), "ros.input_timeout"),
    ("base_position_size", ros(base_position=[0.0, 0.0]), "ros.base_position"),
    ("base_position_huge", ros(base_position=[0.0, 0.0, 1e300]), "ros.base_position[2]"),
    ("base_position_string", ros(base_position=["0", 0.0, 0.0]), "ros.base_position[0]"),
    ("tension_scale_negative", ros(tension_scale=-5.0), "ros.tension_scale"),
    ("diagnostics_period_zero", ros(diagnostics_period=0.0), "ros.diagnostics_period"),
    ("max_lag_zero", ros(max_lag=0.0), "ros.max_lag"),
    ("vessel_size_zero", ros(vessel_size=[30.0, 0.0, 4.0]), "ros.vessel_size[1]"),
    ("rov_size_short", ros(rov_size=[2.0, 1.4]), "ros.rov_size"),
    ("unknown_ros_key", ros(rat=10.0), "ros.rat"),
    ("ros_not_a_map", with_cable({"ros": 3}), "ros"),
]


def node_binary():
    found = roslib.packages.find_node("cable_dynamics", "cable_dynamics_node")
    assert found, "cable_dynamics_node is not built"
    return found[0]


def run_node(namespace):
    """Runs the node in `namespace` for at most 10 s (it stops in well under a second on a bad parameter);
    returns (exit status or None if it was still running, its output)."""
    cmd = [node_binary(), "__ns:=/" + namespace]
    try:
        done = subprocess.run(cmd, capture_output=True, text=True, timeout=10)
        return done.returncode, done.stdout + done.stderr
    except subprocess.TimeoutExpired as e:
        return None, "still running after 10 s (the parameter was accepted): %s" % (e.stdout or b"")


class BadConfig(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        assert rosgraph.is_master_online(), "rostest starts a master"
        assert len(CASES) >= 40 and len({name for name, _, _ in CASES}) == len(CASES)
        for name, params, _ in CASES:
            rospy.set_param("/%s/cable_dynamics_node" % name, params)
        rospy.set_param("/good/cable_dynamics_node", GOOD)

    def test_each_bad_parameter_stops_the_node_with_exit_2_and_its_key(self):
        for name, _, key in CASES:
            with self.subTest(case=name):
                status, output = run_node(name)
                self.assertEqual(status, 2, output)
                # The key as a whole word (not "cable" inside "cable_dynamics_node").
                self.assertRegex(output, r"(?<![\w.])%s(?![\w.\[])" % re.escape(key))
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
