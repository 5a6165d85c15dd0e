"""Issue 26: the ROV body simulated here (load.mode body) against the same ROV written apart and coupled to the
cable at every 1 ms step (a lockstep run through the Python bindings: scripts/simple_rov.py's RovBody, a
6-DOF body in Fossen's form integrated by its own semi-implicit Euler step, on the tip of an attached load
with its stiff coupling). Both ROVs keep station in a 0.3 m/s current, and move it with
the same PID (simple_rov's, fed from each run's own pose every 1 ms) at three masses. Over the last 10 s of
30 s the tether force on the ROV and the ROV's position agree: the body's equations, its coupling at the
tip and its thrust input against an independent implementation.

Both start at rest in the static equilibrium of tether and ROV in the current (the body mode's statics; the
lockstep's tip held at the same point), and at 5 s the station moves 1 m upstream and 1 m up. Figures
(printed): the largest relative difference of the force and of the position over the window."""
import os
import sys

import numpy as np
import pytest

HERE = os.path.dirname(os.path.realpath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "scripts"))
from simple_rov import BLUEROV2, RovBody, quat_to_matrix, scaled  # noqa: E402

import cable_dynamics  # noqa: E402

RHO, G = 1025.0, 9.81
CURRENT = [0.3, 0.0, 0.0]
# demo_rov.yaml's tether (50 m, 25 links) without its 10 kg termination: the ROV is the only load.
CABLE = {"links": 25, "length": 50.0, "diameter": 0.025, "mass_per_length": 0.6}
FLUID = {"density": RHO, "current": CURRENT}
DURATION, WINDOW, DT = 30.0, 10.0, 0.001
MOVE_AT, MOVE = 5.0, np.array([-1.0, 0.0, 1.0])  # at 5 s the station moves 1 m upstream and 1 m up


def paper_to_world(v):
    return np.array([v[0], -v[1], -v[2]])


def body_load(params):
    return {"mode": "body", "mass": params["mass"], "volume": params["buoyancy"] / (RHO * G),
            "body": {"inertia": params["inertia"], "added_mass": params["added_mass"],
                     "linear_damping": params["linear_damping"], "quadratic_damping": params["quadratic_damping"],
                     "center_of_gravity": params["cog"], "center_of_buoyancy": params["cob"]}}


def body_mode(params):
    """The ROV as load.mode body, from the static equilibrium of tether and ROV in the current (the ROV level,
    its submerged weight and drag at the tip), keeping station there: its thrust from simple_rov's PID fed from
    the simulated body's pose at every step (set_body_thrust). Returns the station, the times' force on the
    ROV (world) [N] and its position [m]."""
    sim = cable_dynamics.Simulator.from_dict({"cable": CABLE, "fluid": FLUID, "load": body_load(params),
                                              "initial": {"mode": "equilibrium"},
                                              "simulation": {"dt": DT, "integrator": "rk4"}})
    point = sim.body_pose()["position"]
    controller = RovBody(params, point, current=CURRENT)
    steps = int(round(DURATION / DT))
    forces, positions = np.zeros((steps, 3)), np.zeros((steps, 3))
    for i in range(steps):
        if i == int(round(MOVE_AT / DT)):
            controller.target = point + MOVE
        pose = sim.body_pose()
        controller.p, controller.q = pose["position"], pose["attitude"]
        controller.v = quat_to_matrix(pose["attitude"]).T @ pose["velocity"]
        controller.w = pose["angular_velocity"]
        force, torque = controller.thrust(DT)
        sim.set_body_thrust(force, torque)
        sim.step(1)
        forces[i], positions[i] = paper_to_world(sim.snapshot().load_force), sim.body_pose()["position"]
    return point, forces, positions


def lockstep(params, point):
    """The ROV written apart (simple_rov.RovBody) at the same station, its pose to the attached tip and the
    coupling's force back at every step, from the static equilibrium with the tip held there. The coupling is
    the default spring (20 kN/m) with a damper of 300 N s/m: near critical on the tip's own half link (the
    default 2000 N s/m puts c dt / m = 3 beyond RK4's reach at 1 ms on a tip without a termination)."""
    sim = cable_dynamics.Simulator.from_dict({"cable": CABLE, "fluid": FLUID,
                                              "load": {"mode": "attached", "coupling": {"stiffness": 2.0e4, "damping": 300.0}},
                                              "simulation": {"dt": DT}})
    sim.set_load_target(point)
    sim.reset_to_equilibrium()
    body = RovBody(params, point, current=CURRENT)
    steps = int(round(DURATION / DT))
    forces, positions = np.zeros((steps, 3)), np.zeros((steps, 3))
    for i in range(steps):
        if i == int(round(MOVE_AT / DT)):
            body.target = point + MOVE
        sim.set_load_target(body.p, body.velocity_world(), body.q)
        sim.step(1)
        force = -paper_to_world(sim.snapshot().coupling_force)
        body.step(DT, quat_to_matrix(body.q).T @ force, np.zeros(3))
        forces[i], positions[i] = force, body.p
    return forces, positions


@pytest.mark.parametrize("mass", [5.0, 11.5, 20.0])
def test_body_mode_matches_the_lockstep_rov(mass):
    params = scaled(BLUEROV2, mass)
    point, f_body, p_body = body_mode(params)
    f_lock, p_lock = lockstep(params, point)
    window = slice(int(round((DURATION - WINDOW) / DT)), None)
    scale = np.max(np.linalg.norm(f_lock[window], axis=1))
    force_gap = np.max(np.linalg.norm(f_body[window] - f_lock[window], axis=1)) / scale
    position_gap = np.max(np.linalg.norm(p_body[window] - p_lock[window], axis=1))
    print(f"{mass} kg: tether force {scale:.2f} N, body mode against lockstep: force {force_gap:.2e} of it, "
          f"position {position_gap:.2e} m")
    transient_gap = np.max(np.linalg.norm(p_body - p_lock, axis=1))
    print(f"   the largest position difference over the whole run (the move's transient): {transient_gap:.3f} m")
    # Measured: 5 kg 6.1e-3 of 1.57 N and 2.9 mm, 11.5 kg 1.2e-3 of 3.26 N and 1.1 mm, 20 kg 1.8e-3 of
    # 4.85 N and 0.8 mm; during the move's transient up to 0.10 m (5 kg) to 0.07 m (20 kg): simple_rov
    # integrates by semi-implicit Euler and leaves out the added mass's Coriolis term, and its tip is held
    # by a 20 kN/m spring, not a joint. Bounds: 3 % of the force, 1 cm (the criterion for the pose
    # interface), 0.3 m in the transient.
    assert force_gap < 0.03
    assert position_gap < 0.01
    assert transient_gap < 0.3
