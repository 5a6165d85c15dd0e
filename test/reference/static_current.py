#!/usr/bin/env python3
"""Independent quasi-static reference: an n-link cable at rest in a uniform current.

Why this file exists
--------------------
A dynamic simulation of the cable in a steady current must settle (with some damping) to a
static equilibrium.  This module computes that equilibrium directly, without time stepping and
without any of the C++ code, so the simulator's settled state (top tension, link angles, load
offset) can be checked against it.

Conventions
-----------
* Planar problem in the x-z plane; base fixed at the origin; x horizontal, z DOWN.
* Link k (k = 1 at the base) has length l_k, submerged mass ms_k (may be negative) and outer
  diameter d; its submerged weight per length is w_k = ms_k g / l_k.
* Link k's unit axis, from its base end to its far end, is u_k = (sin a_k, cos a_k) in (x, z):
  a_k is measured from the downward vertical, positive downstream (towards +x).
* A uniform current of speed U flows along +x; the cable is at rest, so the velocity of the
  WATER relative to the cable is v = (U, 0) everywhere.
* Fluid force per unit length of a link (Morison drag, no added mass since nothing accelerates):

      v_t = (v . u) u,   v_n = v - v_t
      f_drag = 1/2 rho Cdn d |v_n| v_n  +  1/2 rho Cdt (pi d) |v_t| v_t

  plus the weight per length (0, w_k).  The terminal load at the far end of link n gets
  F_load = (1/2 rho CdA_c U |U|, ms_c g).

Method (shooting from the tip)
------------------------------
A rigid link with a uniform distributed force f (per length) and a force F_out applied at its
far end by everything outboard is in equilibrium about its (pinned) base end when

      u x (l F_out + l^2/2 f(u)) = 0,   i.e.  u  is parallel to  G(u) = F_out + (l/2) f(u).

With e_a = du/da = (cos a, -sin a) this is the scalar equation h(a) = G(a) . e_a = 0, which is
solved per link by scanning a over the whole circle (step pi/360) and refining every bracket by
bisection to the last bit.  A root is accepted when it is (i) stable, i.e. h goes from + to -
as a increases (the generalized moment l h(a) restores), and (ii) in tension, G . u > 0.  If
several roots pass (never seen in practice), the one closest to the direction of
F_out + (l/2) f(u = straight down) is taken ("downstream and down").  The force the link passes
to its base is F_out + l f(u); that is F_out of the next link inboard.  After link 1 the base
force is the force with which the cable pulls on its base.

The weight part of l f is evaluated as ms_k g (not w_k l_k) so that with U = 0 the top tension is
the plain sum g (sum ms_k + ms_c) up to the order of summation.

An independent continuum limit (perfectly flexible cable, dF/ds = f(F/|F|), RK4) is provided by
``solve_continuum`` so the convergence of the link discretization can be judged against n = inf.

Inputs may also be the JSON printed by the project's model tool
(``cable_model --config FILE --set ...``): keys ``length``, ``submerged_mass``,
``load_submerged_mass`` and ``gravity``.  That JSON carries neither diameter, density, drag
coefficients, load drag area nor current, so these are separate arguments.

Run ``/usr/bin/python3 test/reference/static_current.py --self-test`` for the checks;
``--model-json FILE --diameter ... --density ... --drag-normal ... --drag-tangential ...
--current ... [--load-drag-area ...]`` prints the equilibrium as JSON.
"""

import argparse
import json
import math
import sys

# Scan resolution of the per-link root search: a_i = pi * i / SCAN_HALF_STEPS, i = -N..N.
SCAN_HALF_STEPS = 360


# ------------------------------------------------------------------------------------------
# Forces
# ------------------------------------------------------------------------------------------
def drag_per_length(ux, uz, diameter, rho, Cdn, Cdt, U):
    """Fluid drag per unit length (fx, fz) on a link with unit axis (ux, uz), water velocity (U, 0).

    Straight from the definition: split v = (U, 0) into v_t = (v.u) u and v_n = v - v_t.
    """
    vx, vz = U, 0.0
    vu = vx * ux + vz * uz
    vtx, vtz = vu * ux, vu * uz
    vnx, vnz = vx - vtx, vz - vtz
    vn = math.hypot(vnx, vnz)
    vt = math.hypot(vtx, vtz)
    cn = 0.5 * rho * Cdn * diameter * vn
    ct = 0.5 * rho * Cdt * math.pi * diameter * vt
    return (cn * vnx + ct * vtx, cn * vnz + ct * vtz)


def load_force(load_submerged_mass, load_drag_area, rho, U, g):
    """Force (Fx, Fz) of the current and gravity/buoyancy on the terminal load."""
    return (0.5 * rho * load_drag_area * U * abs(U), load_submerged_mass * g)


def _link_total_force(a, length, ms, diameter, rho, Cdn, Cdt, U, g):
    """Total external force (drag + weight) on a link at angle a: (l f_drag, ms g)."""
    fx, fz = drag_per_length(math.sin(a), math.cos(a), diameter, rho, Cdn, Cdt, U)
    return (length * fx, length * fz + ms * g)


# ------------------------------------------------------------------------------------------
# One link
# ------------------------------------------------------------------------------------------
def _bisect_decreasing(h, lo, hi, h_lo, h_hi):
    """Root of h on [lo, hi] with h(lo) > 0 > h(hi), bisection down to adjacent doubles."""
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if mid <= lo or mid >= hi:
            break
        h_mid = h(mid)
        if h_mid == 0.0:
            return mid
        if h_mid > 0.0:
            lo, h_lo = mid, h_mid
        else:
            hi, h_hi = mid, h_mid
    return lo if abs(h_lo) <= abs(h_hi) else hi


def solve_link_angle(F_out, length, ms, diameter, rho, Cdn, Cdt, U, g, fallback_angle=0.0):
    """Angle a of one link (from the downward vertical, + downstream) in equilibrium.

    F_out = (Fx, Fz) is the force applied at the link's far end by everything outboard.
    Returns (a, number_of_accepted_roots).
    """
    Fx, Fz = F_out

    def G(a):
        dx, dz = _link_total_force(a, length, ms, diameter, rho, Cdn, Cdt, U, g)
        return (Fx + 0.5 * dx, Fz + 0.5 * dz)

    def h(a):
        gx, gz = G(a)
        return gx * math.cos(a) - gz * math.sin(a)

    def tension(a):
        gx, gz = G(a)
        return gx * math.sin(a) + gz * math.cos(a)

    N = SCAN_HALF_STEPS
    grid = [math.pi * i / N for i in range(-N, N + 1)]  # grid[N] == 0.0 exactly
    hv = [h(a) for a in grid]
    scale = max(abs(v) for v in hv)
    if scale == 0.0:
        # G vanishes identically (e.g. neutrally buoyant, unloaded, no current): any angle.
        return fallback_angle, 0

    roots = []
    m = len(grid) - 1  # grid[0] = -pi and grid[m] = +pi are the same direction
    for i in range(m):
        a0, a1, h0, h1 = grid[i], grid[i + 1], hv[i], hv[(i + 1) % m]
        if h0 == 0.0:
            h_prev = hv[(i - 1) % m]
            if h_prev >= 0.0 and h1 <= 0.0 and not (h_prev == 0.0 and h1 == 0.0):
                roots.append(a0)
        elif h0 > 0.0 and h1 < 0.0:
            roots.append(_bisect_decreasing(h, a0, a1, h0, h1))
    roots = [a for a in roots if tension(a) > 0.0]
    if not roots:
        raise RuntimeError("no stable equilibrium in tension for a link (F_out = %r)" % (F_out,))
    if len(roots) > 1:
        gx, gz = G(0.0)
        ref = math.atan2(gx, gz)
        roots.sort(key=lambda a: abs(math.remainder(a - ref, 2.0 * math.pi)))
    a = roots[0]
    if a <= -math.pi:
        a += 2.0 * math.pi
    return a, len(roots)


# ------------------------------------------------------------------------------------------
# Whole cable
# ------------------------------------------------------------------------------------------
def solve_static_current(lengths, submerged_mass, load_submerged_mass, diameter, rho, Cdn, Cdt, U, g,
                         load_drag_area=0.0):
    """Static equilibrium of the n-link cable in a uniform current along +x (z down).

    lengths, submerged_mass: per link, base first [m], [kg]; load_submerged_mass [kg];
    diameter [m] (outer); rho [kg/m^3]; Cdn, Cdt [-]; U [m/s] (along +x, may be negative);
    g [m/s^2]; load_drag_area C_d A of the load [m^2].

    Returns a dict:
      top_tension   |base force| [N]
      top_angle     angle of link 1 from the downward vertical, + downstream [rad]
      link_angles   angles of links 1..n [rad]
      ends          (x, z) of the n+1 link ends, base (0, 0) first [m]
      base_force    (Fx, Fz): force with which the cable pulls on the base [N]
      load_offset   horizontal offset x of the load (far end of link n) from the base [m]
      load_depth    z of the load below the base [m]
      link_tensions |force passed to the base end| of links 1..n [N]
      load_force    (Fx, Fz) on the load [N]
      roots_per_link number of accepted (stable, tensile) roots per link; > 1 = ambiguous
    """
    lengths = [float(v) for v in lengths]
    submerged_mass = [float(v) for v in submerged_mass]
    n = len(lengths)
    if n < 1 or len(submerged_mass) != n:
        raise ValueError("need n >= 1 links and one submerged mass per link")
    if any(l <= 0.0 for l in lengths):
        raise ValueError("link lengths must be positive")

    F_load = load_force(load_submerged_mass, load_drag_area, rho, U, g)
    F = F_load
    angles = [0.0] * n
    tensions = [0.0] * n
    nroots = [0] * n
    previous = 0.0
    for k in range(n - 1, -1, -1):
        a, nr = solve_link_angle(F, lengths[k], submerged_mass[k], diameter, rho, Cdn, Cdt, U, g,
                                 fallback_angle=previous)
        dx, dz = _link_total_force(a, lengths[k], submerged_mass[k], diameter, rho, Cdn, Cdt, U, g)
        F = (F[0] + dx, F[1] + dz)
        angles[k], nroots[k], tensions[k] = a, nr, math.hypot(F[0], F[1])
        previous = a

    ends = [(0.0, 0.0)]
    x = z = 0.0
    for l, a in zip(lengths, angles):
        x += l * math.sin(a)
        z += l * math.cos(a)
        ends.append((x, z))

    return {
        "top_tension": math.hypot(F[0], F[1]),
        "top_angle": angles[0],
        "link_angles": angles,
        "ends": ends,
        "base_force": (F[0], F[1]),
        "load_offset": ends[-1][0],
        "load_depth": ends[-1][1],
        "link_tensions": tensions,
        "load_force": F_load,
        "roots_per_link": nroots,
    }


def solve_from_model_json(model, diameter, rho, Cdn, Cdt, U, load_drag_area=0.0):
    """Same as solve_static_current, with the cable taken from `cable_model` JSON (a dict)."""
    return solve_static_current(model["length"], model["submerged_mass"], model["load_submerged_mass"],
                                diameter, rho, Cdn, Cdt, U, model["gravity"], load_drag_area)


def uniform_cable(total_length, n, submerged_mass_per_length):
    """(lengths, submerged masses) of n equal links of a uniform cable."""
    l = total_length / n
    return [l] * n, [submerged_mass_per_length * l] * n


# ------------------------------------------------------------------------------------------
# Continuum limit (independent of the link model): perfectly flexible cable, RK4
# ------------------------------------------------------------------------------------------
def solve_continuum(lengths, submerged_mass, load_submerged_mass, diameter, rho, Cdn, Cdt, U, g,
                    load_drag_area=0.0, steps_per_meter=400):
    """n -> infinity limit: a flexible cable with the per-length properties of the links.

    Integrates from the tip towards the base over arc length s (measured from the tip):
        dF/ds = f(u) (drag + weight per length),  u = F/|F|,  dr/ds = -u,
    where F is the tension force (pointing towards the tip) at the section.  Needs |F| > 0 at the
    tip, i.e. a load with non-zero force.  Returns top_tension, top_angle (direction of the
    cable at the base), base_force, load_offset, load_depth.
    """
    F = load_force(load_submerged_mass, load_drag_area, rho, U, g)
    if math.hypot(*F) == 0.0:
        raise ValueError("continuum reference needs a loaded tip")

    def rhs(state, w):
        Fx, Fz = state[0], state[1]
        T = math.hypot(Fx, Fz)
        ux, uz = Fx / T, Fz / T
        dx, dz = drag_per_length(ux, uz, diameter, rho, Cdn, Cdt, U)
        return (dx, dz + w, -ux, -uz)

    s = (F[0], F[1], 0.0, 0.0)
    for l, ms in zip(reversed([float(v) for v in lengths]), reversed([float(v) for v in submerged_mass])):
        w = ms * g / l
        m = max(1, int(math.ceil(l * steps_per_meter)))
        h = l / m
        for _ in range(m):
            k1 = rhs(s, w)
            k2 = rhs(tuple(si + 0.5 * h * ki for si, ki in zip(s, k1)), w)
            k3 = rhs(tuple(si + 0.5 * h * ki for si, ki in zip(s, k2)), w)
            k4 = rhs(tuple(si + h * ki for si, ki in zip(s, k3)), w)
            s = tuple(si + h / 6.0 * (a + 2.0 * b + 2.0 * c + d) for si, a, b, c, d in zip(s, k1, k2, k3, k4))
    Fx, Fz, rx, rz = s  # r = base position relative to the tip
    return {
        "top_tension": math.hypot(Fx, Fz),
        "top_angle": math.atan2(Fx, Fz),
        "base_force": (Fx, Fz),
        "load_offset": -rx,
        "load_depth": -rz,
    }


# ------------------------------------------------------------------------------------------
# Self-checks (plain functions: each raises AssertionError on failure and returns its figures)
# ------------------------------------------------------------------------------------------
# The paper-current case of the brief (config/paper_current.yaml has 0.2755 kg/m submerged).
PAPER_CASE = dict(total_length=20.0, diameter=0.03, ms_per_length=0.28, load_submerged_mass=15.9,
                  rho=1025.0, Cdn=1.2, Cdt=0.01, U=3.5, g=9.81)


def check_zero_current():
    """U = 0: every link straight down (angle exactly 0), top tension = g (sum ms_k + ms_c)."""
    cases = [
        ([2.0] * 10, [0.56] * 10, 15.9),
        ([0.7, 1.3, 2.9, 0.4], [0.3, -0.1, 1.7, 0.05], 2.5),  # one buoyant link, uneven lengths
        ([5.0], [1.2], 0.0),
    ]
    g = 9.81
    worst = 0.0
    for lengths, ms, msc in cases:
        r = solve_static_current(lengths, ms, msc, 0.03, 1025.0, 1.2, 0.01, 0.0, g, load_drag_area=0.3)
        assert all(a == 0.0 for a in r["link_angles"]), r["link_angles"]
        assert all(x == 0.0 for x, _ in r["ends"]), r["ends"]
        assert r["base_force"][0] == 0.0
        expected = g * (sum(ms) + msc)
        err = abs(r["top_tension"] - expected)
        assert err <= 1e-12 * abs(expected), (r["top_tension"], expected)
        assert abs(r["load_depth"] - sum(lengths)) <= 1e-12 * sum(lengths)
        worst = max(worst, err)
    return {"cases": len(cases), "max_abs_tension_error_N": worst}


def single_link_closed_form(length, ms, diameter, rho, Cdn, U, g):
    """Closed-form angle of one link, no load, normal drag only (Cdt = 0).

    At angle a the normal relative velocity is U cos a, so the normal drag per length is
    D cos^2 a (D = 1/2 rho Cdn d U|U|), perpendicular to the link; it and the weight w = ms g / l
    are uniform, so both act at mid-link.  Moment about the base (arm l/2 for both):
        D cos^2 a = w sin a      <=>  tan a = D cos^2 a / (w cos a)
    i.e. tan a = (normal drag per length) / (normal component of the weight per length).
    With s = sin a:  D s^2 + w s - D = 0  ->  s = 2 D / (w + sqrt(w^2 + 4 D^2))
    (the root with |s| < 1 for w > 0; written without cancellation).
    """
    w = ms * g / length
    D = 0.5 * rho * Cdn * diameter * U * abs(U)
    s = 2.0 * D / (w + math.sqrt(w * w + 4.0 * D * D))
    return math.atan2(s, math.sqrt((1.0 - s) * (1.0 + s)))


def check_single_link_closed_form(tol=1e-9):
    """n = 1, no load, Cdt = 0: shooting angle == closed form to `tol`."""
    rows = []
    for length, ms, d, U in [(20.0, 5.6, 0.03, 3.5), (2.0, 0.56, 0.03, 0.5), (1.0, 2.0, 0.05, -1.5),
                             (10.0, 0.1, 0.02, 10.0), (3.0, 1.0, 0.03, 1e-3)]:
        rho, Cdn, g = 1025.0, 1.2, 9.81
        r = solve_static_current([length], [ms], 0.0, d, rho, Cdn, 0.0, U, g)
        exact = single_link_closed_form(length, ms, d, rho, Cdn, U, g)
        err = abs(r["top_angle"] - exact)
        assert err <= tol, (length, ms, d, U, r["top_angle"], exact)
        # the residual of the moment balance itself, in closed form
        w = ms * g / length
        D = 0.5 * rho * Cdn * d * U * abs(U)
        a = r["top_angle"]
        resid = D * math.cos(a) ** 2 - w * math.sin(a)
        assert abs(resid) <= 1e-12 * max(abs(D), abs(w)), resid
        rows.append({"U": U, "angle_deg": math.degrees(exact), "abs_error_rad": err})
    return rows


def check_convergence(ns=(5, 10, 20, 40, 80), case=None):
    """Top tension etc. for n equal links of the same cable; must converge (~ 1/n^2) to the
    continuum limit.  Returns the table rows and the continuum reference."""
    c = dict(PAPER_CASE if case is None else case)
    rows = []
    for n in ns:
        lengths, ms = uniform_cable(c["total_length"], n, c["ms_per_length"])
        r = solve_static_current(lengths, ms, c["load_submerged_mass"], c["diameter"], c["rho"], c["Cdn"],
                                 c["Cdt"], c["U"], c["g"], c.get("load_drag_area", 0.0))
        rows.append({"n": n, "top_tension": r["top_tension"], "top_angle_deg": math.degrees(r["top_angle"]),
                     "load_offset": r["load_offset"], "load_depth": r["load_depth"],
                     "tip_angle_deg": math.degrees(r["link_angles"][-1])})
    lengths, ms = uniform_cable(c["total_length"], 1, c["ms_per_length"])
    cont = solve_continuum(lengths, ms, c["load_submerged_mass"], c["diameter"], c["rho"], c["Cdn"], c["Cdt"],
                           c["U"], c["g"], c.get("load_drag_area", 0.0))
    cont2 = solve_continuum(lengths, ms, c["load_submerged_mass"], c["diameter"], c["rho"], c["Cdn"], c["Cdt"],
                            c["U"], c["g"], c.get("load_drag_area", 0.0), steps_per_meter=100)
    # RK4 self-consistency of the continuum limit
    assert abs(cont["top_tension"] - cont2["top_tension"]) <= 1e-9 * cont["top_tension"]
    T_inf = cont["top_tension"]
    for r in rows:
        r["tension_minus_continuum"] = r["top_tension"] - T_inf
    errs = [abs(r["tension_minus_continuum"]) for r in rows]
    for e0, e1 in zip(errs, errs[1:]):
        assert e1 < 0.5 * e0, errs  # at least first order; the link model is ~2nd order
    assert errs[-1] <= 1e-3 * T_inf, errs
    return rows, cont


def _external_forces(result, lengths, submerged_mass, load_submerged_mass, diameter, rho, Cdn, Cdt, U, g,
                     load_drag_area):
    """[(point of application, force)] recomputed from the end positions only."""
    ends = result["ends"]
    out = []
    for k, (l, ms) in enumerate(zip(lengths, submerged_mass)):
        (x0, z0), (x1, z1) = ends[k], ends[k + 1]
        ux, uz = (x1 - x0) / l, (z1 - z0) / l
        fx, fz = drag_per_length(ux, uz, diameter, rho, Cdn, Cdt, U)
        # uniform distributed load -> resultant at mid-link
        out.append(((0.5 * (x0 + x1), 0.5 * (z0 + z1)), (l * fx, l * fz + ms * g), k))
    out.append((ends[-1], load_force(load_submerged_mass, load_drag_area, rho, U, g), len(lengths)))
    return out


def check_global_balance(tol=1e-9):
    """Base force == sum of all external forces (drag + weight + load) to `tol` [N], recomputed
    from the link end positions alone; also the moment of everything outboard of every joint
    about that joint vanishes (pinned joints), to tol * (top tension * length)."""
    import random
    rs = random.Random(7)
    c = PAPER_CASE
    cases = []
    for n, cda in [(5, 0.0), (20, 0.35), (80, 0.0)]:
        lengths, ms = uniform_cable(c["total_length"], n, c["ms_per_length"])
        cases.append((lengths, ms, c["load_submerged_mass"], c["diameter"], c["rho"], c["Cdn"], c["Cdt"], c["U"],
                      c["g"], cda))
    for _ in range(4):  # random non-uniform cables, some buoyant links, either current direction
        n = rs.randint(1, 12)
        lengths = [rs.uniform(0.3, 4.0) for _ in range(n)]
        ms = [l * rs.uniform(-0.2, 1.0) for l in lengths]
        cases.append((lengths, ms, rs.uniform(0.0, 10.0) + max(0.0, -sum(ms)), rs.uniform(0.01, 0.08), 1025.0,
                      rs.uniform(0.8, 1.5), rs.uniform(0.0, 0.05), rs.uniform(-4.0, 4.0), 9.81, rs.uniform(0.0, 0.5)))
    worst_f = worst_m = 0.0
    for args in cases:
        r = solve_static_current(*args[:9], load_drag_area=args[9])
        forces = _external_forces(r, *args)
        sx = sum(F[0] for _, F, _ in forces)
        sz = sum(F[1] for _, F, _ in forces)
        ef = max(abs(sx - r["base_force"][0]), abs(sz - r["base_force"][1]))
        assert ef <= tol, (ef, args)
        worst_f = max(worst_f, ef)
        L = sum(args[0])
        for j, (px, pz) in enumerate(r["ends"][:-1]):
            # moment (y component up to sign) of all forces acting on links j+1..n and the load
            M = sum((qx - px) * F[1] - (qz - pz) * F[0] for (qx, qz), F, k in forces if k >= j)
            em = abs(M) / (r["top_tension"] * L)
            assert em <= tol, (j, M, args)
            worst_m = max(worst_m, em)
    return {"cases": len(cases), "max_abs_force_error_N": worst_f, "max_rel_moment_error": worst_m}


def run_self_tests(out=sys.stdout):
    """Runs all checks, prints the figures; raises AssertionError on failure."""
    r1 = check_zero_current()
    print("1. U = 0: %d cases, all angles == 0, max |T_top - g sum ms| = %.3g N"
          % (r1["cases"], r1["max_abs_tension_error_N"]), file=out)
    r2 = check_single_link_closed_form()
    print("2. single link, normal drag only, closed form D cos^2 a = w sin a:", file=out)
    for row in r2:
        print("   U = %7.3f m/s  angle = %12.8f deg  |shoot - exact| = %.2e rad"
              % (row["U"], row["angle_deg"], row["abs_error_rad"]), file=out)
    rows, cont = check_convergence(ns=(5, 10, 20, 40, 80, 160))
    print("3. convergence, 20 m cable, d 0.03, ms 0.28 kg/m, load 15.9 kg, rho 1025, Cdn 1.2, Cdt 0.01,"
          " U 3.5, g 9.81, CdA_load 0:", file=out)
    print("   %5s %14s %13s %13s %12s %12s %14s" % ("n", "T_top [N]", "top [deg]", "tip [deg]", "x_load [m]",
                                                 "z_load [m]", "T - T_inf [N]"), file=out)
    for r in rows:
        print("   %5d %14.8f %13.8f %13.8f %12.8f %12.8f %14.3e"
              % (r["n"], r["top_tension"], r["top_angle_deg"], r["tip_angle_deg"], r["load_offset"],
                 r["load_depth"], r["tension_minus_continuum"]), file=out)
    print("   %5s %14.8f %13.8f %13s %12.8f %12.8f   (continuum, RK4)"
          % ("inf", cont["top_tension"], math.degrees(cont["top_angle"]), "", cont["load_offset"],
             cont["load_depth"]), file=out)
    r4 = check_global_balance()
    print("4. global balance: %d cases, max |F_base - sum F_ext| = %.2e N, max joint moment / (T L) = %.2e"
          % (r4["cases"], r4["max_abs_force_error_N"], r4["max_rel_moment_error"]), file=out)
    print("all self-tests passed", file=out)


# ------------------------------------------------------------------------------------------
def _jsonable(x):
    if isinstance(x, dict):
        return {k: _jsonable(v) for k, v in x.items()}
    if isinstance(x, (list, tuple)):
        return [_jsonable(v) for v in x]
    return x


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.split("\n")[1],
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--self-test", action="store_true", help="run the self-checks and print their figures")
    p.add_argument("--model-json", metavar="FILE",
                   help="JSON printed by cable_model (keys length, submerged_mass, load_submerged_mass, "
                        "gravity); '-' or omitted = stdin")
    p.add_argument("--diameter", type=float, help="outer cable diameter [m]")
    p.add_argument("--density", type=float, help="water density [kg/m^3]")
    p.add_argument("--drag-normal", type=float, help="normal drag coefficient Cdn [-]")
    p.add_argument("--drag-tangential", type=float, help="tangential drag coefficient Cdt [-]")
    p.add_argument("--current", type=float, help="current speed U along +x [m/s]")
    p.add_argument("--load-drag-area", type=float, default=0.0, help="load C_d A [m^2] (default 0)")
    a = p.parse_args(argv)
    if a.self_test:
        run_self_tests()
        return 0
    missing = [name for name in ("diameter", "density", "drag_normal", "drag_tangential", "current")
               if getattr(a, name) is None]
    if missing:
        p.error("missing " + ", ".join("--" + m.replace("_", "-") for m in missing))
    if a.model_json in (None, "-"):
        model = json.load(sys.stdin)
    else:
        with open(a.model_json) as fh:
            model = json.load(fh)
    r = solve_from_model_json(model, a.diameter, a.density, a.drag_normal, a.drag_tangential, a.current,
                              a.load_drag_area)
    json.dump(_jsonable(r), sys.stdout, indent=1)
    sys.stdout.write("\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
