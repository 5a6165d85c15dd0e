"""cable_sweep (issue 25 item 1): a sweep's table against direct cable_sim runs of its cases.

What is checked, and against what:
* the same sweep on a local cluster of 2 workers and through a scheduler with two workers started as
  separate processes on 127.0.0.1 gives the same table, and every row equals a direct `cable_sim` run of
  the case: the status from cable_sim's exit status, the reason from its message, the summary computed
  here from cable_sim's CSV with numpy (to 1e-9 relative: the CSV's 10 significant digits round by at
  most 5e-10 relative), and `--keep`'s time series is cable_sim's CSV byte for byte;
* a case with `cable.links: 0` is a `refused` row whose reason names the key (cable_sim exits 2 for it);
  an equilibrium start without an equilibrium is a `no_equilibrium` row (cable_sim exits 6), a run whose
  step fails a `diverged` row with the summary of its samples (cable_sim exits 3, its CSV has them);
  a run cable_sim judges unreliable (exit 5: the implicit step putting energy into a kinked release, the
  case of test_unreliable_runs.py) is an `unreliable` row;
* a rerun into the same directory runs no case again; a worker killed (SIGKILL) mid-sweep loses no case;
* bad sweep files (an unknown key, an empty axis, a value of the wrong type, a missing config file) exit 2
  naming the key before any case runs; an unreachable scheduler exits 3 within 10 s;
* the seeded draws: the same seed gives the same cases, inside a uniform draw's bounds, and a normal
  draw's sample mean within 4 standard errors of its mean.

Environment: CABLE_SIM_BIN (the built cable_sim), CABLE_SWEEP_BIN (scripts/cable_sweep), run in the devel
space (cable_dynamics importable, dask-scheduler and dask-worker on PATH); the tests fail without them.
"""
import csv
import os
import signal
import socket
import subprocess
import sys
import time

import numpy as np
import pytest
import yaml

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(HERE)
DEFAULT = os.path.join(REPO, "config", "default.yaml")
sys.path.insert(0, os.path.join(REPO, "cable_dynamics", "python"))
from sweep.cases import make_cases  # noqa: E402  (the library's own files, not the devel space's link)
from sweep.sweep_file import load_sweep  # noqa: E402

# cable_sim's exit status -> the sweep's status (docs/CLI.md).
STATUS = {0: "ok", 2: "refused", 3: "diverged", 5: "unreliable", 6: "no_equilibrium"}
# The CSV's 10 significant digits round a value by at most 5e-10 of it: 1e-9 is twice that bound.
RTOL = 1e-9
# The kinked release of test_unreliable_runs.py: at dt = 10 ms the implicit step puts energy in (exit 5).
KINKED = {"cable": {"links": 20, "length": 10.0, "diameter": 0.025, "mass_per_length": 0.6,
                    "stiffness": {"model": "bending", "bending_rigidity": 20.0, "torsional_rigidity": 20.0},
                    "damping": {"elevation": 0.0, "azimuth": 0.0, "torsion": 0.0}},
          "load": {"mass": 5.0, "volume": 0.0}, "fluid": {"density": 0.0, "current": [0, 0, 0]},
          "initial": {"mode": "angles", "elevation": [0.5] + [0.0] * 19},
          "simulation": {"integrator": "implicit", "dt": 0.01}}


def binary(name):
    path = os.environ.get(name)
    if not path:
        pytest.fail(f"set {name} (the pytest target in test/tests.cmake does)")
    return path


def sweep_cmd(sweep, out, *extra):
    return [sys.executable, binary("CABLE_SWEEP_BIN"), str(sweep), "--output", str(out), *extra]


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def write_sweep(path, text):
    path.write_text(text)
    return path


@pytest.fixture(scope="module")
def configs(tmp_path_factory):
    """The default umbilical (with cable.limits) and the kinked release (as files), in one directory."""
    d = tmp_path_factory.mktemp("configs")
    with open(DEFAULT) as f:
        default = yaml.safe_load(f)
    # Limits (docs/MODEL.md section 13), so that the summary's max_utilisation is not all 0.
    default["cable"]["limits"] = {"max_tension": 150.0, "min_bend_radius": 5.0}
    (d / "default.yaml").write_text(yaml.safe_dump(default))
    kinked = dict(default)
    for key, value in KINKED.items():
        kinked[key] = {**default.get(key, {}), **value} if isinstance(value, dict) else value
    kinked["base"] = {"motion": {}}
    (d / "kinked.yaml").write_text(yaml.safe_dump(kinked))
    return d


@pytest.fixture(scope="module")
def main_sweep(configs):
    # 8 cases: 2 load masses x 2 currents x 2 link counts, of which cable.links = 0 is refused.
    return write_sweep(configs / "main.yaml", """\
config: default.yaml
duration: 1.5
axes:
  load.mass: [5.0, 20.0]
  fluid.current: [[0.5, 0, 0], [1.5, 0, 0.2]]
  cable.links: [10, 0]
""")


@pytest.fixture(scope="module")
def scheduler_cluster():
    """dask-scheduler and two dask-worker processes (no nanny: a killed worker stays dead) on 127.0.0.1."""
    port = free_port()
    address = f"tcp://127.0.0.1:{port}"
    procs = [subprocess.Popen(["dask-scheduler", "--host", "127.0.0.1", "--port", str(port), "--no-dashboard"],
                              stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)]
    time.sleep(1.0)
    for _ in range(2):
        procs.append(subprocess.Popen(["dask-worker", address, "--nthreads", "1", "--no-nanny", "--no-dashboard",
                                       "--host", "127.0.0.1"],
                                      stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL))
    from dask.distributed import Client
    with Client(address, timeout=20) as client:
        client.wait_for_workers(2, timeout=30)
    yield address, procs
    for p in reversed(procs):
        p.terminate()
    for p in procs:
        try:
            p.wait(timeout=10)
        except subprocess.TimeoutExpired:
            p.kill()


def read(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


@pytest.fixture(scope="module")
def local_run(main_sweep, tmp_path_factory):
    out = tmp_path_factory.mktemp("local")
    done = subprocess.run(sweep_cmd(main_sweep, out, "--workers", "2", "--keep"), capture_output=True, text=True,
                          timeout=300)
    assert done.returncode == 0, done.stderr
    return out, done


@pytest.fixture(scope="module")
def scheduler_run(main_sweep, scheduler_cluster, tmp_path_factory):
    out = tmp_path_factory.mktemp("scheduler")
    done = subprocess.run(sweep_cmd(main_sweep, out, "--scheduler", scheduler_cluster[0]), capture_output=True,
                          text=True, timeout=300)
    assert done.returncode == 0, done.stderr
    return out, done


def cable_sim(config, overrides, duration, csv_path):
    cmd = [binary("CABLE_SIM_BIN"), "--config", str(config), "--duration", str(duration), "--output", str(csv_path)]
    for o in overrides:
        cmd += ["--set", o]
    return subprocess.run(cmd, capture_output=True, text=True, timeout=300)


def summary_from_csv(path):
    """The summary's columns from cable_sim's CSV (numpy on its columns; none of the sweep's code)."""
    data = np.genfromtxt(path, delimiter=",", names=True)
    names = data.dtype.names
    tension = np.column_stack([data[n] for n in names if n.startswith("tension")])
    peak = tension.max()
    first = int(np.flatnonzero(tension.max(axis=1) == peak)[0])
    touching = data["touchdown_arc_length"][data["touchdown_arc_length"] >= 0]
    load = np.sqrt(data["load_force_x"] ** 2 + data["load_force_y"] ** 2 + data["load_force_z"] ** 2)
    return {"max_top_tension": data["top_tension"].max(), "min_top_tension": data["top_tension"].min(),
            "max_tension": peak, "max_tension_link": int(np.argmax(tension[first])) + 1,
            "max_load_force": load.max(),
            "min_grounded_length": data["grounded_length"].min(), "max_grounded_length": data["grounded_length"].max(),
            "min_touchdown": touching.min() if touching.size else None,
            "max_touchdown": touching.max() if touching.size else None,
            "max_slack_links": int(data["slack_links"].max()) if "slack_links" in names else 0,
            "min_bend_radius": data["min_bend_radius"].min(), "max_utilisation": data["max_utilisation"].max()}


def overrides_of(row, keys):
    return [f"{k}={row[k]}" for k in keys]


def check_against_cable_sim(rows, keys, config, duration, tmp_path, kept=None):
    for row in rows:
        csv_path = tmp_path / f"direct_{row['case']}.csv"
        direct = cable_sim(config, overrides_of(row, keys), duration, csv_path)
        assert row["status"] == STATUS[direct.returncode], (row, direct.stderr)
        if row["status"] != "ok":
            # The reason is cable_sim's own message (it prints "cable_sim: <message>").
            assert row["reason"] and row["reason"] in direct.stderr, (row["reason"], direct.stderr)
        if row["status"] in ("refused", "no_equilibrium"):
            assert row["max_tension"] == "", row
            continue
        expected = summary_from_csv(csv_path)
        for column, value in expected.items():
            if value is None:
                assert row[column] == "", (column, row)
            elif isinstance(value, int):
                assert int(row[column]) == value, (column, row[column], value)
            else:
                assert float(row[column]) == pytest.approx(value, rel=RTOL, abs=0), (column, row[column], value)
        assert row["max_line_pull"] == ""  # no winch in these configs
        if kept is not None:
            assert (kept / f"case_{int(row['case']):04d}.csv").read_bytes() == csv_path.read_bytes()


KEYS = ["load.mass", "fluid.current", "cable.links"]


def test_local_cluster_equals_cable_sim(local_run, configs, tmp_path):
    out, done = local_run
    rows = read(out / "results.csv")
    assert [r["case"] for r in sorted(rows, key=lambda r: int(r["case"]))] == [str(i) for i in range(8)]
    assert list(rows[0])[:6] == ["case"] + KEYS + ["status", "reason"]
    assert list(rows[0])[-1] == "wall_time" and all(float(r["wall_time"]) > 0 for r in rows)
    assert sorted(r["status"] for r in rows) == ["ok"] * 4 + ["refused"] * 4
    check_against_cable_sim(rows, KEYS, configs / "default.yaml", 1.5, tmp_path, kept=out / "cases")
    assert (out / "summary.png").stat().st_size > 10000


def test_refused_case_names_the_key(local_run):
    refused = [r for r in read(local_run[0] / "results.csv") if r["cable.links"] == "0"]
    assert len(refused) == 4
    assert all(r["status"] == "refused" and "cable.links" in r["reason"] for r in refused), refused


def test_scheduler_and_workers_equal_local(local_run, scheduler_run):
    def table(out):
        rows = sorted(read(out / "results.csv"), key=lambda r: int(r["case"]))
        return [{k: v for k, v in r.items() if k != "wall_time"} for r in rows]
    assert table(scheduler_run[0]) == table(local_run[0])
    assert "on 2 workers" in scheduler_run[1].stderr


def test_rerun_runs_no_case_again(local_run, main_sweep):
    out = local_run[0]
    before = (out / "results.csv").read_bytes()
    again = subprocess.run(sweep_cmd(main_sweep, out, "--workers", "2"), capture_output=True, text=True, timeout=120)
    assert again.returncode == 0, again.stderr
    assert "8 already in" in again.stderr and "0 to run" in again.stderr, again.stderr
    assert (out / "results.csv").read_bytes() == before


def test_rerun_after_an_interruption_runs_only_the_missing_cases(local_run, main_sweep, tmp_path):
    # A results file that lost its last three rows (and half of a fourth, cut by the kill) gets them back.
    lines = (local_run[0] / "results.csv").read_text().splitlines(keepends=True)
    (tmp_path / "results.csv").write_text("".join(lines[:-4]) + lines[-4][:20])
    again = subprocess.run(sweep_cmd(main_sweep, tmp_path, "--workers", "2"), capture_output=True, text=True,
                           timeout=120)
    assert again.returncode == 0, again.stderr
    assert "4 already in" in again.stderr and "4 to run" in again.stderr, again.stderr
    rows = read(tmp_path / "results.csv")
    assert sorted(int(r["case"]) for r in rows) == list(range(8))


def test_unreliable_run_is_a_row(configs, tmp_path):
    # cable_sim exits 5 at dt = 10 ms (energy the step puts in) and 0 at 2.5 ms (test_unreliable_runs.py).
    sweep = write_sweep(configs / "kinked_sweep.yaml", "config: kinked.yaml\nduration: 10\n"
                        "axes:\n  simulation.dt: [0.01, 0.0025]\n")
    done = subprocess.run(sweep_cmd(sweep, tmp_path / "out", "--workers", "2"), capture_output=True, text=True,
                          timeout=300)
    assert done.returncode == 0, done.stderr
    rows = sorted(read(tmp_path / "out" / "results.csv"), key=lambda r: int(r["case"]))
    assert [r["status"] for r in rows] == ["unreliable", "ok"], rows
    assert "energy balance rose" in rows[0]["reason"]
    check_against_cable_sim(rows, ["simulation.dt"], configs / "kinked.yaml", 10, tmp_path)


def test_no_equilibrium_is_a_row(configs, tmp_path):
    # paper_seabed.yaml's anchor moved 40 m aside and 20 m down from a 20 m cable's tip: no equilibrium to
    # start from (cable_sim exits 6, test_presets.py); at its own anchor the start is solved and runs.
    with open(os.path.join(REPO, "config", "paper_seabed.yaml")) as f:
        (configs / "paper_seabed.yaml").write_text(f.read())
    sweep = write_sweep(configs / "equilibrium.yaml", "config: paper_seabed.yaml\nduration: 0.5\naxes:\n"
                        "  initial.mode: [equilibrium]\n  load.motion.offset: [[40.0, 0.0, 20.0], [0.0, 0.0, 0.0]]\n")
    done = subprocess.run(sweep_cmd(sweep, tmp_path / "out", "--workers", "2"), capture_output=True, text=True,
                          timeout=300)
    assert done.returncode == 0, done.stderr
    rows = sorted(read(tmp_path / "out" / "results.csv"), key=lambda r: int(r["case"]))
    assert [r["status"] for r in rows] == ["no_equilibrium", "ok"], rows
    assert "m long" in rows[0]["reason"], rows[0]
    check_against_cable_sim(rows, ["initial.mode", "load.motion.offset"], configs / "paper_seabed.yaml", 0.5,
                            tmp_path)


def test_diverged_and_seabed_cases_equal_cable_sim(configs, tmp_path):
    # tms_tether.yaml (a tether on the bottom, an equilibrium start): without a current its equilibrium
    # start stalls (the statics' seabed continuation, 2026-12-03: the simulator's verdict, cable_sim's too);
    # in a 0.5 m/s current along x it runs, its slack on the bottom (a touchdown in the summary). That run
    # diverged at 0.068 s until the twist's 4 pi holonomy jump was fixed (joint_geometry.h), and this test
    # used it as its diverged case. The next one, MoorDyn's jumper at an implicit step of 50 ms on a stiff
    # spring anchor (a runaway angular velocity at 0.15 s even in 64 substeps), now runs to the end: the
    # implicit step retries in pieces a step whose balance rose (issue 27), and that run is reported
    # unreliable. The diverged case is now rov_tether.yaml at 25 links in air, its ROV started 60 m above
    # the hanging tip (a 5000 N/m coupling yanking a 2 kg tip with 300 kN: an input nothing could follow),
    # at RK4's stability limit: it diverges at 0.038 s even in 64 substeps; the same tether with its ROV at
    # the tip runs. The row of a failed run carries the summary of the samples it has, as cable_sim's CSV
    # does.
    with open(os.path.join(REPO, "config", "tms_tether.yaml")) as f:
        (configs / "tms_tether.yaml").write_text(f.read())
    sweep = write_sweep(configs / "tms.yaml", "config: tms_tether.yaml\nduration: 0.3\naxes:\n"
                        "  fluid.current: [[0.0, 0, 0], [0.5, 0, 0]]\n")
    done = subprocess.run(sweep_cmd(sweep, tmp_path / "out", "--workers", "2"), capture_output=True, text=True,
                          timeout=300)
    assert done.returncode == 0, done.stderr
    rows = sorted(read(tmp_path / "out" / "results.csv"), key=lambda r: int(r["case"]))
    assert [r["status"] for r in rows] == ["no_equilibrium", "ok"], rows
    assert rows[1]["max_touchdown"] != "", rows[1]
    check_against_cable_sim(rows, ["fluid.current"], configs / "tms_tether.yaml", 0.3, tmp_path)

    with open(os.path.join(REPO, "config", "rov_tether.yaml")) as f:
        (configs / "rov_tether.yaml").write_text(f.read())
    sweep = write_sweep(configs / "yank_sweep.yaml", "config: rov_tether.yaml\nduration: 0.3\naxes:\n"
                        "  fluid.density: [0.0]\n  cable.links: [25]\n  initial.mode: [angles]\n"
                        "  simulation.integrator: [rk4]\n  simulation.dt: [0.0096]\n"
                        "  load.motion.offset: [[0.0, 0.0, 0.0], [0.0, 0.0, 60.0]]\n")
    done = subprocess.run(sweep_cmd(sweep, tmp_path / "out_yank", "--workers", "2"), capture_output=True,
                          text=True, timeout=300)
    assert done.returncode == 0, done.stderr
    rows = sorted(read(tmp_path / "out_yank" / "results.csv"), key=lambda r: int(r["case"]))
    assert [r["status"] for r in rows] == ["ok", "diverged"], rows
    assert "diverged even in 64 substeps" in rows[1]["reason"] and rows[1]["max_top_tension"] != "", rows[1]
    check_against_cable_sim(rows, ["fluid.density", "cable.links", "initial.mode", "simulation.integrator", "simulation.dt",
                                   "load.motion.offset"], configs / "rov_tether.yaml", 0.3, tmp_path)


def test_killed_worker_loses_no_case(configs, scheduler_cluster, tmp_path):
    # 12 cases of about 0.5 s each on the two workers. Once the first row is in, the worker running a case
    # is found through the scheduler (its pid and the case it is processing) and killed with SIGKILL: that
    # case must come back from the other worker, and no case may be missing or twice.
    from dask.distributed import Client
    address, procs = scheduler_cluster
    sweep = write_sweep(configs / "long.yaml", "config: default.yaml\nduration: 8\naxes:\n"
                        "  cable.links: [60]\n  load.mass: [1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0, 9.0, 10.0, 11.0, 12.0]\n")
    out = tmp_path / "out"
    sweep_proc = subprocess.Popen(sweep_cmd(sweep, out, "--scheduler", address), stdout=subprocess.PIPE,
                                  stderr=subprocess.PIPE, text=True)
    results = out / "results.csv"
    with Client(address, timeout=20) as client:
        deadline = time.monotonic() + 120
        while time.monotonic() < deadline and not (results.exists() and len(results.read_text().splitlines()) >= 2):
            time.sleep(0.02)
        busy = {w: keys for w, keys in client.processing().items() if keys}
        assert busy, "no worker is running a case: make the cases longer"
        worker, keys = next(iter(busy.items()))
        pid = client.run(os.getpid, workers=[worker])[worker]
        os.kill(pid, signal.SIGKILL)
    killed_case = int(str(keys[0]).split("-")[2])  # keys are cable_sweep-case-<index>-<hash>
    stdout, stderr = sweep_proc.communicate(timeout=300)
    assert sweep_proc.returncode == 0, stderr
    rows = read(results)
    assert sorted(int(r["case"]) for r in rows) == list(range(12))
    assert any(int(r["case"]) == killed_case for r in rows)
    assert all(r["status"] == "ok" for r in rows), rows


@pytest.mark.parametrize("text,names", [
    ("config: default.yaml\nduration: 1\naxis:\n  cable.links: [10]\n", "axis: unknown key"),
    ("config: default.yaml\nduration: 1\naxes:\n  cable.links: []\n", "axes.cable.links is empty"),
    ("config: default.yaml\nduration: ten\naxes:\n  cable.links: [10]\n", "duration = 'ten'"),
    ("config: default.yaml\nduration: 1\naxes:\n  cable.links: 10\n", "axes.cable.links = 10"),
    ("config: default.yaml\nduration: 1\naxes:\n  cable.links: [{a: 1}]\n", "axes.cable.links: value"),
    ("config: nowhere.yaml\nduration: 1\naxes:\n  cable.links: [10]\n", "config = 'nowhere.yaml': no such file"),
    ("config: default.yaml\nduration: 1\nsamples: {seed: 1, count: 2, keys: {load.mass: {uniform: [5, 1]}}}\n",
     "samples.keys.load.mass.uniform"),
])
def test_bad_sweep_file_exits_2_before_any_case(configs, tmp_path, text, names):
    sweep = configs / "bad.yaml"
    sweep.write_text(text)
    done = subprocess.run(sweep_cmd(sweep, tmp_path / "out"), capture_output=True, text=True, timeout=60)
    assert done.returncode == 2, done.stderr
    assert names in done.stderr, done.stderr
    assert not (tmp_path / "out" / "results.csv").exists()


def test_unreachable_scheduler_exits_within_10_s(main_sweep, tmp_path):
    port = free_port()  # nothing listens there
    start = time.monotonic()
    done = subprocess.run(sweep_cmd(main_sweep, tmp_path / "out", "--scheduler", f"tcp://127.0.0.1:{port}"),
                          capture_output=True, text=True, timeout=60)
    took = time.monotonic() - start
    assert done.returncode == 3, done.stderr
    assert "cannot reach the Dask scheduler" in done.stderr, done.stderr
    assert took < 10.0, took
    assert not (tmp_path / "out" / "results.csv").exists() and not (tmp_path / "out" / "summary.png").exists()


def test_seeded_draws(configs):
    sweep = write_sweep(configs / "draws.yaml", """\
config: default.yaml
duration: 1
axes:
  cable.links: [10, 20]
samples:
  seed: 7
  count: 2000
  keys:
    load.mass: {uniform: [5.0, 20.0]}
    fluid.drag_normal: {normal: [1.2, 0.1]}
""")
    cases = make_cases(load_sweep(sweep))
    assert len(cases) == 4000
    assert [c.overrides for c in cases] == [c.overrides for c in make_cases(load_sweep(sweep))]
    mass = np.array([c.values["load.mass"] for c in cases])
    drag = np.array([c.values["fluid.drag_normal"] for c in cases[:2000]])
    assert mass.min() >= 5.0 and mass.max() < 20.0
    # 4 standard errors of the mean of 2000 draws of deviation 0.1: 0.0089.
    assert abs(drag.mean() - 1.2) < 4 * 0.1 / np.sqrt(2000)
    # Each axes case has the same draws; the overrides read back as the same double (repr).
    assert [c.values["load.mass"] for c in cases[:2000]] == [c.values["load.mass"] for c in cases[2000:]]
    assert all(float(c.overrides[1].split("=")[1]) == c.values["load.mass"] for c in cases[:50])
