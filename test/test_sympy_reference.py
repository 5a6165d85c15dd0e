"""The C++ cable model against an independent symbolic derivation (sympy).

Why: the C++ generator writes M(q), h(q, q') and G(q) of the n-link cable for any n.  The
reference in ``test/reference/sympy_cable_lagrange.py`` was not written from the same formulas:
it only states the kinematics and the energies T and V and lets sympy take every derivative
(M = Hessian of T in q', h = (d/dt dT/dq')|_{q''=0} - dT/dq, G = dV/dq).  If both agree to
~1e-9 relative at random states for several n, link lengths, in air / in water and with / without
a load, the generated model is the Lagrangian of those energies, not merely self-consistent.

Each of M, h, G is compared twice: as specified, relative to the largest entry of that quantity,
and again in mass-normalized coordinates (entries scaled by 1/sqrt(M_ii)), because the first
comparison alone cannot see the tiny torsion terms of a thin cable (see that test).

The physical parameters (masses, lengths, inertias, submerged masses, gravity) are read back
from the tool's own JSON output, so this test checks the model generation and not the parameter
derivation from the config (that has its own tests).

Environment:
  CABLE_MODEL_BIN     path of the built ``cable_model`` executable (required: the comparison
                      tests FAIL, not skip, without it, so a CI that forgot it cannot look green)
  CABLE_TEST_CONFIG   config file (default: <repo>/config/default.yaml)

Run:  CABLE_MODEL_BIN=.../cable_model /usr/bin/python3 -m pytest test/test_sympy_reference.py -q

The self-checks at the bottom (single link in closed form, memoized derivatives against plain
sympy.diff, energy conservation) need no binary: they check the reference itself.
"""

import functools
import json
import os
import subprocess
import sys
import zlib
from pathlib import Path

import numpy as np
import pytest

HERE = Path(__file__).resolve().parent
REPO = HERE.parent  # two levels up from test/test_sympy_reference.py
sys.path.insert(0, str(HERE / "reference"))

import sympy_cable_lagrange as reference  # noqa: E402

# Agreement required per quantity: max |C++ - reference| <= RTOL * max |reference|.
RTOL = 1e-9
# M from the C++ side must be symmetric to rounding: max |M - M^T| <= SYM_RTOL * max |M|.
SYM_RTOL = 1e-12
STATES_PER_CASE = 5

# (id, n, --set overrides).  Every case sets cable.links explicitly, so the config's own n
# does not matter.
CASES = [
    ("n2", 2, ["cable.links=2"]),
    ("n3", 3, ["cable.links=3"]),
    ("n4", 4, ["cable.links=4"]),
    ("n3_link_lengths", 3, ["cable.links=3", "cable.link_lengths=[1.0,2.5,0.7]"]),
    ("n3_air", 3, ["cable.links=3", "fluid.density=0.0"]),
    ("n4_air", 4, ["cable.links=4", "fluid.density=0.0"]),
    ("n3_no_load", 3, ["cable.links=3", "load.mass=0.0"]),
    ("n2_air_no_load", 2, ["cable.links=2", "fluid.density=0.0", "load.mass=0.0"]),
]
CASE_BY_ID = {c[0]: c for c in CASES}


# ----------------------------------------------------------------------------------------------
# Running the C++ tool
# ----------------------------------------------------------------------------------------------

def _binary():
    path = os.environ.get("CABLE_MODEL_BIN")
    if not path:
        pytest.fail("CABLE_MODEL_BIN is not set: point it at the built cable_model executable, e.g. "
                    "CABLE_MODEL_BIN=<ws>/devel/lib/cable_dynamics/cable_model", pytrace=False)
    if not (os.path.isfile(path) and os.access(path, os.X_OK)):
        pytest.fail("CABLE_MODEL_BIN=%r is not an executable file" % path, pytrace=False)
    return path


def _config():
    path = os.environ.get("CABLE_TEST_CONFIG", str(REPO / "config" / "default.yaml"))
    if not os.path.isfile(path):
        pytest.fail("config file %r not found (set CABLE_TEST_CONFIG)" % path, pytrace=False)
    return path


def _fmt(values):
    """Full precision (17 significant digits round-trips a double)."""
    return ",".join("%.17g" % v for v in values)


def _state(case_id, index):
    """Fixed pseudo-random state for (case, index): te in [0.2, 1.3] (M is singular at te = 0),
    azimuth and torsion in [-pi, pi], all rates in [-2, 2]."""
    n = CASE_BY_ID[case_id][1]
    rs = np.random.RandomState((zlib.crc32(case_id.encode()) + 7919 * index) % 2**32)
    return reference.random_state(n, rs)


@functools.lru_cache(maxsize=None)
def _run(case_id, index):
    """Run cable_model for one case and state; returns (command, parsed JSON, q, qd)."""
    _, n, sets = CASE_BY_ID[case_id]
    q, qd = _state(case_id, index)
    cmd = [_binary(), "--config", _config()]
    for s in sets:
        cmd += ["--set", s]
    cmd += ["--q", _fmt(q), "--qd", _fmt(qd)]
    try:
        proc = subprocess.run(cmd, capture_output=True, text=True, timeout=120)
    except subprocess.TimeoutExpired:
        pytest.fail("cable_model timed out: %s" % " ".join(cmd), pytrace=False)
    if proc.returncode != 0:
        pytest.fail("cable_model exited with %d\ncommand: %s\nstderr:\n%s"
                    % (proc.returncode, " ".join(cmd), proc.stderr), pytrace=False)
    try:
        data = json.loads(proc.stdout)
    except json.JSONDecodeError as err:
        pytest.fail("cable_model did not print JSON (%s)\ncommand: %s\nstdout starts:\n%s"
                    % (err, " ".join(cmd), proc.stdout[:2000]), pytrace=False)
    return cmd, data, q, qd


def _worst_entry_report(quantity, got, want, names):
    """None if max |got - want| <= RTOL * max |want|, else a message about the worst entry."""
    got = np.asarray(got, dtype=float)
    want = np.asarray(want, dtype=float)
    if got.shape != want.shape:
        return "%s: shape %s from C++, reference %s" % (quantity, got.shape, want.shape)
    scale = max(1e-300, float(np.max(np.abs(want))))
    err = np.abs(got - want)
    if np.all(np.isfinite(got)) and float(np.max(err)) <= RTOL * scale:
        return None
    # NaN/inf in the C++ output counts as the worst entry.
    err = np.where(np.isfinite(err), err, np.inf)
    idx = np.unravel_index(int(np.argmax(err)), err.shape)
    label = ", ".join(names[i] for i in idx)
    return ("%s%s [%s]: C++ %.17g, reference %.17g, |diff| %.3e = %.3e x max|%s| (%.6g); "
            "allowed %.1e; %d of %d entries outside"
            % (quantity, list(idx), label, got[idx], want[idx], err[idx], err[idx] / scale,
               quantity, scale, RTOL, int(np.sum(err > RTOL * scale)), err.size))


# ----------------------------------------------------------------------------------------------
# C++ against the reference
# ----------------------------------------------------------------------------------------------

@pytest.mark.parametrize("case_id", [c[0] for c in CASES])
def test_output_layout(case_id):
    """n, coordinate names/order, array sizes, and that the override really took effect."""
    _, n, sets = CASE_BY_ID[case_id]
    cmd, data, q, qd = _run(case_id, 0)
    assert data["n"] == n, "n = %r for %s" % (data["n"], " ".join(cmd))
    assert data["coordinates"] == reference.coordinate_names(n)
    for key in reference.PER_LINK_KEYS:
        assert len(data[key]) == n, "%s has %d entries, expected %d" % (key, len(data[key]), n)
    for key in reference.SCALAR_KEYS:
        assert np.isfinite(float(data[key])), key
    N = 3 * n
    assert np.asarray(data["M"], dtype=float).shape == (N, N)
    assert np.asarray(data["h"], dtype=float).shape == (N,)
    assert np.asarray(data["G"], dtype=float).shape == (N,)
    # The state went in with 17 digits; it must come back (up to printing) unchanged, in order.
    np.testing.assert_allclose(data["q"], q, rtol=1e-14, atol=0, err_msg="q echoed differently")
    np.testing.assert_allclose(data["qd"], qd, rtol=1e-14, atol=1e-300, err_msg="qd echoed differently")
    # Without these the variants would silently test the default configuration again.
    if "cable.link_lengths=[1.0,2.5,0.7]" in sets:
        np.testing.assert_allclose(data["length"], [1.0, 2.5, 0.7], rtol=1e-15)
    if "fluid.density=0.0" in sets:
        np.testing.assert_allclose(data["submerged_mass"], data["mass"], rtol=1e-15)
        assert float(data["load_submerged_mass"]) == pytest.approx(float(data["load_mass"]), rel=1e-15)
    if "load.mass=0.0" in sets:
        assert float(data["load_mass"]) == 0.0


@pytest.mark.parametrize("index", range(STATES_PER_CASE))
@pytest.mark.parametrize("case_id", [c[0] for c in CASES])
def test_cpp_matches_sympy_reference(case_id, index):
    """M, h, G from cable_model equal the Lagrangian of the energies (RTOL relative, per quantity)."""
    _, n, _ = CASE_BY_ID[case_id]
    cmd, data, q, qd = _run(case_id, index)
    names = reference.coordinate_names(n)
    assert data["coordinates"] == names

    M_cpp = np.asarray(data["M"], dtype=float)
    asym = float(np.max(np.abs(M_cpp - M_cpp.T)))
    m_scale = max(1e-300, float(np.max(np.abs(M_cpp))))

    params = reference.params_from_json(data)
    M_ref, h_ref, G_ref = reference.build(n).evaluate(params, q, qd)

    problems = []
    if not asym <= SYM_RTOL * m_scale:
        i, j = np.unravel_index(int(np.argmax(np.abs(M_cpp - M_cpp.T))), M_cpp.shape)
        problems.append("M not symmetric: |M[%d,%d] - M[%d,%d]| = %.3e (%s / %s), max|M| %.6g"
                        % (i, j, j, i, asym, names[i], names[j], m_scale))
    for quantity, got, want in (("M", M_cpp, M_ref), ("h", data["h"], h_ref), ("G", data["G"], G_ref)):
        msg = _worst_entry_report(quantity, got, want, names)
        if msg:
            problems.append(msg)
    if problems:
        pytest.fail("case %s, state %d\n  %s\nq  = [%s]\nqd = [%s]\ncommand: %s"
                    % (case_id, index, "\n  ".join(problems), _fmt(q), _fmt(qd), " ".join(cmd)),
                    pytrace=False)


@pytest.mark.parametrize("index", range(STATES_PER_CASE))
@pytest.mark.parametrize("case_id", [c[0] for c in CASES])
def test_cpp_matches_sympy_reference_mass_scaled(case_id, index):
    """The same comparison in mass-normalized coordinates y_i = sqrt(M_ii) q_i.

    Why a second comparison: with a thin cable the torsion block of M is ~1e-7 of its largest
    entry (I_P = m r^2/2 against m l^2/4), so "RTOL x max|M|" above cannot see the torsion
    physics at all (a 1 % error in every polar inertia passes it).  Scaling M_ij by
    1/sqrt(M_ii M_jj) and h_i, G_i by 1/sqrt(M_ii) (the reference's diagonal) puts every
    coordinate on the same footing; the tolerance is the same RTOL.
    """
    _, n, _ = CASE_BY_ID[case_id]
    cmd, data, q, qd = _run(case_id, index)
    names = reference.coordinate_names(n)
    params = reference.params_from_json(data)
    M_ref, h_ref, G_ref = reference.build(n).evaluate(params, q, qd)
    s = 1.0 / np.sqrt(np.diag(M_ref))
    S = np.outer(s, s)
    problems = []
    for quantity, got, want in (("M_scaled", np.asarray(data["M"], dtype=float) * S, M_ref * S),
                                ("h_scaled", np.asarray(data["h"], dtype=float) * s, h_ref * s),
                                ("G_scaled", np.asarray(data["G"], dtype=float) * s, G_ref * s)):
        msg = _worst_entry_report(quantity, got, want, names)
        if msg:
            problems.append(msg)
    if problems:
        pytest.fail("case %s, state %d (entries scaled by 1/sqrt(M_ii))\n  %s\nq  = [%s]\nqd = [%s]\n"
                    "command: %s" % (case_id, index, "\n  ".join(problems), _fmt(q), _fmt(qd), " ".join(cmd)),
                    pytrace=False)


# ----------------------------------------------------------------------------------------------
# Self-checks of the reference (no binary needed)
# ----------------------------------------------------------------------------------------------

def test_reference_single_link_no_load_in_air():
    """n = 1, no load, in air: M[0,0] = m l^2/4 + I_T and G[0] = g m (l/2) sin(te);
    the rest of M, h and G against the hand-derived single link as well."""
    m, ln, it, ip, g = 1.7, 1.3, 0.31, 0.02, 9.81
    params = {"mass": [m], "length": [ln], "inertia_transverse": [it], "inertia_polar": [ip],
              "submerged_mass": [m], "load_mass": 0.0, "load_submerged_mass": 0.0, "gravity": g}
    ref = reference.build(1)
    rs = np.random.RandomState(11)
    for _ in range(5):
        q, qd = reference.random_state(1, rs)
        M, h, G = ref.evaluate(params, q, qd)
        assert M[0, 0] == pytest.approx(m * ln**2 / 4 + it, rel=1e-13)
        assert G[0] == pytest.approx(g * m * (ln / 2) * np.sin(q[0]), rel=1e-13)
        M1, h1, G1 = reference.single_link_closed_form(params, q, qd)
        np.testing.assert_allclose(M, M1, rtol=0, atol=1e-13 * np.max(np.abs(M1)))
        np.testing.assert_allclose(h, h1, rtol=0, atol=1e-13 * np.max(np.abs(h1)))
        np.testing.assert_allclose(G, G1, rtol=0, atol=1e-13 * np.max(np.abs(G1)))


def test_reference_single_link_with_load_in_water():
    """n = 1 with a point load and buoyancy against the hand-derived single link."""
    params = {"mass": [2.3], "length": [0.9], "inertia_transverse": [0.17], "inertia_polar": [0.004],
              "submerged_mass": [0.8], "load_mass": 4.0, "load_submerged_mass": -1.5, "gravity": 9.81}
    ref = reference.build(1)
    rs = np.random.RandomState(12)
    for _ in range(5):
        q, qd = reference.random_state(1, rs)
        for got, want in zip(ref.evaluate(params, q, qd), reference.single_link_closed_form(params, q, qd)):
            np.testing.assert_allclose(got, want, rtol=0, atol=1e-13 * np.max(np.abs(want)))


def test_reference_memoized_derivatives_equal_sympy_diff():
    """The fast memoized differentiation gives the same M, h, G as plain sympy.diff (n = 2)."""
    fast, slow = reference.build(2, "dag"), reference.build(2, "sympy")
    rs = np.random.RandomState(13)
    for seed in range(3):
        params = reference.example_params(2, seed=seed)
        q, qd = reference.random_state(2, rs)
        for got, want in zip(fast.evaluate(params, q, qd), slow.evaluate(params, q, qd)):
            np.testing.assert_allclose(got, want, rtol=0, atol=1e-13 * np.max(np.abs(want)))


def test_reference_kinematics_and_energy():
    """R_k e_z = u_k, dR/dt R^T is skew, T = q'^T M q'/2, M symmetric positive definite, and an
    unforced motion of M q'' + h + G = 0 conserves T + V (a wrong h would not)."""
    n = 2
    ref = reference.build(n)
    params = reference.example_params(n, seed=5)
    q, qd = reference.random_state(n, np.random.RandomState(14))
    axis_res, skew_res = reference._numeric_kinematics_checks(ref, params, q, qd)
    assert axis_res < 1e-14 and skew_res < 1e-13
    M, _, _ = ref.evaluate(params, q, qd)
    assert ref.T(params, q, qd) == pytest.approx(qd @ M @ qd / 2, rel=1e-13)
    assert np.array_equal(M, M.T)
    assert np.linalg.eigvalsh(M)[0] > 0
    assert reference.energy_drift(ref, params, q, qd, dt=1e-3, steps=300) < 1e-7
