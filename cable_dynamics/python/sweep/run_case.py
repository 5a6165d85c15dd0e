"""One case, run in a Dask worker: the config with the case's overrides, run as cable_sim runs it
(Simulator.run: the same steps, samples and verdict, tools/sampled_run.h), reduced to its summary there.

The status, from what the simulator reports, as cable_sim's exit status says it:
  ok             the run finished and is reliable (cable_sim 0)
  refused        the config or an override is refused (cable_sim 2): ConfigError / ValueError naming the key
  no_equilibrium initial.mode: equilibrium and there is none (cable_sim 6)
  diverged       a step failed even in substeps, or an output was not finite (cable_sim 3)
  unreliable     the run finished but cable_sim exits 5 for it (retried steps, energy balance, seabed)
"""
import time

import cable_dynamics

from .summary import Summary

RUN_STATUS = {0: "ok", 3: "diverged", 5: "unreliable"}


def run_case(config, overrides, duration, sample, keep_csv=None):
    """Runs one case; returns {"status", "reason", "wall_time" [s], and the summary's columns}. `keep_csv`:
    where to write cable_sim's CSV of the case (None: nothing is written). Raises OSError when that CSV
    cannot be written (a problem of the sweep's output, not of the case)."""
    start = time.monotonic()
    row = {"status": "ok", "reason": ""}
    try:
        sim = cable_dynamics.Simulator.from_file(config, list(overrides))
    except ValueError as e:  # ConfigError is a ValueError; so is the simulator's refusal of a dt, a rule
        row.update(status="refused", reason=str(e))
    except RuntimeError as e:  # the constructor's equilibrium start found none
        row.update(status="no_equilibrium", reason=str(e))
    summary = Summary(has_winch=False)
    if row["status"] == "ok":
        summary.has_winch = sim.has_winch
        try:
            outcome = sim.run(duration, sample, on_sample=summary.add, csv=keep_csv or "")
        except RuntimeError as e:  # the only error run() raises: the CSV cannot be opened
            raise OSError(str(e)) from e
        if outcome["status"] == 4:
            raise OSError(outcome["message"])
        row.update(status=RUN_STATUS[outcome["status"]], reason=outcome["message"])
    row.update(summary.values())
    row["wall_time"] = time.monotonic() - start
    return row
