"""A pinned stiff cable between two points (issue 14, end fixity): cable_sim --statics with a pinned base
(base.fixity: pinned) and an anchored tip (held exactly at a point, free to rotate) against the
heavy elastica solved here with scipy's boundary-value solver: an inextensible Euler-Bernoulli rod of
bending stiffness EI under its own weight w, pinned at both ends (zero moment), in the vertical plane.
With theta the tangent's angle from the horizontal, F(s) the force the part beyond s exerts on the part
before it (F' = w z_hat) and M = EI theta' the moment:
    x' = cos theta, z' = sin theta, theta' = M / EI, M' = -(cos theta F_z(s) - sin theta F_x),
    F_x constant, F_z(s) = F_z0 + w s;  x(0) = z(0) = 0, M(0) = M(L) = 0, x(L) = X, z(L) = Z.
The rigid-link model converges to it as 1/n^2 (joint springs EI / s_k between link centres); the end
forces are compared at n = 10, 20, 40 (0.5 % at 40) and the measured order stated. The catenary
(EI -> 0) differs from the elastica here by several percent, so the test sees the stiffness."""
import os
import subprocess

import numpy as np
import pytest
from scipy.integrate import solve_bvp

L, D, MASS, EI, G = 20.0, 0.05, 5.0, 2000.0, 9.81  # m, m, kg/m, N m^2, m/s^2
W = MASS * G  # weight per metre in air [N/m]
# The anchor 12 m across and 8 m below the base: offset from the tip hanging straight down (20 m).
OFFSET = (12.0, 0.0, 12.0)


def binary():
    path = os.environ.get("CABLE_SIM_BIN")
    if not path:
        pytest.fail("set CABLE_SIM_BIN to the built executable (scripts/test.sh does)")
    return path


def run_statics(tmp_path, name, links, config_text):
    """cable_sim --statics on `config_text`: the tip [m] and the cable's forces on the base and on the
    load [N], in the elastica's frame (z up)."""
    config = tmp_path / f"{name}.yaml"
    config.write_text(config_text)
    out = tmp_path / f"{name}.csv"
    done = subprocess.run([binary(), "--config", str(config), "--statics", "--output", str(out)], capture_output=True,
                          text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    header = out.read_text().splitlines()[0].split(",")
    row = dict(zip(header, np.loadtxt(out, delimiter=",", skiprows=1)))
    # Paper frame (z down) to the elastica's (z up): the tip, and the cable's force on the base, which
    # is F(0) (the base holds the cable with -F(0)), and on the load, -F(L).
    tip = np.array([row[f"end{links}_x"], -row[f"end{links}_z"]])
    base_force = np.array([row["base_force_x"], -row["base_force_z"]])
    load_force = np.array([row["load_force_x"], -row["load_force_z"]])
    return tip, base_force, load_force


def cable_config(links, ei=EI):
    return (f"cable: {{links: {links}, length: {L}, diameter: {D}, mass_per_length: {MASS},\n"
            f"        stiffness: {{model: bending, bending_rigidity: {ei}, torsional_rigidity: {max(ei, 1.0) / 2}}}}}\n"
            f"fluid: {{density: 0.0}}\n")


def model_statics(tmp_path, links, ei=EI):
    return run_statics(tmp_path, f"beam_{links}_{ei}", links, cable_config(links, ei) +
                       f"base: {{fixity: pinned}}\n"
                       f"load: {{mode: anchored, motion: {{offset: [{OFFSET[0]}, {OFFSET[1]}, {OFFSET[2]}]}}}}\n")


def solve_elastica(tip, ei, ends):
    """F(0) = (F_x, F_z0) of the heavy elastica from (0, 0) to `tip` [m]; `ends(ya, yb)` gives its two
    end conditions besides the positions (zero moments when pinned, the angles when clamped)."""
    X, Z = tip
    s = np.linspace(0.0, L, 401)
    chord = np.hypot(X, Z)
    sag = np.sqrt(max(L * L - chord * chord, 0.0)) / 2.0
    x0 = X * s / L
    z0 = Z * s / L - 2.0 * sag * np.sin(np.pi * s / L)  # a sagging first guess
    theta0 = np.arctan2(np.gradient(z0, s), np.gradient(x0, s))
    y0 = np.vstack([x0, z0, theta0, np.zeros_like(s)])

    def rhs(s, y, p):
        fx, fz0 = p
        x, z, theta, m = y
        return np.vstack([np.cos(theta), np.sin(theta), m / ei, -(np.cos(theta) * (fz0 + W * s) - np.sin(theta) * fx)])

    def bc(ya, yb, p):
        return np.concatenate([[ya[0], ya[1]], ends(ya, yb), [yb[0] - X, yb[1] - Z]])

    solution = solve_bvp(rhs, bc, s, y0, p=[W * L / 2.0, -W * L / 2.0], tol=1e-7, bc_tol=1e-9, max_nodes=100000)
    assert solution.success, solution.message
    return np.array(solution.p)


def elastica(tip, ei=EI):
    """The pinned heavy elastica: zero moment at both ends."""
    return solve_elastica(tip, ei, lambda ya, yb: [ya[3], yb[3]])


def test_pinned_stiff_cable_between_two_points_matches_the_heavy_elastica(tmp_path):
    errors = {}
    for n in (10, 20, 40):
        tip, base_force, load_force = model_statics(tmp_path, n)
        f0 = elastica(tip)
        fl = f0 + np.array([0.0, W * L])  # F(L)
        scale = np.linalg.norm(f0)
        errors[n] = max(np.linalg.norm(base_force - f0), np.linalg.norm(load_force + fl)) / scale
        print(f"n = {n}: base force {base_force} N against {f0}, anchor {-load_force} against {fl}, "
              f"error {errors[n]:.2e}")
    order = np.log2(errors[20] / errors[40])
    print(f"order in n between 20 and 40: {order:.2f}")
    assert errors[40] < 0.005
    assert order > 1.7  # second order (1/n^2), with the round-off of a few 1e-5 far below
    # The stiffness matters here: the catenary through the same points pulls differently.
    tip, _, _ = model_statics(tmp_path, 40)
    catenary = elastica(tip, ei=1e-3)
    assert np.linalg.norm(catenary - elastica(tip)) / np.linalg.norm(catenary) > 0.03


def clamped_statics(tmp_path, links, base_direction, tip_direction):
    # The exact anchor (the statics put the tip on it; the elastica is solved to the tip where it is).
    return run_statics(tmp_path, f"clamped_{links}", links, cable_config(links) +
                       f"base: {{fixity: clamped, direction: [{base_direction[0]}, 0.0, {base_direction[1]}]}}\n"
                       f"load: {{mode: anchored, fixity: clamped, direction: [{tip_direction[0]}, 0.0, {tip_direction[1]}],\n"
                       f"        motion: {{offset: [{OFFSET[0]}, {OFFSET[1]}, {OFFSET[2]}]}}}}\n")


def clamped_elastica(tip, theta_base, theta_tip):
    """The heavy elastica clamped at angles theta_base and theta_tip [rad] from the horizontal."""
    return solve_elastica(tip, EI, lambda ya, yb: [ya[2] - theta_base, yb[2] - theta_tip])


def test_clamped_stiff_cable_between_two_points_matches_the_clamped_heavy_elastica(tmp_path):
    # The base clamped 30 degrees below the horizontal toward the anchor, the tip (load.fixity: clamped)
    # arriving horizontally: the clamps' half-link springs (EI / (l/2)) converge at second order too.
    theta_base, theta_tip = -np.pi / 6.0, 0.0
    base_direction = (np.cos(theta_base), np.sin(theta_base))
    tip_direction = (np.cos(theta_tip), np.sin(theta_tip))
    errors = {}
    for n in (10, 20, 40):
        tip, base_force, load_force = clamped_statics(tmp_path, n, base_direction, tip_direction)
        f0 = clamped_elastica(tip, theta_base, theta_tip)
        fl = f0 + np.array([0.0, W * L])
        errors[n] = max(np.linalg.norm(base_force - f0), np.linalg.norm(load_force + fl)) / np.linalg.norm(f0)
        print(f"clamped, n = {n}: base force {base_force} N against {f0}, error {errors[n]:.2e}")
    order = np.log2(errors[20] / errors[40])
    print(f"clamped: order in n between 20 and 40: {order:.2f}")
    assert errors[40] < 0.005
    assert order > 1.7
    # The clamps matter: pinned ends through the same points pull differently.
    tip, _, _ = clamped_statics(tmp_path, 40, base_direction, tip_direction)
    assert np.linalg.norm(elastica(tip) - clamped_elastica(tip, theta_base, theta_tip)) / np.linalg.norm(elastica(tip)) > 0.03
