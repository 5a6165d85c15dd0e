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

and lets the computer take every derivative:

    M = d^2 T / dq' dq'^T                      (Hessian of T in the rates)
    h = (d/dt dT/dq')|_{q''=0} - dT/dq = (d(dT/dq')/dq) q' - dT/dq
    G = dV/dq

The velocities (dc_k/dt, dR_k/dt) come from sympy.diff with q(t) as functions of time.  The
Lagrange derivatives above are taken by a small memoized differentiator on the sympy expression
graph (:class:`_Derivation`, only because sympy.diff is ~10x slower on these large unsimplified
expressions); ``build(n, "sympy")`` does them with plain sympy.diff instead, and the tests check
that both give the same M, h, G.

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
* I_world,k = I_T (Id - u u^T) + I_P u u^T about the CoM, so
  T_rot,k = 1/2 w^T I_world w = 1/2 (I_T |u x w|^2 + I_P (u.w)^2)   (|u| = 1).
* V = -g (sum_k ms_k z(c_k) + ms_load z(p_{n+1}))   (height is -z; ms = submerged mass).

No symbolic simplification is performed (it is slow and unnecessary): the raw derivative trees
are turned into numeric code with ``sympy.lambdify`` with common-subexpression elimination
(its ``cse`` option, given sympy.cse with order="none", which is the same elimination as
``cse=True`` without the slow canonical re-ordering).  Results are cached per n.

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


class _Derivation:
    """Memoized derivation D on expression DAGs, given by its values on the symbols.

    ``_Derivation({x: 1})`` is d/dx;  ``_Derivation({q_j: qd_j})`` is sum_j qd_j d/dq_j.
    Applies the sum, product, power and chain rules (sin, cos) node by node and remembers the
    result of every sub-expression, so shared sub-expressions (the expressions from the energy
    are DAGs with heavy sharing) are differentiated once.  sympy.diff re-walks and re-checks
    the whole result at every level (n = 4: ~30 s for h instead of ~2 s here); the result here
    is the same derivative (checked against sympy.diff by the tests for n = 2), just faster.
    Anything outside these node types raises instead of being guessed.
    """

    def __init__(self, seeds):
        self.seeds = {sp.sympify(k): sp.sympify(v) for k, v in seeds.items()}
        self.memo = {}

    def __call__(self, expr):
        expr = sp.sympify(expr)
        try:
            return self.memo[expr]
        except KeyError:
            pass
        out = self._rule(expr)
        self.memo[expr] = out
        return out

    def _rule(self, e):
        zero = sp.S.Zero
        if e.is_Symbol:
            return self.seeds.get(e, zero)
        if e.is_Number or e.is_NumberSymbol:
            return zero
        if e.is_Add:
            terms = [d for d in map(self, e.args) if d is not zero]
            return sp.Add(*terms) if terms else zero
        if e.is_Mul:
            args = e.args
            terms = []
            for i, a in enumerate(args):
                da = self(a)
                if da is not zero:
                    terms.append(sp.Mul(*(args[:i] + (da,) + args[i + 1:])))
            return sp.Add(*terms) if terms else zero
        if e.is_Pow:
            base, ex = e.args
            if self(ex) is not zero:
                raise TypeError("variable exponent not supported: %s" % (e,))
            db = self(base)
            if db is zero:
                return zero
            return ex * base ** (ex - 1) * db
        if isinstance(e, sp.sin):
            da = self(e.args[0])
            return zero if da is zero else sp.cos(e.args[0]) * da
        if isinstance(e, sp.cos):
            da = self(e.args[0])
            return zero if da is zero else -sp.sin(e.args[0]) * da
        raise TypeError("cannot differentiate node of type %s" % type(e).__name__)


class _Opaque(list):
    """A list of expressions whose str() is short (see the lambdify call)."""

    def __str__(self):
        return "<cable reference expressions>"

    __repr__ = __str__


def _fast_cse(exprs):
    """sympy.cse without canonical re-ordering (same result, several times faster here)."""
    return sp.cse(exprs, order="none")


class CableReference:
    """Symbolic derivation for one n plus its lambdified numeric evaluators.

    ``method="dag"`` differentiates with the memoized :class:`_Derivation` (fast, default);
    ``method="sympy"`` uses plain ``sympy.diff`` for every derivative (slow; used by the tests
    for small n to show that both give the same M, h, G).
    """

    def __init__(self, n, method="dag"):
        if n < 1:
            raise ValueError("n must be >= 1")
        self.n = n
        self.method = method
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
            # 1/2 w^T (I_T (Id - u u^T) + I_P u u^T) w, written with |u x w|^2 for
            # w^T (Id - u u^T) w (equal because |u| = 1).  Same value, but better numbers: the
            # form |w|^2 - (u.w)^2 cancels for spin about the axis and leaves I_T * eps * |w|^2,
            # which swamps the torsion terms when I_T / I_P ~ 1e6 (25 m links, 25 mm thick).
            uw = uk.dot(w)
            uxw = uk.cross(w)
            T += (it[k] * uxw.dot(uxw) + ip[k] * uw**2) / 2
            V += -g * ms[k] * to_state(c[k])[2]
        v_load = ddt(p[n])
        T += m_load * v_load.dot(v_load) / 2
        V += -g * ms_load * to_state(p[n])[2]
        self.T_expr, self.V_expr = T, V
        timings["energies"] = time.perf_counter() - t0

        # --- Lagrange ---------------------------------------------------------------------
        #   mom = dT/dq',  M = d mom/dq',  h = D mom - dT/dq,  G = dV/dq,
        # where D = sum_j q'_j d/dq_j is d/dt along a motion with q'' = 0, so D mom is exactly
        # (d/dt dT/dq')|_{q''=0}.
        t1 = time.perf_counter()
        N = 3 * n
        if method == "dag":
            d_qd = [_Derivation({v: sp.S.One}) for v in qd]
            d_q = [_Derivation({v: sp.S.One}) for v in q]
            d_time = _Derivation(dict(zip(q, qd)))
        elif method == "sympy":
            d_qd = [lambda e, v=v: sp.diff(e, v) for v in qd]
            d_q = [lambda e, v=v: sp.diff(e, v) for v in q]

            def d_time(expr):
                return sum((sp.diff(expr, qj) * vj for qj, vj in zip(q, qd)), sp.S.Zero)
        else:
            raise ValueError("method must be 'dag' or 'sympy'")
        mom = [d_qd[i](T) for i in range(N)]  # generalized momenta dT/dq'
        Mx = sp.zeros(N, N)
        for i in range(N):
            for j in range(i, N):
                Mx[i, j] = d_qd[j](mom[i])
                Mx[j, i] = Mx[i, j]  # a Hessian: symmetric, take the same expression
        hx = sp.Matrix([d_time(mom[i]) - d_q[i](T) for i in range(N)])
        Gx = sp.Matrix([d_q[i](V) for i in range(N)])
        self.M_expr, self.h_expr, self.G_expr = Mx, hx, Gx
        timings["derivatives"] = time.perf_counter() - t1

        # --- numeric code -----------------------------------------------------------------
        # One lambdify for (M, h, G) so that common sub-expressions are shared between them.
        # The list wrapper only stops sympy 1.11's lambdify from str()-ing the whole
        # unsimplified expression for its docstring (that alone took > 25 s for n = 3).
        t2 = time.perf_counter()
        args = self.param_syms + self.q_syms + self.qd_syms
        self._MhG = sp.lambdify(args, _Opaque([Mx, hx, Gx]), modules="numpy", cse=_fast_cse)
        self._TV = sp.lambdify(args, _Opaque([T, V]), modules="numpy", cse=_fast_cse)
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

    def evaluate(self, params, q, qd):
        """(M, h, G) at one state: M (3n x 3n), h (3n), G (3n) as numpy arrays."""
        N = 3 * self.n
        Mv, hv, Gv = self._MhG(*self._args(params, q, qd))
        return (np.asarray(Mv, dtype=float).reshape(N, N),
                np.asarray(hv, dtype=float).reshape(N),
                np.asarray(Gv, dtype=float).reshape(N))

    def M(self, params, q, qd=None):
        """Mass matrix (3n x 3n); independent of qd (which may be omitted)."""
        return self.evaluate(params, q, np.zeros(3 * self.n) if qd is None else qd)[0]

    def h(self, params, q, qd):
        """Coriolis/centrifugal vector (3n)."""
        return self.evaluate(params, q, qd)[1]

    def G(self, params, q, qd=None):
        """Gravity-minus-buoyancy generalized force dV/dq (3n)."""
        return self.evaluate(params, q, np.zeros(3 * self.n) if qd is None else qd)[2]

    def T(self, params, q, qd):
        """Kinetic energy."""
        return float(self._TV(*self._args(params, q, qd))[0])

    def V(self, params, q, qd=None):
        """Potential energy (independent of qd)."""
        qd = np.zeros(3 * self.n) if qd is None else qd
        return float(self._TV(*self._args(params, q, qd))[1])

    def accel(self, params, q, qd, tau=None):
        """q'' from M q'' + h + G = tau (tau = 0 by default)."""
        Mv, hv, Gv = self.evaluate(params, q, qd)
        rhs = -hv - Gv
        if tau is not None:
            rhs = rhs + np.asarray(tau, dtype=float)
        return np.linalg.solve(Mv, rhs)


@functools.lru_cache(maxsize=None)
def build(n, method="dag"):
    """Derive (once per n and method, cached) the reference model of an n-link cable."""
    return CableReference(int(n), method)


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


def single_link_closed_form(params, q, qd):
    """Hand-derived (M, h, G) of ONE link, used only to check the symbolic derivation.

    For n = 1 the energies reduce to
        T = 1/2 A (te'^2 + sin^2 te a'^2) + 1/2 I_P (t' + cos te a')^2,
        A = m l^2/4 + I_T + m_load l^2,
        V = -g (ms l/2 + ms_load l) cos te,
    from which (c = cos te, s = sin te)
        M = [[A, 0, 0], [0, A s^2 + I_P c^2, I_P c], [0, I_P c, I_P]],
        h = [-(A - I_P) s c a'^2 + I_P s a' t',
             2 (A - I_P) s c te' a' - I_P s te' t',
             -I_P s te' a'],
        G = [g (ms l/2 + ms_load l) s, 0, 0].
    """
    m, ln = params["mass"][0], params["length"][0]
    it, ip = params["inertia_transverse"][0], params["inertia_polar"][0]
    ms, g = params["submerged_mass"][0], params["gravity"]
    big_a = m * ln**2 / 4 + it + params["load_mass"] * ln**2
    te, ted, ad, td = q[0], qd[0], qd[1], qd[2]
    c, s = np.cos(te), np.sin(te)
    M = np.array([[big_a, 0.0, 0.0],
                  [0.0, big_a * s**2 + ip * c**2, ip * c],
                  [0.0, ip * c, ip]])
    h = np.array([-(big_a - ip) * s * c * ad**2 + ip * s * ad * td,
                  2 * (big_a - ip) * s * c * ted * ad - ip * s * ted * td,
                  -ip * s * ted * ad])
    G = np.array([g * (ms * ln / 2 + params["load_submerged_mass"] * ln) * s, 0.0, 0.0])
    return M, h, G


def _rel_err(a, b):
    return float(np.max(np.abs(np.asarray(a) - np.asarray(b))) / max(1e-300, np.max(np.abs(b))))


def _main():
    print("sympy %s, numpy %s" % (sp.__version__, np.__version__))
    # n = 1 against the hand-derived single link (no load, in air, then with load and buoyancy).
    ref1 = build(1)
    print("n=1: build %.2f s" % ref1.timings["total"])
    m_, l_, it_, ip_, g_ = 1.7, 1.3, 0.31, 0.02, 9.81
    p1 = {"mass": [m_], "length": [l_], "inertia_transverse": [it_], "inertia_polar": [ip_],
          "submerged_mass": [m_], "load_mass": 0.0, "load_submerged_mass": 0.0, "gravity": g_}
    q1, qd1 = [0.7, 0.4, -1.1], [0.3, -1.2, 0.8]
    M1, h1, G1 = ref1.evaluate(p1, q1, qd1)
    print("   M[0,0] = %.15g (m l^2/4 + I_T = %.15g)" % (M1[0, 0], m_ * l_**2 / 4 + it_))
    print("   G[0]   = %.15g (g m l/2 sin te = %.15g)" % (G1[0], g_ * m_ * l_ / 2 * np.sin(q1[0])))
    p1w = dict(p1, submerged_mass=[0.4 * m_], load_mass=3.0, load_submerged_mass=2.1)
    for label, pp in (("no load, air", p1), ("load, water", p1w)):
        want = single_link_closed_form(pp, q1, qd1)
        got = ref1.evaluate(pp, q1, qd1)
        print("   closed form (%s): rel err M %.1e  h %.1e  G %.1e"
              % ((label,) + tuple(_rel_err(a, b) for a, b in zip(got, want))))

    # The memoized derivation against plain sympy.diff (n = 2).
    ref2s = build(2, "sympy")
    print("n=2 with plain sympy.diff: build %.2f s (derivatives %.2f)"
          % (ref2s.timings["total"], ref2s.timings["derivatives"]))
    rs = np.random.RandomState(7)
    params = example_params(2, seed=7)
    worst = [0.0, 0.0, 0.0]
    for _ in range(5):
        q, qd = random_state(2, rs)
        for i, (a, b) in enumerate(zip(build(2).evaluate(params, q, qd), ref2s.evaluate(params, q, qd))):
            worst[i] = max(worst[i], _rel_err(a, b))
    print("   dag vs sympy.diff: rel err M %.1e  h %.1e  G %.1e" % tuple(worst))

    for n in (2, 3, 4):
        ref = build(n)
        tm = ref.timings
        print("n=%d: build %.2f s (energies %.2f, derivatives %.2f, lambdify %.2f)"
              % (n, tm["total"], tm["energies"], tm["derivatives"], tm["lambdify"]))
        rs = np.random.RandomState(100 + n)
        params = example_params(n, seed=n)
        q, qd = random_state(n, rs)
        t1 = time.perf_counter()
        Mn, hn, Gn = ref.evaluate(params, q, qd)
        t_eval = time.perf_counter() - t1
        Tn = ref.T(params, q, qd)
        axis_res, skew_res = _numeric_kinematics_checks(ref, params, q, qd)
        eig = np.linalg.eigvalsh(Mn)
        print("   eval M,h,G %.2f ms; |R e_z - u| %.1e; |W + W^T| %.1e; |T - qd'Mqd/2| %.1e; "
              "|M - M^T| %.1e; min eig(M) %.3e; |h|max %.3e; |G|max %.3e"
              % (1e3 * t_eval, axis_res, skew_res, abs(Tn - qd @ Mn @ qd / 2),
                 np.max(np.abs(Mn - Mn.T)), eig[0], np.max(np.abs(hn)), np.max(np.abs(Gn))))
        t2 = time.perf_counter()
        drift = energy_drift(ref, params, q, qd, dt=1e-3, steps=500)
        print("   energy drift of M q'' + h + G = 0 over 0.5 s RK4 (dt 1 ms): %.2e (%.1f s)"
              % (drift, time.perf_counter() - t2))


if __name__ == "__main__":
    _main()
