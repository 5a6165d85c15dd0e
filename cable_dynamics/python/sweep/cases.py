"""The cases a sweep asks for: the product of its axes (the last axis varying fastest), each repeated with
`samples.count` seeded random draws when the file has samples. A case is known by its overrides, the
`key=value` strings cable_sim's --set takes, so a rerun recognises the cases it already has."""
import itertools
import math

import numpy as np


def flow(value):
    """`value` in YAML flow form, as --set reads it: 0.5, 10, true, rk4, [0.5, 0, 0]. Floats are written
    with repr (the shortest text that reads back as the same double), so a case's identity is exact."""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, (list, tuple)):
        return "[" + ", ".join(flow(v) for v in value) + "]"
    if isinstance(value, float):
        if not math.isfinite(value):
            raise ValueError(f"{value!r}: not a finite number")
        return repr(value)
    return str(value)


class Case:
    """One case: its number in the sweep (`index`), the values it sets (key -> value, the sweep's keys in
    order) and their overrides ("key=value")."""

    def __init__(self, index, values):
        self.index = index
        self.values = values
        self.overrides = [f"{key}={flow(value)}" for key, value in values.items()]

    @property
    def identity(self):
        return tuple(self.overrides)


def _draws(samples):
    """`samples.count` draws of the sampled keys from one generator seeded with `samples.seed`: the same
    file gives the same draws on every machine (numpy's PCG64)."""
    rng = np.random.default_rng(samples["seed"])
    draws = []
    for _ in range(samples["count"]):
        draw = {}
        for key, (kind, a, b) in samples["keys"].items():
            draw[key] = float(rng.uniform(a, b) if kind == "uniform" else rng.normal(a, b))
        draws.append(draw)
    return draws


def make_cases(sweep):
    """The sweep's cases, numbered from 0 in the order above."""
    grid = [dict(zip(sweep.axes, combo)) for combo in itertools.product(*sweep.axes.values())]
    draws = _draws(sweep.samples) if sweep.samples else [{}]
    cases = []
    for point in grid:
        for draw in draws:
            cases.append(Case(len(cases), {**point, **draw}))
    return cases
