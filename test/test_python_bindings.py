"""The Python module `cable_dynamics` (cable_dynamics/python/) against independent truths.

What is checked, and against what:
* the static tension of a hanging chain: the submerged weight below each link's base end, computed here
  from the config's numbers (mass per length, diameter, water density, load), both at the vertical rest
  state and after the static solver;
* a single link in air swinging: the compound pendulum's period from its inertia about the pivot;
* the model's matrices: the same as `cable_model`'s JSON at the same state (the C++ tool, no Python),
  M, K, D symmetric and M positive definite;
* the current: the equilibrium in a current along x and along y against the independent shooting solver
  test/reference/static_current.py (knows nothing of the C++ code), which also checks the current's axes;
* the winch: a speed command pays out by the ramp-and-cruise distance of the winch's acceleration law;
* the README example (cable_dynamics/python/examples/current_sweep.py) is the README's text, runs through a
  shell after `source devel/setup.bash` as a user would, and prints top tensions equal to the reference's;
* bad input: a ValueError naming the argument or key, and its range; a configuration cable_sim refuses
  (an RK4 step beyond the cable's stable limit, the paper model's singular springs) is refused with
  cable_sim's own message, which the test reads from cable_sim itself;

Environment: CABLE_MODEL_BIN (the built cable_model), CABLE_SIM_BIN (the built cable_sim) and CABLE_DEVEL_SETUP
(the devel space's setup.bash);
the tests that need them fail, not skip, without them.
"""
import json
import math
import os
import subprocess
import sys

import numpy as np
import pytest

import cable_dynamics

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(HERE)
EXAMPLE = os.path.join(REPO, "cable_dynamics", "python", "examples", "current_sweep.py")
sys.path.insert(0, os.path.join(HERE, "reference"))
import static_current  # noqa: E402

G = 9.81
RHO = 1025.0


def required_env(name):
    value = os.environ.get(name)
    if not value:
        pytest.fail(f"set {name} (test/tests.cmake does)")
    return value


def hanging_config(links=10, length=20.0, diameter=0.03, mass_per_length=1.5, load_mass=40.0, load_volume=0.01):
    return {
        "cable": {"links": links, "length": length, "diameter": diameter, "mass_per_length": mass_per_length},
        "load": {"mass": load_mass, "volume": load_volume},
        "fluid": {"density": RHO, "current": [0.0, 0.0, 0.0]},
        "gravity": G,
    }


def submerged_weight_below(cfg):
    """(n) the submerged weight below each link's base end [N], from the config's numbers alone."""
    c, load = cfg["cable"], cfg["load"]
    n, l = c["links"], c["length"] / c["links"]
    link = (c["mass_per_length"] - RHO * math.pi * (c["diameter"] / 2) ** 2) * l * G  # [N]
    tip = (load["mass"] - RHO * load["volume"]) * G
    return np.array([tip + (n - k) * link for k in range(n)])


# --- tension of a hanging chain -------------------------------------------------------------------

def test_hanging_chain_tension_is_the_submerged_weight_below():
    cfg = hanging_config()
    expected = submerged_weight_below(cfg)
    sim = cable_dynamics.Simulator.from_dict(cfg)
    # At t = 0 the cable hangs straight down at rest (initial angles 0): nothing accelerates, so each
    # link's base end carries what hangs below it. Sums of ~10 terms: 1e-12 relative is rounding.
    s = sim.snapshot()
    assert s.tension.shape == (10,)
    np.testing.assert_allclose(s.tension, expected, rtol=1e-12)
    assert s.line_pull == pytest.approx(expected[0], rel=1e-12)
    # It stays so while stepped (1 s): vertical at rest is an equilibrium.
    sim.step(1000)
    assert sim.time == pytest.approx(1.0, abs=1e-12)
    np.testing.assert_allclose(sim.snapshot().tension, expected, rtol=1e-9)
    # The static solver gives the same (its residual tolerance is 1e-9 relative).
    sim.reset_to_equilibrium()
    np.testing.assert_allclose(sim.snapshot().tension, expected, rtol=1e-9)
    # The link ends hang straight down, l apart (paper frame: z down).
    ends = sim.snapshot().link_ends
    assert ends.shape == (11, 3)
    np.testing.assert_allclose(ends[:, 2], np.linspace(0.0, 20.0, 11), atol=1e-9)
    np.testing.assert_allclose(ends[:, :2], 0.0, atol=1e-9)


def test_an_elastic_chain_stretches_by_the_weight_below():
    """With cable.axial_stiffness each link stretches by T l / EA under the tension in its stretch: the
    weight below its far end and the half of its own weight that rides there (docs/MODEL.md section 12),
    which is the continuum's tension at the link's middle; the snapshot carries the strains. The tip then
    hangs where the elastic rod's does, L + (W L + w L^2 / 2) / EA (W the load's submerged weight, w the
    cable's per length): the tension is linear along the rod, and the midpoint rule sums it exactly."""
    cfg = hanging_config()
    ea = 2.0e5  # [N]
    cfg["cable"]["axial_stiffness"] = ea
    cfg["initial"] = {"mode": "equilibrium"}
    sim = cable_dynamics.Simulator.from_dict(cfg)
    s = sim.snapshot()
    below = submerged_weight_below(cfg)
    n, l = cfg["cable"]["links"], cfg["cable"]["length"] / cfg["cable"]["links"]
    link = below[0] - below[1]
    far = below - 0.5 * link  # the tension in each link's stretch [N]
    # The elastic statics' fixed point stops at 1e-12 of the length; the sums are ~10 terms.
    np.testing.assert_allclose(s.strain, far / ea, rtol=1e-9)
    np.testing.assert_allclose(s.stretched_length, l * (1.0 + far / ea), rtol=1e-12)
    np.testing.assert_allclose(s.far_tension, far, rtol=1e-9)
    assert s.slack_links == 0
    # The tip hangs the stretched length down, the elastic rod's.
    assert s.link_ends[-1, 2] == pytest.approx(n * l + (far / ea * l).sum(), rel=1e-12)
    length, w, tip = n * l, link / l, below[0] - n * link
    assert s.link_ends[-1, 2] == pytest.approx(length + (tip * length + w * length ** 2 / 2) / ea, rel=1e-12)



def test_the_limits_exist_and_equal_cable_sims_csv(tmp_path):
    """The limits (cable.limits; docs/MODEL.md section 13) in the snapshot: each joint's bend radius and each
    link's utilisation (numpy, n), the smallest radius and the largest utilisation with their links; equal
    to the columns of cable_sim's CSV for the same config at the same instants (10 significant digits), the
    straight start's infinite radii (`inf` in the CSV) included."""
    config = tmp_path / "limits.yaml"
    config.write_text(
        "cable: {links: 8, length: 10.0, diameter: 0.025, mass_per_length: 0.6,\n"
        "        stiffness: {model: bending, bending_rigidity: 50.0},\n"
        "        limits: {max_tension: 30.0, min_bend_radius: 5.0}}\n"
        "load: {mass: 2.0, volume: 0.0005}\n"
        "fluid: {density: 1025.0, current: [0.8, 0.0, 0.0]}\n"
        "simulation: {integrator: implicit, dt: 0.01}\n")
    out = tmp_path / "run.csv"
    done = subprocess.run([required_env("CABLE_SIM_BIN"), "--config", str(config), "--output", str(out),
                           "--duration", "1.0", "--sample", "0.5"], capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr
    with open(out) as f:
        header = f.readline().strip().split(",")
    data = np.loadtxt(out, delimiter=",", skiprows=1, ndmin=2)
    csv = {name: data[:, i] for i, name in enumerate(header)}
    n = 8
    sim = cable_dynamics.Simulator.from_file(str(config))
    for row in range(3):  # t = 0, 0.5, 1.0 s
        if row:
            sim.step(50)
        s = sim.snapshot()
        assert s.time == pytest.approx(csv["time"][row], abs=1e-12)
        assert s.bend_radius.shape == (n,) and s.utilisation.shape == (n,)
        radius = np.array([csv[f"bend_radius{k}"][row] for k in range(1, n + 1)])
        used = np.array([csv[f"utilisation{k}"][row] for k in range(1, n + 1)])
        np.testing.assert_allclose(s.bend_radius, radius, rtol=1e-9)
        np.testing.assert_allclose(s.utilisation, used, rtol=1e-9)
        assert s.min_bend_radius == pytest.approx(csv["min_bend_radius"][row], rel=1e-9)
        assert s.max_utilisation == pytest.approx(csv["max_utilisation"][row], rel=1e-9)
        assert 0 <= s.min_bend_radius_link < n and 0 <= s.max_utilisation_link < n
        assert s.max_utilisation == s.utilisation[s.max_utilisation_link]
        assert s.seabed_clearance == math.inf  # no seabed
        if row == 0:  # the straight start: every joint straight, only the tension uses the cable
            assert np.all(np.isinf(radius)) and math.isinf(s.min_bend_radius)
            np.testing.assert_allclose(s.utilisation, s.tension / 30.0, rtol=1e-12)
    # In the current it bends: finite radii, the bend limit in the utilisation.
    assert np.all(np.isfinite(s.bend_radius)) and s.min_bend_radius < math.inf
    assert s.max_utilisation > 0.0

# --- the seabed ------------------------------------------------------------------------------------

def test_a_chain_on_the_seabed_rests_its_weight_on_it():
    # The hanging chain (no load) anchored on a bottom 10 m down, 14 m out: at equilibrium its submerged
    # weight (from the config's numbers) is carried by the base, the anchor and the bottom's normal
    # forces, which the snapshot reports (paper frame, z down; the bottom pushes up, -z).
    cfg = hanging_config(load_mass=0.0, load_volume=0.0)
    cfg["load"].update({"mode": "anchored", "motion": {"offset": [14.0, 0.0, 10.0]}})  # from the tip 20 m down
    cfg["seabed"] = {"depth": 10.0}
    cfg["initial"] = {"mode": "equilibrium"}
    sim = cable_dynamics.Simulator.from_dict(cfg)
    s = sim.snapshot()
    c = cfg["cable"]
    weight = (c["mass_per_length"] - RHO * math.pi * (c["diameter"] / 2) ** 2) * c["length"] * G
    assert s.seabed_force.shape == (10, 3)
    np.testing.assert_allclose(-s.seabed_force[:, 2], s.seabed_normal, rtol=1e-12, atol=1e-12)  # no friction at rest
    assert s.base_force[2] - s.coupling_force[2] + s.seabed_normal.sum() == pytest.approx(weight, rel=1e-6)
    assert s.grounded_length > 1.0 and s.seabed_normal.sum() > 0.1 * weight
    assert 10.0 < s.touchdown_arc_length < 20.0
    assert 0.0 < s.max_penetration < 0.015  # half the diameter is allowed
    assert s.contact_energy > 0.0


def test_static_friction_holds_the_cable_where_the_equilibrium_laid_it():
    # The same chain on a bottom with friction (mu 0.5): the statics solve without friction (one of the
    # equilibria the static friction allows) and put each contact point's anchor on its point, so the
    # snapshot shows every grounded point held and a run from there stays at rest. With breakout 0 (the
    # regularized law, no anchors) nothing is held.
    cfg = hanging_config(load_mass=0.0, load_volume=0.0)
    cfg["load"].update({"mode": "anchored", "motion": {"offset": [14.0, 0.0, 10.0]}})
    cfg["seabed"] = {"depth": 10.0, "friction": {"axial": 0.5, "lateral": 0.5}}
    cfg["initial"] = {"mode": "equilibrium"}
    sim = cable_dynamics.Simulator.from_dict(cfg)
    start = sim.snapshot()
    assert start.grounded_length > 1.0
    assert start.stuck_length == pytest.approx(start.grounded_length, abs=1e-12)
    sim.step(200)
    after = sim.snapshot()
    assert after.stuck_length == pytest.approx(after.grounded_length, abs=1e-12)
    # at rest: 0.2 s moved the ends by 1.8e-14 m (rounding)
    assert np.abs(after.link_ends - start.link_ends).max() < 1e-10
    cfg["seabed"]["friction"]["breakout"] = 0.0
    assert cable_dynamics.Simulator.from_dict(cfg).snapshot().stuck_length == 0.0


# --- stepping: the compound pendulum ----------------------------------------------------------------

def test_single_link_swings_with_the_compound_pendulum_period():
    length, diameter = 2.0, 0.02
    theta0 = 0.05  # [rad]
    cfg = {"cable": {"links": 1, "length": length, "diameter": diameter, "mass_per_length": 1.0},
           "fluid": {"density": 0.0}, "gravity": G, "initial": {"elevation": theta0},
           "simulation": {"dt": 0.0005}}
    sim = cable_dynamics.Simulator.from_dict(cfg)
    r = diameter / 2
    # Solid cylinder about its end: m (l^2/3 + r^2/4); weight moment m g l/2; finite amplitude (1 + th^2/16).
    period = 2 * math.pi * math.sqrt((length ** 2 / 3 + r ** 2 / 4) / (G * length / 2)) * (1 + theta0 ** 2 / 16)
    times, values = [], []
    while sim.time < 4.5 * period:
        sim.step(1)
        times.append(sim.time)
        # The elevation is measured from the vertical (>= 0, the azimuth turns by pi as the link passes
        # it): follow the tip's horizontal position instead, y in the paper frame for azimuth 0.
        values.append(sim.snapshot().link_ends[-1][1])
    times, values = np.array(times), np.array(values)
    # Downward zero crossings of the tip's position, located by linear interpolation within a step.
    i = np.where((values[:-1] > 0) & (values[1:] <= 0))[0]
    crossings = times[i] + (times[i + 1] - times[i]) * values[i] / (values[i] - values[i + 1])
    measured = np.mean(np.diff(crossings))
    assert len(crossings) >= 4
    # RK4 at dt = T/4000 is exact to far better than the th^4 term left out of the amplitude correction
    # (~1e-7 at 0.05 rad); 1e-5 relative leaves room for the interpolation of the crossings.
    assert measured == pytest.approx(period, rel=1e-5)


# --- model matrices ---------------------------------------------------------------------------------

def random_state(n, seed):
    rng = np.random.default_rng(seed)
    q = np.zeros(3 * n)
    q[0::3] = rng.uniform(0.3, 1.2, n)   # elevation, away from the vertical
    q[1::3] = rng.uniform(-1.0, 1.0, n)  # azimuth
    q[2::3] = rng.uniform(-1.0, 1.0, n)  # torsion
    return q, rng.uniform(-0.5, 0.5, 3 * n)


def test_model_matches_cable_model_and_is_symmetric():
    config = os.path.join(REPO, "config", "default.yaml")
    overrides = ["cable.links=4", "cable.stiffness.model=bending", "cable.stiffness.bending_rigidity=50",
                 "cable.stiffness.torsional_rigidity=20", "cable.damping.elevation=3", "cable.damping.azimuth=3",
                 "cable.damping.torsion=1", "simulation.dt=0.0001"]  # within RK4's limit for these springs (0.39 ms)
    sim = cable_dynamics.Simulator.from_file(config, overrides)
    n = sim.links
    q, qd = random_state(n, 7)
    sim.set_state(q, qd)
    m = sim.model()
    assert m.coordinates[:3] == ["joint_1_elevation", "joint_1_azimuth", "joint_1_torsion"]
    assert m.M.shape == (3 * n, 3 * n) and m.h.shape == (3 * n,)
    # The state read back is the one set (through the core's axes and twists: rounding only).
    np.testing.assert_allclose(m.q, q, atol=1e-12)
    np.testing.assert_allclose(m.qd, qd, atol=1e-12)
    # The same state through the C++ tool: its JSON prints 17 digits, so both are the same computation.
    cmd = [required_env("CABLE_MODEL_BIN"), "--config", config]
    for o in overrides:
        cmd += ["--set", o]
    cmd += ["--q", ",".join(repr(float(v)) for v in m.q), "--qd", ",".join(repr(float(v)) for v in m.qd)]
    tool = json.loads(subprocess.run(cmd, capture_output=True, text=True, check=True).stdout)
    for key in ("M", "K", "D"):
        ref = np.array(tool[key])
        np.testing.assert_allclose(getattr(m, key), ref, rtol=1e-12, atol=1e-12 * np.abs(ref).max(), err_msg=key)
    for key in ("h", "G"):
        ref = np.array(tool[key])
        np.testing.assert_allclose(getattr(m, key), ref, rtol=1e-12, atol=1e-12 * np.abs(ref).max(), err_msg=key)
    # Symmetric (a kinetic energy's Hessian, a potential's, a dissipation function's) and M positive definite.
    for key in ("M", "K", "D"):
        a = getattr(m, key)
        assert np.abs(a - a.T).max() <= 1e-12 * np.abs(a).max(), key
    assert np.all(np.linalg.eigvalsh(m.M) > 0.0)
    assert np.abs(m.K).max() > 0.0 and np.abs(m.D).max() > 0.0, "the overrides gave springs and dampers"


# --- the current --------------------------------------------------------------------------------------

def shooting_reference(cfg, speed):
    c, load, f = cfg["cable"], cfg["load"], cfg["fluid"]
    lengths, ms = static_current.uniform_cable(
        c["length"], c["links"], c["mass_per_length"] - f["density"] * math.pi * (c["diameter"] / 2) ** 2)
    return static_current.solve_static_current(lengths, ms, load["mass"] - f["density"] * load["volume"],
                                               c["diameter"], f["density"], f["drag_normal"], f["drag_tangential"],
                                               speed, cfg.get("gravity", 9.81))


def reference_axial_tensions(cfg, speed, ref):
    """(n) the reference's force at each link's base end along that link [N], summed from the tip as the
    shooting solver does."""
    c, f = cfg["cable"], cfg["fluid"]
    n, l = c["links"], c["length"] / c["links"]
    ms = (c["mass_per_length"] - f["density"] * math.pi * (c["diameter"] / 2) ** 2) * l
    force = np.array(ref["load_force"], dtype=float)
    axial = np.zeros(n)
    for k in range(n - 1, -1, -1):
        a = ref["link_angles"][k]
        force += static_current._link_total_force(a, l, ms, c["diameter"], f["density"], f["drag_normal"],
                                                  f["drag_tangential"], speed, cfg.get("gravity", 9.81))
        axial[k] = force @ np.array([math.sin(a), math.cos(a)])
    return axial


def current_config():
    cfg = hanging_config(links=20, length=50.0, diameter=0.025, mass_per_length=0.6, load_mass=10.0,
                         load_volume=0.005)
    cfg["fluid"].update({"drag_normal": 1.2, "drag_tangential": 0.01})
    return cfg


# Both solve the same discrete chain (a straight link in a uniform current feels a uniform drag), to a
# relative residual of 1e-9 (statics) and the last bit (shooting's bisection): 1e-6 leaves margin.
REFERENCE_TOLERANCE = 1e-6


@pytest.mark.parametrize("axis", [0, 1])
def test_current_changes_the_drag_as_the_shooting_reference(axis):
    cfg = current_config()
    sim = cable_dynamics.Simulator.from_dict(cfg)
    still = sim.snapshot().line_pull
    speed = 1.2
    current = [0.0, 0.0, 0.0]
    current[axis] = speed
    sim.set_current(current)
    sim.reset_to_equilibrium()
    s = sim.snapshot()
    ref = shooting_reference(cfg, speed)
    print(f"axis {axis}: top tension {s.line_pull:.9f} N (reference {reference_axial_tensions(cfg, speed, ref)[0]:.9f}"
          f" N, still water {still:.6f} N); |base force| {np.linalg.norm(s.base_force):.9f} N (reference "
          f"{ref['top_tension']:.9f} N); tip offset {s.link_ends[-1]} (reference {ref['load_offset']:.9f} m downstream)")
    # The drag swings the cable downstream; across an inclined link it also lifts, so the top tension
    # may fall below the still water's (here 86.7 N against 95.3 N): the reference decides.
    assert abs(s.line_pull - still) > 0.01 * still
    # The reference's top_tension is the base force's magnitude; line_pull is its part along link 1 (a link
    # under a distributed load is not quite aligned with the force at its end).
    assert np.linalg.norm(s.base_force) == pytest.approx(ref["top_tension"], rel=REFERENCE_TOLERANCE)
    axial = reference_axial_tensions(cfg, speed, ref)
    assert s.line_pull == pytest.approx(axial[0], rel=REFERENCE_TOLERANCE)
    # Downstream in world axes: +x is paper +x, +y is paper -y (the paper frame is half a turn about x).
    tip = s.link_ends[-1]
    downstream = tip[0] if axis == 0 else -tip[1]
    across = tip[1] if axis == 0 else tip[0]
    assert downstream > 0.5 * cfg["cable"]["length"]
    assert downstream == pytest.approx(ref["load_offset"], rel=REFERENCE_TOLERANCE)
    assert abs(across) < 1e-9
    assert tip[2] == pytest.approx(ref["load_depth"], rel=REFERENCE_TOLERANCE)
    # The shape: every link end, planar in the current's plane.
    ends = np.array(ref["ends"])  # (n+1, 2): x downstream, z down
    np.testing.assert_allclose(s.link_ends[:, axis] * (1 if axis == 0 else -1), ends[:, 0],
                               rtol=0, atol=REFERENCE_TOLERANCE * cfg["cable"]["length"])
    np.testing.assert_allclose(s.link_ends[:, 2], ends[:, 1], rtol=0, atol=REFERENCE_TOLERANCE * cfg["cable"]["length"])
    # Each link's tension is the force at its base end along the link: the reference's force there (its
    # own sums from the tip) dotted with the link's axis.
    np.testing.assert_allclose(s.tension, axial, rtol=REFERENCE_TOLERANCE)


# --- the winch ------------------------------------------------------------------------------------------

def test_winch_speed_command_pays_out_by_the_ramp_law():
    cfg = hanging_config()
    cfg["winch"] = {"max_length": 40.0, "min_length": 6.0, "max_speed": 2.0, "max_acceleration": 1.0}
    sim = cable_dynamics.Simulator.from_dict(cfg)
    assert sim.has_winch and sim.links == 21
    start = sim.snapshot().deployed_length
    assert start == pytest.approx(20.0, abs=1e-12)
    sim.command_winch_speed(0.5)
    sim.step(2000)  # 2 s: ramps at 1 m/s^2 to 0.5 m/s in 0.5 s (0.125 m), then cruises 1.5 s (0.75 m)
    s = sim.snapshot()
    assert s.winch_speed == pytest.approx(0.5, abs=1e-12)
    assert s.deployed_length - start == pytest.approx(0.875, abs=1e-6)
    # Paid out at the base: the base link (slot 11, 2 m at start) grows until it splits at 2.25 link lengths.
    assert s.first_link == 11
    base_link = np.linalg.norm(s.link_ends[12] - s.link_ends[11])
    assert base_link == pytest.approx(2.0 + 0.875, abs=1e-6)
    with pytest.raises(ValueError, match=r"speed = 2\.5.*within \+-2 m/s"):
        sim.command_winch_speed(2.5)
    with pytest.raises(ValueError, match=r"length = 41.*\[6, 40\] m"):
        sim.command_winch_length(41.0)
    sim.command_winch_length(25.0)  # accepted
    no_winch = cable_dynamics.Simulator.from_dict(hanging_config())
    with pytest.raises(ValueError, match="no winch"):
        no_winch.command_winch_speed(0.1)


# --- the README example ---------------------------------------------------------------------------------

def test_readme_example_is_the_file_and_prints_the_reference_tensions():
    with open(EXAMPLE) as f:
        code = f.read()
    body = code.split("\n", 1)[1]  # the README shows it without the shebang
    with open(os.path.join(REPO, "README.md")) as f:
        assert body.strip() in f.read(), "README.md shows cable_dynamics/python/examples/current_sweep.py verbatim"
    setup = required_env("CABLE_DEVEL_SETUP")
    # As a user runs it: a fresh shell, the devel space sourced, Debian's python3.
    done = subprocess.run(["bash", "-c", f'source "{setup}" && /usr/bin/python3 "{EXAMPLE}"'], capture_output=True,
                          text=True, timeout=300, env={"HOME": os.environ.get("HOME", "/tmp"), "PATH": "/usr/bin:/bin"})
    assert done.returncode == 0, done.stderr
    print(done.stdout)
    rows = [line.split() for line in done.stdout.strip().splitlines()[1:]]
    assert len(rows) == 6
    cfg = {"cable": {"links": 25, "length": 50.0, "diameter": 0.025, "mass_per_length": 0.6},
           "load": {"mass": 10.0, "volume": 0.005},
           "fluid": {"density": RHO, "drag_normal": 1.2, "drag_tangential": 0.01}}
    for speed, tension, offset, depth in ((float(v) for v in row) for row in rows):
        ref = shooting_reference(cfg, speed)
        # Printed to 4 decimals: half a unit of the last digit, or the reference tolerance. The top tension
        # is the force along the top link (line_pull), the reference's axial force there.
        top = reference_axial_tensions(cfg, speed, ref)[0]
        assert tension == pytest.approx(top, rel=REFERENCE_TOLERANCE, abs=5e-5)
        assert offset == pytest.approx(ref["load_offset"], rel=REFERENCE_TOLERANCE, abs=5e-5)
        assert depth == pytest.approx(ref["load_depth"], rel=REFERENCE_TOLERANCE, abs=5e-5)


# --- bad input -------------------------------------------------------------------------------------------

def test_bad_input_is_refused_by_name():
    with pytest.raises(cable_dynamics.ConfigError, match="cable.links"):
        cable_dynamics.Simulator.from_dict({"cable": {"links": 0, "length": 1.0, "diameter": 0.01,
                                                      "mass_per_length": 1.0}})
    with pytest.raises(ValueError, match="cable.lenght"):  # ConfigError is a ValueError; unknown key named
        cable_dynamics.Simulator.from_dict({"cable": {"links": 2, "length": 1.0, "lenght": 1.0, "diameter": 0.01,
                                                      "mass_per_length": 1.0}})
    with pytest.raises(ValueError, match="fluid.density"):
        cable_dynamics.Simulator.from_dict(dict(hanging_config(), fluid={"density": float("nan")}))
    with pytest.raises(TypeError, match="cable.diameter"):
        cable_dynamics.Simulator.from_dict({"cable": {"links": 2, "length": 1.0, "diameter": None,
                                                      "mass_per_length": 1.0}})
    with pytest.raises(cable_dynamics.ConfigError, match="cable.links"):
        cable_dynamics.Simulator.from_file(os.path.join(REPO, "config", "default.yaml"), ["cable.links=-3"])
    sim = cable_dynamics.Simulator.from_dict(hanging_config())
    # The simulator's gate names the component as the config loader does (fluid.current's range).
    with pytest.raises(ValueError, match=r"'fluid.current\[0\]' = nan"):
        sim.set_current([float("nan"), 0.0, 0.0])
    with pytest.raises(ValueError, match=r"'fluid.current\[1\]' = 150: expected a finite number in \[-100, 100\]"):
        sim.set_current([0.0, 150.0, 0.0])
    with pytest.raises(ValueError, match="attitude"):
        sim.set_load_target([0.0, 0.0, -20.0], [0.0, 0.0, 0.0], [0.0, 0.0, 0.0, 0.0])
    with pytest.raises(ValueError, match="steps = 0"):
        sim.step(0)
    with pytest.raises(ValueError, match="3n = 30"):
        sim.set_state(np.zeros(3), np.zeros(3))
    # numpy inputs work like lists
    cable_dynamics.Simulator.from_dict(dict(hanging_config(), fluid={"density": np.float64(1025.0),
                                                                    "current": np.array([0.1, 0.0, 0.0])}))


def cable_sim_refusal(config, overrides, tmp_path):
    """cable_sim's exit status and its one-line message (without the 'cable_sim: ' prefix) on `config`."""
    args = [required_env("CABLE_SIM_BIN"), "--config", config, "--output", str(tmp_path / "run.csv"),
            "--duration", "0.1"]
    for o in overrides:
        args += ["--set", o]
    done = subprocess.run(args, capture_output=True, text=True, timeout=120)
    line = done.stderr.strip().splitlines()[0]
    assert line.startswith("cable_sim: "), done.stderr
    return done.returncode, line[len("cable_sim: "):]


@pytest.mark.parametrize("overrides, key", [
    # The review's case: config/rov_tether.yaml with RK4 at 50 ms (its stability limit: 0.96 ms). Accepted
    # by from_file and from_dict at 05a647c, where only cable_sim and the node checked the step.
    (["simulation.integrator=rk4", "simulation.dt=0.05"], "simulation.dt"),
    # The paper model's azimuth spring, singular at the vertical (the simulator's rule, not the loader's).
    (["cable.stiffness={model: paper, azimuth: 1.0}"], "cable.stiffness.azimuth"),
])
def test_python_refuses_what_cable_sim_refuses_with_its_message(overrides, key, tmp_path):
    config = os.path.join(REPO, "config", "rov_tether.yaml")
    status, message = cable_sim_refusal(config, overrides, tmp_path)
    assert status == 2 and key in message, message
    with pytest.raises(ValueError) as from_file:
        cable_dynamics.Simulator.from_file(config, overrides)
    assert str(from_file.value) == message
    import yaml
    with open(config) as f:
        tree = yaml.safe_load(f)
    with pytest.raises(ValueError) as from_dict:
        cable_dynamics.Simulator.from_dict(tree, overrides)
    assert str(from_dict.value) == message


def test_run_samples_where_cable_sim_does():
    # Simulator.run is cable_sim's run (tools/sampled_run.h): t = 0, every `sample` (every round(sample /
    # dt) steps), and the last step; 105 steps of 1 ms sampled every 10 ms give 12 samples. The CSV it
    # writes is compared with cable_sim's byte for byte in test_cable_sweep.py.
    sim = cable_dynamics.Simulator.from_file(os.path.join(REPO, "config", "default.yaml"), ["cable.links=5"])
    times = []
    outcome = sim.run(0.105, sample=0.01, on_sample=lambda s: times.append(s.time))
    assert outcome["status"] == 0 and outcome["message"] == "", outcome
    assert times == pytest.approx([0.0] + [0.01 * k for k in range(1, 11)] + [0.105], abs=1e-12)
    assert sim.time == pytest.approx(0.105, abs=1e-12)
    for bad, name in (({"duration": 0.0}, "duration"), ({"duration": 1.0, "sample": -1.0}, "sample"),
                      ({"duration": float("nan")}, "duration")):
        with pytest.raises(ValueError, match=name):
            sim.run(**bad)

    def refuse(snapshot):  # an exception in the callback stops the run and comes back to the caller
        raise KeyError("stop here")

    with pytest.raises(KeyError, match="stop here"):
        sim.run(1.0, on_sample=refuse)
