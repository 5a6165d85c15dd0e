#!/usr/bin/env python3
"""A sweep over the current's speed: the top tension of a 50 m umbilical holding a 10 kg load at rest."""
import cable_dynamics

config = {  # the keys of a config file (docs/CONFIG.md), checked the same way
    "cable": {"links": 25, "length": 50.0, "diameter": 0.025, "mass_per_length": 0.6},
    "load": {"mass": 10.0, "volume": 0.005},
    "fluid": {"density": 1025.0, "drag_normal": 1.2, "drag_tangential": 0.01},
}
sim = cable_dynamics.Simulator.from_dict(config)
print("current [m/s]  top tension [N]  tip offset [m]  tip depth [m]")
for speed in [0.0, 0.25, 0.5, 1.0, 1.5, 2.0]:
    sim.set_current([speed, 0.0, 0.0])  # world axes, z up
    sim.reset_to_equilibrium()          # at rest in the static equilibrium for this current
    s = sim.snapshot()
    tip = s.link_ends[-1]               # paper frame: base at the origin, z down
    print(f"{speed:13.2f}  {s.line_pull:15.4f}  {tip[0]:14.4f}  {tip[2]:13.4f}")
