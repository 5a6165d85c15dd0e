#!/usr/bin/env python3
"""cable_sweep's throughput on 1 and on 2 local workers, side by side (issue 25: two workers should give
at least 1.8 times one worker's throughput on a 24-case sweep).

Usage (after a build, in the devel space: `source scripts/env.bash`):
    python3 bench/sweep/throughput.py [--repeats 5] [--duration 120] [--links 25]

Each repeat runs the same 24-case sweep (the default umbilical, 24 load masses) once with --workers 1
and once with --workers 2, in alternating order, each into a fresh directory, and times the whole
command (its start-up, a local cluster's included), and reads the time the cases themselves took from
its last line ("ran 24 cases in X s", from the first submission to the last row). Throughput = 24
cases / time. It prints every run, then the ratio (2 workers / 1 worker) of both per repeat, their
medians and ranges. A bench, not a test: the machine is shared, so the spread is part of the result.

Beside it, in each repeat, the machine's own ceiling without Dask: 4 of the same cases run by
Simulator.run in one process after the other, against 2 processes (multiprocessing) running 2 each at
once. Its ratio is what two cores give two independent runs of this simulator here (memory bandwidth,
the host's sharing of the virtual cores, other sessions), the most a sweep on 2 workers can reach.
"""
import argparse
import os
import re
import statistics
import subprocess
import sys
import tempfile
import time

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SWEEP_BIN = os.path.join(REPO, "scripts", "cable_sweep")
CASES = 24


def sweep_file(directory, duration, links):
    masses = ", ".join(f"{5.0 + 0.5 * i:.1f}" for i in range(CASES))
    path = os.path.join(directory, "bench_sweep.yaml")
    with open(path, "w") as f:
        f.write(f"config: {os.path.join(REPO, 'config', 'default.yaml')}\nduration: {duration}\n"
                f"axes:\n  cable.links: [{links}]\n  load.mass: [{masses}]\n")
    return path


def timed_sweep(sweep, workers, directory):
    out = tempfile.mkdtemp(prefix=f"w{workers}_", dir=directory)
    start = time.monotonic()
    done = subprocess.run([sys.executable, SWEEP_BIN, sweep, "--output", out, "--workers", str(workers)],
                          capture_output=True, text=True)
    wall = time.monotonic() - start
    if done.returncode != 0:
        sys.exit(f"cable_sweep failed ({done.returncode}):\n{done.stderr}")
    cases = float(re.search(r"ran \d+ cases in ([0-9.]+) s", done.stderr).group(1))
    return wall, cases


def _ceiling_case(args):
    import cable_dynamics
    links, duration, mass = args
    sim = cable_dynamics.Simulator.from_file(os.path.join(REPO, "config", "default.yaml"),
                                             [f"cable.links={links}", f"load.mass={mass}"])
    return sim.run(duration)["status"]


def ceiling(links, duration):
    """Wall time of 4 cases one after the other in one process, and of 2 processes doing 2 each [s]."""
    import multiprocessing
    work = [(links, duration, 5.0 + i) for i in range(4)]
    start = time.monotonic()
    for w in work:
        _ceiling_case(w)
    serial = time.monotonic() - start
    with multiprocessing.get_context("spawn").Pool(2) as pool:
        pool.map(_ceiling_case, work[:2])  # start-up and imports outside the timing
        start = time.monotonic()
        pool.map(_ceiling_case, work, chunksize=1)
        parallel = time.monotonic() - start
    return serial, parallel


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--repeats", type=int, default=5)
    p.add_argument("--duration", type=float, default=120.0, help="simulated seconds per case")
    p.add_argument("--links", type=int, default=25)
    args = p.parse_args()
    with tempfile.TemporaryDirectory() as directory:
        sweep = sweep_file(directory, args.duration, args.links)
        ratios = {"whole command": [], "cases only": [], "ceiling (no Dask)": []}
        for r in range(args.repeats):
            order = (1, 2) if r % 2 == 0 else (2, 1)
            times = {w: timed_sweep(sweep, w, directory) for w in order}
            for i, what in enumerate(list(ratios)[:2]):
                ratios[what].append(times[1][i] / times[2][i])  # throughput(2) / throughput(1)
            serial, parallel = ceiling(args.links, args.duration)
            ratios["ceiling (no Dask)"].append(serial / parallel)
            print(f"repeat {r + 1}: 1 worker {times[1][0]:.2f} s (cases {times[1][1]:.2f} s), 2 workers "
                  f"{times[2][0]:.2f} s (cases {times[2][1]:.2f} s); ratio {ratios['whole command'][-1]:.3f} "
                  f"(cases only {ratios['cases only'][-1]:.3f}); ceiling: 4 cases {serial:.2f} s in 1 process, "
                  f"{parallel:.2f} s in 2, ratio {ratios['ceiling (no Dask)'][-1]:.3f}", flush=True)
    print(f"{CASES} cases of {args.links} links, {args.duration:g} s simulated each, {os.cpu_count()} cores:")
    for what, values in ratios.items():
        print(f"  throughput 2 workers / 1 worker, {what}: median {statistics.median(values):.3f}, "
              f"range {min(values):.3f} to {max(values):.3f} over {len(values)} repeats")


if __name__ == "__main__":
    main()
