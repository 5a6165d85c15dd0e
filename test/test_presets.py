"""Every preset in config/ runs to its configured end with cable_sim, writing only finite numbers; the
current preset settles to the quasi-static shape of an independent shooting solver
(test/reference/static_current.py, which knows nothing of the dynamics)."""
import glob
import math
import os
import subprocess
import sys

import numpy as np
import pytest
import yaml

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(HERE)
sys.path.insert(0, os.path.join(HERE, "reference"))
import static_current  # noqa: E402

PRESETS = sorted(glob.glob(os.path.join(REPO, "config", "*.yaml")))
# cable_sim --statics against the shooting reference, the same discrete chain: measured -5.9e-8 on the top
# tension and 2.3e-10 on the top angle (the CSV's 10 significant digits resolve 3.4e-10 of it); 5x and 9x.
# test_python_bindings.py holds the same pair to its REFERENCE_TOLERANCE, 1e-6.
TENSION_TOLERANCE = 3e-7
ANGLE_TOLERANCE = 2e-9


def binary(name):
    path = os.environ.get(name)
    if not path:
        pytest.fail(f"set {name} to the built executable (scripts/test.sh does)")
    return path


def run_sim(config, out_csv, *extra):
    cmd = [binary("CABLE_SIM_BIN"), "--config", config, "--output", out_csv, "--sample", "0.05", *extra]
    done = subprocess.run(cmd, capture_output=True, text=True, timeout=900)
    assert done.returncode == 0, f"{' '.join(cmd)}\n{done.stderr}"
    return done.stderr


def shooting_reference(cfg):
    """The shooting solver's equilibrium for a preset, its cable's numbers read from the YAML here (not from
    cable_model's JSON, which the code under test writes): n equal links of the section's submerged mass
    per metre, m' - rho pi d^2 / 4, and the load's mass less rho times its volume."""
    cable, load, fluid = cfg["cable"], cfg["load"], cfg["fluid"]
    assert "sections" not in cable and "winch" not in cfg and "attachments" not in cfg, "a uniform cable"
    assert fluid["current"][1:] == [0.0, 0.0], "the reference is planar: current along x"
    rho, d = fluid["density"], cable["diameter"]
    lengths, submerged = static_current.uniform_cable(cable["length"], cable["links"],
                                                      cable["mass_per_length"] - rho * math.pi * d * d / 4.0)
    return static_current.solve_static_current(lengths, submerged, load["mass"] - rho * load.get("volume", 0.0), d,
                                               rho, fluid["drag_normal"], fluid["drag_tangential"],
                                               fluid["current"][0], cfg["gravity"], load.get("drag_area", 0.0))


def read_csv(path):
    with open(path) as f:
        header = f.readline().strip().split(",")
    return header, np.loadtxt(path, delimiter=",", skiprows=1, ndmin=2)


@pytest.mark.parametrize("config", PRESETS, ids=[os.path.basename(p) for p in PRESETS])
def test_preset_runs_to_its_end(config, tmp_path):
    out = str(tmp_path / "run.csv")
    run_sim(config, out)
    header, data = read_csv(out)
    assert header[0] == "time" and "top_tension" in header and "end1_x" in header
    # Every value finite, but a straight joint's bend radius: +inf (`inf` in the CSV), never NaN or -inf.
    radius = np.array([name.startswith("bend_radius") or name == "min_bend_radius" for name in header])
    assert np.all(np.isfinite(data[:, ~radius])), "non-finite value in the output"
    assert np.all(np.isfinite(data[:, radius]) | (data[:, radius] == np.inf)), "NaN or -inf bend radius"
    duration = yaml.safe_load(open(config))["simulation"]["duration"]
    assert data[-1, 0] == pytest.approx(duration, abs=1e-9)


def test_current_preset_settles_to_the_quasi_static_shape(tmp_path):
    config = os.path.join(REPO, "config", "paper_current.yaml")
    out = str(tmp_path / "run.csv")
    run_sim(config, out)
    header, data = read_csv(out)
    last = dict(zip(header, data[-1]))
    cfg = yaml.safe_load(open(config))
    static = shooting_reference(cfg)
    top_angle = last["joint_1_elevation"]  # angle of the top link from the downward vertical
    tension_error = last["top_tension"] / static["top_tension"] - 1.0
    angle_error = top_angle / static["top_angle"] - 1.0
    print(f"top tension: simulated {last['top_tension']:.6f} N, quasi-static {static['top_tension']:.6f} N "
          f"({tension_error:.2e}); top angle: simulated {top_angle:.8f} rad, quasi-static "
          f"{static['top_angle']:.8f} rad ({angle_error:.2e})")
    # After 36 s what is left is the start's transient, still dying out (not a numerical error): measured
    # 3.7e-6 on the tension and -8.9e-6 on the angle; about 5x above. (The bound was 2 %.)
    assert abs(tension_error) < 2e-5
    assert abs(angle_error) < 5e-5
    # Still moving? The steady state must be steady: the tension changed little over the last 5 s.
    late = data[data[:, 0] > data[-1, 0] - 5.0, header.index("top_tension")]
    assert np.ptp(late) < 0.002 * static["top_tension"]


def test_statics_match_the_shooting_reference(tmp_path):
    """cable_sim --statics against the independent shooting solver (test/reference/static_current.py):
    the same discrete chain in the same current, so the two agree to the solvers' tolerances (the issue
    asked for 0.5 %; see TENSION_TOLERANCE)."""
    config = os.path.join(REPO, "config", "paper_current.yaml")
    out = str(tmp_path / "statics.csv")
    cmd = [binary("CABLE_SIM_BIN"), "--config", config, "--statics", "--output", out]
    done = subprocess.run(cmd, capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    header, data = read_csv(out)
    assert data.shape[0] == 1, "one row: the equilibrium"
    row = dict(zip(header, data[0]))
    cfg = yaml.safe_load(open(config))
    static = shooting_reference(cfg)
    print(done.stderr.strip())
    tension_error = row["top_tension"] / static["top_tension"] - 1.0
    angle_error = row["joint_1_elevation"] / static["top_angle"] - 1.0
    print(f"top tension {row['top_tension']:.9f} N against {static['top_tension']:.9f} N ({tension_error:.2e}); "
          f"top angle {row['joint_1_elevation']:.10f} rad against {static['top_angle']:.10f} rad ({angle_error:.2e})")
    assert row["top_tension"] == pytest.approx(static["top_tension"], rel=TENSION_TOLERANCE)
    assert row["joint_1_elevation"] == pytest.approx(static["top_angle"], rel=ANGLE_TOLERANCE)
    assert np.all(np.abs(data[0, [header.index(c) for c in header if c.endswith("_rate")]]) == 0.0)


def test_statics_say_when_there_is_no_equilibrium(tmp_path):
    config = os.path.join(REPO, "config", "paper_seabed.yaml")
    cfg = yaml.safe_load(open(config))
    length = cfg["cable"]["length"]
    cmd = [binary("CABLE_SIM_BIN"), "--config", config, "--statics", "--output", str(tmp_path / "s.csv"),
           "--set", f"load.motion.offset=[{2.0 * length}, 0.0, {length}]"]
    done = subprocess.run(cmd, capture_output=True, text=True, timeout=120)
    assert done.returncode == 6, done.stderr
    assert "no equilibrium" in done.stderr and "m long" in done.stderr
