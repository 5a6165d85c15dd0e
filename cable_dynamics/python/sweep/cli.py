"""The command `cable_sweep SWEEP.yaml --output DIR [--workers N | --scheduler tcp://HOST:PORT] [--keep]`.

Exit statuses: 0 every case has its row (whatever its status), 1 some case was lost (a case that killed
its workers; a rerun tries it again) or the sweep was interrupted, 2 a bad option, sweep file or
results file (before any case runs), 3 the scheduler cannot be reached (before any case runs), 4 an
output cannot be written."""
import argparse
import os
import sys
import time

from .cases import make_cases
from .cluster import ClusterError, connect, run_cases
from .picture import draw_summary
from .progress import Progress
from .results import ResultsError, ResultsTable, read_rows
from .sweep_file import SweepFileError, load_sweep


def _parser():
    p = argparse.ArgumentParser(prog="cable_sweep", description=(
        "Runs every case of a sweep file (a cable_dynamics config, a duration, axes of config values, seeded "
        "random draws) on Dask and writes one row a case to DIR/results.csv and a heat map to "
        "DIR/summary.png. A rerun into the same DIR runs only the cases it does not have."))
    p.add_argument("sweep", metavar="SWEEP.yaml", help="the sweep file (docs/CLI.md, cable_sweep)")
    p.add_argument("--output", required=True, metavar="DIR", help="where results.csv and summary.png go")
    where = p.add_mutually_exclusive_group()
    where.add_argument("--workers", type=int, metavar="N", help="a local cluster of N worker processes "
                       "(default: one per core)")
    where.add_argument("--scheduler", metavar="tcp://HOST:PORT", help="a running Dask scheduler instead")
    p.add_argument("--keep", action="store_true", help="also write each case's time series (cable_sim's CSV) "
                   "under DIR/cases/")
    return p


def _workers(count):
    return f"{count} worker" + ("" if count == 1 else "s")


def _say(text):
    print(f"cable_sweep: {text}", file=sys.stderr, flush=True)


def main(argv=None):
    args = _parser().parse_args(argv)
    if args.workers is not None and args.workers < 1:
        _say(f"--workers {args.workers}: expected at least 1")
        return 2
    try:
        sweep = load_sweep(args.sweep)
        cases = make_cases(sweep)
        os.makedirs(args.output, exist_ok=True)
        table = ResultsTable(os.path.join(args.output, "results.csv"), sweep.keys())
        done = table.done()
    except (SweepFileError, ResultsError) as e:
        _say(str(e))
        return 2
    except OSError as e:
        _say(f"{args.output}: {e.strerror}")
        return 4
    todo = [c for c in cases if c.identity not in done]
    keep_dir = os.path.abspath(os.path.join(args.output, "cases")) if args.keep else None
    _say(f"{len(cases)} cases, {len(cases) - len(todo)} already in {table.path}, {len(todo)} to run")
    status = 0
    if todo:
        status = _run(args, sweep, todo, table, keep_dir)
        if status == 3 or not os.path.exists(table.path):  # no case ran: no table, no picture
            return status
    try:
        draw_summary(read_rows(table.path), sweep, os.path.join(args.output, "summary.png"))
        _say(f"wrote {table.path} and {os.path.join(args.output, 'summary.png')}")
    except OSError as e:
        _say(f"cannot write the picture: {e}")
        return status or 4
    return status


def _run(args, sweep, todo, table, keep_dir):
    try:
        client, cluster = connect(args.workers, args.scheduler)
    except ClusterError as e:
        _say(str(e))
        return 3
    try:
        if keep_dir:
            os.makedirs(keep_dir, exist_ok=True)
        table.open()
        workers = len(client.scheduler_info()["workers"])
        _say(f"running {len(todo)} cases on {_workers(workers)} ({args.scheduler or 'a local cluster'})")
        if workers == 0:
            _say("the scheduler has no worker yet: the cases wait for one (dask-worker " + args.scheduler + ")")
        progress = Progress(len(todo))
        lost, unwritten = 0, 0
        for case, row in run_cases(client, sweep, todo, keep_dir):
            if isinstance(row, Exception):  # no row: the case is run again by the next rerun
                progress.case_done(ok=False)
                _say(f"case {case.index} ({' '.join(case.overrides)}) is lost: {type(row).__name__}: {row}")
                unwritten += isinstance(row, OSError)  # its --keep CSV could not be written
                lost += 1
                continue
            table.append(case, row)
            progress.case_done(ok=row["status"] == "ok")
        progress.finish()
        table.close()
        took = time.monotonic() - progress.start
        _say(f"ran {len(todo)} cases in {took:.2f} s ({len(todo) / took:.3g} cases/s) on {_workers(workers)}")
        if lost:
            _say(f"{lost} cases lost (not in the table): a rerun runs them again")
            return 4 if unwritten else 1
        return 0
    except ResultsError as e:
        _say(str(e))
        return 4
    except OSError as e:  # DIR/cases cannot be made
        _say(f"cannot write {e.filename}: {e.strerror}")
        return 4
    except KeyboardInterrupt:
        _say("interrupted: the finished cases are in the table; a rerun runs the others")
        return 1
    finally:
        client.close()
        if cluster is not None:
            cluster.close()
