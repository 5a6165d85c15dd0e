#!/usr/bin/env python3
"""Independent symbolic reference for the n-link cable model (Lagrange from energies).

Why this file exists
--------------------
The C++ model generator builds the mass matrix M(q), the Coriolis/centrifugal vector h(q, q')
and the gravity/buoyancy vector G(q) of the n-link cable of Gomes, Zanela and Pereira (2016)
for any n.  Hand-written closed-form mass-matrix formulas are exactly where sign, index and
frame conventions go wrong, and a test that re-implements the same formulas would only repeat
the same mistakes.  This module therefore starts from nothing but the *definitions*:

* the kinematics (link axis u_k, joint positions p_k, centres of mass c_k, link orientation R_k),
* the kinetic energy T (translation of every link CoM, rotation of every link with an
  axisymmetric inertia, translation of the terminal point load) and
* the potential V (gravity minus buoyancy),

and lets sympy do every derivative:

    M = d^2 T / dq' dq'^T                      (Hessian of T in the rates)
    h = (d/dt dT/dq')|_{q''=0} - dT/dq = (d(dT/dq')/dq) q' - dT/dq
    G = dV/dq

so that  M q'' + h + G  equals the generalized forces of springs, damping and fluid (which are
not part of this reference).  The angular velocity is obtained from the skew matrix
dR/dt R^T of the orientation written as a function of time, not from Euler-rate formulas,
so the rotational part is also independent of any hand derivation.

Conventions (same as the C++ package)
-------------------------------------
* n links, base fixed at the origin, world z axis pointing DOWN (towards Earth's centre).
* q = [te_1, a_1, t_1, ..., te_n, a_n, t_n]; te_k absolute elevation from the downward vertical,
  azimuth relative (psi_k = a_1 + ... + a_k), torsion relative (phi_k = t_1 + ... + t_k).
* u_k = (sin te_k sin psi_k, sin te_k cos psi_k, cos te_k);  p_k = sum_{j<k} l_j u_j;
  c_k = p_k + l_k/2 u_k (Eq. 2 of the paper);  load at p_{n+1} = sum_{j<=n} l_j u_j.
* R_k = Rz(-psi_k) Rx(-te_k) Rz(-phi_k), so that R_k e_z = u_k.
* I_world,k = I_T (Id - u u^T) + I_P u u^T about the CoM.
* V = -g (sum_k ms_k z(c_k) + ms_load z(p_{n+1}))   (height is -z; ms = submerged mass).

No symbolic simplification is performed (it is slow and unnecessary): the raw derivative trees
are turned into numeric code with ``sympy.lambdify(..., cse=True)``, which removes the repeated
sub-expressions.  Results are cached per n.

Numeric interface
-----------------
``build(n)`` returns a :class:`CableReference` whose methods ``M``, ``h``, ``G``, ``T``, ``V``
take ``(params, q, qd)`` where ``params`` is a dict with the keys used by the C++ JSON output:
``mass``, ``length``, ``inertia_transverse``, ``inertia_polar``, ``submerged_mass`` (length-n
sequences) and ``load_mass``, ``load_submerged_mass``, ``gravity`` (scalars).

Run ``/usr/bin/python3 test/reference/sympy_cable_lagrange.py`` for timings and sanity checks.
"""

import functools
import time

import numpy as np
import sympy as sp

PER_LINK_KEYS = ("mass", "length", "inertia_transverse", "inertia_polar", "submerged_mass")
SCALAR_KEYS = ("load_mass", "load_submerged_mass", "gravity")
JOINT_KINDS = ("elevation", "azimuth", "torsion")


def coordinate_names(n):
    """Names of the 3n generalized coordinates in the order of q (K = 1..n)."""
    return ["joint_%d_%s" % (k, kind) for k in range(1, n + 1) for kind in JOINT_KINDS]


def rot_x(a):
    """Standard active rotation about x by angle a."""
    c, s = sp.cos(a), sp.sin(a)
    return sp.Matrix([[1, 0, 0], [0, c, -s], [0, s, c]])


def rot_z(a):
    """Standard active rotation about z by angle a."""
    c, s = sp.cos(a), sp.sin(a)
    return sp.Matrix([[c, -s, 0], [s, c, 0], [0, 0, 1]])


def link_axis(te, psi):
    """Unit axis of a link, pointing from its base end to its far end (z down)."""
    return sp.Matrix([sp.sin(te) * sp.sin(psi), sp.sin(te) * sp.cos(psi), sp.cos(te)])


def link_orientation(te, psi, phi):
    """Orientation of a link: R = Rz(-psi) Rx(-te) Rz(-phi); its local z axis is the link axis."""
    return rot_z(-psi) * rot_x(-te) * rot_z(-phi)


class CableReference:
    """Symbolic derivation for one n plus its lambdified numeric evaluators."""

    def __init__(self, n):
        if n < 1:
            raise ValueError("n must be >= 1")
        self.n = n
        self.names = coordinate_names(n)
        timings = {}
        t0 = time.perf_counter()

        # --- symbols ---------------------------------------------------------------------
        time_sym = sp.Symbol("time", real=True)
        q = sp.symbols(["q_%s" % nm for nm in self.names], real=True)
        qd = sp.symbols(["qd_%s" % nm for nm in self.names], real=True)
        # Coordinates as functions of time: the velocities below are genuine d/dt derivatives.
        qf = [sp.Function("f_%s" % nm, real=True)(time_sym) for nm in self.names]
        m = sp.symbols("m_1:%d" % (n + 1), positive=True)
        ln = sp.symbols("l_1:%d" % (n + 1), positive=True)
        it = sp.symbols("IT_1:%d" % (n + 1), positive=True)
        ip = sp.symbols("IP_1:%d" % (n + 1), positive=True)
        ms = sp.symbols("ms_1:%d" % (n + 1), real=True)
        m_load, ms_load, g = sp.symbols("m_load ms_load g", real=True)
        self.q_syms, self.qd_syms = list(q), list(qd)
        self.param_syms = list(m) + list(ln) + list(it) + list(ip) + list(ms) + [m_load, ms_load, g]

        # Replace q_i'(t) -> qd_i first, then q_i(t) -> q_i.
        deriv_sub = {sp.Derivative(f, time_sym): v for f, v in zip(qf, qd)}
        func_sub = {f: v for f, v in zip(qf, q)}

        def to_state(expr):
            return expr.xreplace(deriv_sub).xreplace(func_sub)

        def ddt(expr):
            return to_state(sp.diff(expr, time_sym))

        # --- kinematics as functions of time ----------------------------------------------
        te = qf[0::3]
        az = qf[1::3]
        tw = qf[2::3]
        psi = [sum(az[: k + 1], sp.S.Zero) for k in range(n)]
        phi = [sum(tw[: k + 1], sp.S.Zero) for k in range(n)]
        u = [link_axis(te[k], psi[k]) for k in range(n)]
        p = [sp.zeros(3, 1)]
        for k in range(n):
            p.append(p[k] + ln[k] * u[k])
        c = [p[k] + ln[k] / 2 * u[k] for k in range(n)]

        # --- energies ---------------------------------------------------------------------
        T = sp.S.Zero
        V = sp.S.Zero
        self._omega_exprs = []  # world angular velocities, kept for the sanity checks
        self._skew_residuals = []
        self._axis_residuals = []
        for k in range(n):
            vc = ddt(c[k])
            T += m[k] * vc.dot(vc) / 2
            R = link_orientation(te[k], psi[k], phi[k])
            Rdot = ddt(R)
            Rs = to_state(R)
            W = Rdot * Rs.T  # skew-symmetric: [w]_x
            w = sp.Matrix([W[2, 1], W[0, 2], W[1, 0]])
            self._omega_exprs.append(w)
            self._skew_residuals.append(W + W.T)
            self._axis_residuals.append(Rs[:, 2] - to_state(u[k]))
            uk = to_state(u[k])
            uw = uk.dot(w)
            # 1/2 w^T (I_T (Id - u u^T) + I_P u u^T) w
            T += (it[k] * (w.dot(w) - uw**2) + ip[k] * uw**2) / 2
            V += -g * ms[k] * to_state(c[k])[2]
        v_load = ddt(p[n])
        T += m_load * v_load.dot(v_load) / 2
        V += -g * ms_load * to_state(p[n])[2]
        self.T_expr, self.V_expr = T, V
        self._u_state = [to_state(uk) for uk in u]
        timings["energies"] = time.perf_counter() - t0

        # --- Lagrange ---------------------------------------------------------------------
        t1 = time.perf_counter()
        dT_dqd = [sp.diff(T, v) for v in qd]
        N = 3 * n
        Mx = sp.zeros(N, N)
        for i in range(N):
            for j in range(i, N):
                Mx[i, j] = sp.diff(dT_dqd[i], qd[j])
                Mx[j, i] = Mx[i, j]  # Hessian: symmetric by construction (same expression)
        hx = sp.zeros(N, 1)
        for i in range(N):
            hx[i] = sum((sp.diff(dT_dqd[i], q[j]) * qd[j] for j in range(N)), sp.S.Zero) - sp.diff(T, q[i])
        Gx = sp.Matrix([sp.diff(V, v) for v in q])
        self.M_expr, self.h_expr, self.G_expr = Mx, hx, Gx
        timings["derivatives"] = time.perf_counter() - t1

        # --- numeric code -----------------------------------------------------------------
        t2 = time.perf_counter()
        args = self.param_syms + self.q_syms + self.qd_syms
        self._M = sp.lambdify(args, Mx, modules="numpy", cse=True)
        self._h = sp.lambdify(args, hx, modules="numpy", cse=True)
        self._G = sp.lambdify(args, Gx, modules="numpy", cse=True)
        self._T = sp.lambdify(args, T, modules="numpy", cse=True)
        self._V = sp.lambdify(args, V, modules="numpy", cse=True)
        timings["lambdify"] = time.perf_counter() - t2
        timings["total"] = time.perf_counter() - t0
        self.timings = timings

    # --- numeric evaluation ------------------------------------------------------------------
    def _args(self, params, q, qd):
        n = self.n
        vals = []
        for key in PER_LINK_KEYS:
            arr = [float(x) for x in params[key]]
            if len(arr) != n:
                raise ValueError("params[%r] has length %d, expected %d" % (key, len(arr), n))
            vals.extend(arr)
        vals.extend(float(params[key]) for key in SCALAR_KEYS)
        q = [float(x) for x in q]
        qd = [float(x) for x in qd]
        if len(q) != 3 * n or len(qd) != 3 * n:
            raise ValueError("q and qd must have length %d" % (3 * n))
        return vals + q + qd

    def M(self, params, q, qd=None):
        """Mass matrix (3n x 3n); independent of qd (which may be omitted)."""
        if qd is None:
            qd = np.zeros(3 * self.n)
        return np.asarray(self._M(*self._args(params, q, qd)), dtype=float).reshape(3 * self.n, 3 * self.n)

    def h(self, params, q, qd):
        """Coriolis/centrifugal vector (3n)."""
        return np.asarray(self._h(*self._args(params, q, qd)), dtype=float).reshape(3 * self.n)

    def G(self, params, q, qd=None):
        """Gravity-minus-buoyancy generalized force dV/dq (3n)."""
        if qd is None:
            qd = np.zeros(3 * self.n)
        return np.asarray(self._G(*self._args(params, q, qd)), dtype=float).reshape(3 * self.n)

    def T(self, params, q, qd):
        """Kinetic energy."""
        return float(self._T(*self._args(params, q, qd)))

    def V(self, params, q, qd=None):
        """Potential energy."""
        if qd is None:
            qd = np.zeros(3 * self.n)
        return float(self._V(*self._args(params, q, qd)))

    def accel(self, params, q, qd, tau=None):
        """q'' from M q'' + h + G = tau (tau = 0 by default)."""
        rhs = -self.h(params, q, qd) - self.G(params, q)
        if tau is not None:
            rhs = rhs + np.asarray(tau, dtype=float)
        return np.linalg.solve(self.M(params, q), rhs)


@functools.lru_cache(maxsize=None)
def build(n):
    """Derive (once per n, cached) the reference model of an n-link cable."""
    return CableReference(int(n))


def params_from_json(data):
    """Extract the physical parameters from the JSON printed by the C++ ``cable_model`` tool."""
    out = {key: [float(x) for x in data[key]] for key in PER_LINK_KEYS}
    out.update({key: float(data[key]) for key in SCALAR_KEYS})
    return out


def example_params(n, seed=0):
    """Plausible but deliberately irregular parameters (for the self-checks only)."""
    rs = np.random.RandomState(seed)
    m = rs.uniform(0.5, 3.0, n)
    ln = rs.uniform(0.5, 2.5, n)
    r = rs.uniform(0.01, 0.2, n)
    return {
        "mass": list(m),
        "length": list(ln),
        "inertia_transverse": list(m * (ln**2 / 12 + r**2 / 4)),
        "inertia_polar": list(m * r**2 / 2),
        "submerged_mass": list(m * rs.uniform(0.2, 0.9, n)),
        "load_mass": float(rs.uniform(1.0, 10.0)),
        "load_submerged_mass": float(rs.uniform(0.5, 5.0)),
        "gravity": 9.81,
    }


def random_state(n, rs):
    """Random state away from zero elevation (where M is singular), as used by the tests."""
    q = np.empty(3 * n)
    q[0::3] = rs.uniform(0.2, 1.3, n)
    q[1::3] = rs.uniform(-np.pi, np.pi, n)
    q[2::3] = rs.uniform(-np.pi, np.pi, n)
    qd = rs.uniform(-2.0, 2.0, 3 * n)
    return q, qd


def _numeric_kinematics_checks(ref, params, q, qd):
    """Max residuals of R e_z - u and of the skew-symmetry of dR/dt R^T at one state."""
    args = ref.param_syms + ref.q_syms + ref.qd_syms
    vals = ref._args(params, q, qd)
    worst_axis = 0.0
    worst_skew = 0.0
    for k in range(ref.n):
        fa = sp.lambdify(args, ref._axis_residuals[k], modules="numpy", cse=True)
        fs = sp.lambdify(args, ref._skew_residuals[k], modules="numpy", cse=True)
        worst_axis = max(worst_axis, float(np.max(np.abs(np.asarray(fa(*vals), dtype=float)))))
        worst_skew = max(worst_skew, float(np.max(np.abs(np.asarray(fs(*vals), dtype=float)))))
    return worst_axis, worst_skew


def energy_drift(ref, params, q0, qd0, dt=1e-3, steps=2000):
    """Relative drift of T + V along an unforced RK4 trajectory of M q'' + h + G = 0.

    A wrong h (or an M/h mismatch) does not conserve energy, so this checks the derived
    equations against the energies they came from.
    """
    def f(x):
        nq = 3 * ref.n
        return np.concatenate([x[nq:], ref.accel(params, x[:nq], x[nq:])])

    nq = 3 * ref.n
    x = np.concatenate([q0, qd0]).astype(float)
    e0 = ref.T(params, x[:nq], x[nq:]) + ref.V(params, x[:nq])
    scale = abs(ref.T(params, x[:nq], x[nq:])) + abs(ref.V(params, x[:nq])) + 1e-300
    worst = 0.0
    for _ in range(steps):
        k1 = f(x)
        k2 = f(x + dt / 2 * k1)
        k3 = f(x + dt / 2 * k2)
        k4 = f(x + dt * k3)
        x = x + dt / 6 * (k1 + 2 * k2 + 2 * k3 + k4)
        e = ref.T(params, x[:nq], x[nq:]) + ref.V(params, x[:nq])
        worst = max(worst, abs(e - e0) / scale)
    return worst


def _main():
    # n = 1 closed form (pendulum with axisymmetric inertia, no load, in air).
    ref1 = build(1)
    m_, l_, it_, ip_, g_ = 1.7, 1.3, 0.31, 0.02, 9.81
    p1 = {"mass": [m_], "length": [l_], "inertia_transverse": [it_], "inertia_polar": [ip_],
          "submerged_mass": [m_], "load_mass": 0.0, "load_submerged_mass": 0.0, "gravity": g_}
    q1 = [0.7, 0.4, -1.1]
    M1 = ref1.M(p1, q1)
    G1 = ref1.G(p1, q1)
    print("n=1: M[0,0] = %.15g (expected %.15g)" % (M1[0, 0], m_ * l_**2 / 4 + it_))
    print("n=1: G[0]   = %.15g (expected %.15g)" % (G1[0], g_ * m_ * l_ / 2 * np.sin(q1[0])))

    for n in (2, 3, 4):
        t0 = time.perf_counter()
        ref = build(n)
        wall = time.perf_counter() - t0
        tm = ref.timings
        print("n=%d: build %.2f s (energies %.2f, derivatives %.2f, lambdify %.2f)"
              % (n, wall, tm["energies"], tm["derivatives"], tm["lambdify"]))
        rs = np.random.RandomState(100 + n)
        params = example_params(n, seed=n)
        q, qd = random_state(n, rs)
        t1 = time.perf_counter()
        Mn = ref.M(params, q)
        hn = ref.h(params, q, qd)
        Gn = ref.G(params, q)
        t_eval = time.perf_counter() - t1
        Tn = ref.T(params, q, qd)
        axis_res, skew_res = _numeric_kinematics_checks(ref, params, q, qd)
        eig = np.linalg.eigvalsh(Mn)
        print("   eval M,h,G %.2f ms; |R e_z - u| %.1e; |W + W^T| %.1e; |T - qd'Mqd/2| %.1e; "
              "min eig(M) %.3e; |h|max %.3e; |G|max %.3e"
              % (1e3 * t_eval, axis_res, skew_res, abs(Tn - qd @ Mn @ qd / 2), eig[0],
                 np.max(np.abs(hn)), np.max(np.abs(Gn))))
        if n <= 3:
            t2 = time.perf_counter()
            drift = energy_drift(ref, params, q, qd, dt=1e-3, steps=500)
            print("   energy drift over 0.5 s RK4 (dt 1 ms): %.2e (%.1f s)" % (drift, time.perf_counter() - t2))


if __name__ == "__main__":
    _main()
