"""cable_sim --bag: the bag of a short run, read back with Debian's Python rosbag (its own reader, which
decodes the messages from the definitions stored in the bag), against the CSV of the same run: the topics,
one message per sample on each, stamps = 1 s + the CSV's time and increasing, joint positions, tensions,
the top tension and the frames' origins equal to the CSV's numbers (the CSV has 10 significant digits:
compared to 1e-9 relative), and `rosbag info` reads it."""
import os
import subprocess

import numpy as np
import pytest
import rosbag

CONFIG_DIR = os.environ.get("CABLE_CONFIG_DIR", os.path.join(os.path.dirname(__file__), "..", "..", "config"))
NS = "/umbilical/"
TOPICS_PER_SAMPLE = [NS + t for t in ("joint_states", "cable_state", "cable_markers", "rov_wrench", "rov_wrench_world",
                                      "base_wrench", "base_wrench_world")] + ["/tf"]
TIME_ORIGIN = 1.0  # s: bag times are the simulated time plus this (rosbag refuses a time of 0)
# The CSV's 10 significant digits: a value and its CSV text differ by at most 5e-10 of the value.
CSV_RELATIVE = 1e-9


def cable_sim():
    path = os.environ.get("CABLE_SIM_BIN")
    if not path:
        pytest.fail("set CABLE_SIM_BIN to the built cable_sim (scripts/test.sh does)")
    return path


def run(config, tmp_path, *extra):
    csv, bag = str(tmp_path / "run.csv"), str(tmp_path / "run.bag")
    cmd = [cable_sim(), "--config", os.path.join(CONFIG_DIR, config), "--output", csv, "--bag", bag, *extra]
    done = subprocess.run(cmd, capture_output=True, text=True, timeout=600)
    assert done.returncode == 0, f"{' '.join(cmd)}\n{done.stderr}"
    with open(csv) as f:
        header = f.readline().strip().split(",")
    data = np.loadtxt(csv, delimiter=",", skiprows=1, ndmin=2)
    return bag, {name: data[:, i] for i, name in enumerate(header)}, len(data)


def by_topic(bag_path):
    messages = {}
    with rosbag.Bag(bag_path) as bag:
        for topic, msg, t in bag.read_messages():
            messages.setdefault(topic, []).append((t.to_sec(), msg))
    return messages


def close(a, b):
    return np.allclose(a, b, rtol=CSV_RELATIVE, atol=1e-12)


def test_default_run_replays_the_csv(tmp_path):
    bag, csv, rows = run("default.yaml", tmp_path, "--set", "cable.links=10", "--set", "fluid.current=[0.5,0,0]",
                         "--duration", "1", "--sample", "0.1")
    assert rows == 11
    messages = by_topic(bag)
    assert sorted(messages) == sorted(TOPICS_PER_SAMPLE + [NS + "robot_description"])
    assert len(messages[NS + "robot_description"]) == 1
    assert "<robot" in messages[NS + "robot_description"][0][1].data
    for topic in TOPICS_PER_SAMPLE:
        assert len(messages[topic]) == rows, topic
        times = np.array([t for t, _ in messages[topic]])
        assert np.all(np.diff(times) > 0), topic
        assert np.allclose(times, TIME_ORIGIN + csv["time"], atol=1e-9), topic

    n = 10
    names = [f"joint_{k}_{a}" for k in range(1, n + 1) for a in ("elevation", "azimuth", "torsion")]
    for row, (t, js) in enumerate(messages[NS + "joint_states"]):
        assert js.header.stamp.to_sec() == pytest.approx(t, abs=1e-9)
        assert list(js.name) == ["umbilical/" + j for j in names]
        assert close(js.position, [csv[j][row] for j in names]), row
        assert close(js.velocity, [csv[j + "_rate"][row] for j in names]), row
    for row, (t, state) in enumerate(messages[NS + "cable_state"]):
        assert state.sim_time == pytest.approx(csv["time"][row], abs=1e-12)
        assert close(state.tension, [csv[f"tension{k}"][row] for k in range(1, n + 1)]), row
        assert close(state.top_tension, csv["top_tension"][row]), row
        assert close(state.kinetic_energy, csv["kinetic_energy"][row]), row
    # The frames (paper frame, z down, as the CSV): link K starts at the end of link K-1, the load at the tip.
    for row, (t, tf) in enumerate(messages["/tf"]):
        origin = {x.child_frame_id: x.transform.translation for x in tf.transforms}
        for k in range(2, n + 1):
            o = origin[f"umbilical/link_{k}"]
            assert close([o.x, o.y, o.z], [csv[f"end{k - 1}_{c}"][row] for c in "xyz"]), (row, k)
        o = origin["umbilical/cable_load"]
        assert close([o.x, o.y, o.z], [csv[f"end{n}_{c}"][row] for c in "xyz"]), row
    # The current has pushed the cable downstream by the end: the bag is not of a cable at rest.
    assert csv[f"end{n}_x"][-1] > 1e-3

    info = subprocess.run(["rosbag", "info", bag], capture_output=True, text=True, timeout=60)
    assert info.returncode == 0, info.stderr
    assert "cable_msgs/CableState" in info.stdout and f"{NS}cable_state" in info.stdout


def test_winch_run_carries_the_deployed_links(tmp_path):
    # rov_dive: a winch paying out; the joint states and frames carry the deployed links only.
    bag, csv, rows = run("rov_dive.yaml", tmp_path, "--duration", "20", "--sample", "1")
    messages = by_topic(bag)
    deployed = csv["deployed_links"].astype(int)
    assert deployed[-1] > deployed[0], "the winch paid no link out in 20 s"
    for row, (t, js) in enumerate(messages[NS + "joint_states"]):
        assert len(js.position) == 3 * deployed[row], row
    for row, (t, state) in enumerate(messages[NS + "cable_state"]):
        assert close(state.deployed_length, csv["deployed_length"][row]), row
        assert close(state.top_tension, csv["top_tension"][row]), row


def test_bag_refused_with_statics(tmp_path):
    done = subprocess.run([cable_sim(), "--config", os.path.join(CONFIG_DIR, "default.yaml"), "--statics", "--output",
                           str(tmp_path / "s.csv"), "--bag", str(tmp_path / "s.bag")], capture_output=True, text=True,
                          timeout=60)
    assert done.returncode == 2 and "--bag" in done.stderr
