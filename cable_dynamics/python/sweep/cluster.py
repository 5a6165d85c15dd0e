"""The Dask cluster the cases run on: a local one of N worker processes (one thread each: a case holds a
core while it steps), or a running one at a scheduler's address (`dask-scheduler`, `dask-worker`)."""
import logging
import os

from dask.distributed import Client, LocalCluster, as_completed

from .run_case import run_case

# How long to try to reach a scheduler before giving up [s]; with the imports, cable_sweep reports an
# unreachable one within 10 s of its start.
CONNECT_TIMEOUT = 5.0


class ClusterError(RuntimeError):
    """The scheduler cannot be reached (cable_sweep exits with status 3, before any case runs)."""


def connect(workers=None, scheduler=None):
    """A Dask client: on the cluster at `scheduler` (tcp://HOST:PORT), or on a new local cluster of
    `workers` processes (default: one per core). Returns (client, the local cluster or None)."""
    # Dask's own news (a purged stale directory of a killed worker, connections) stays out of the sweep's
    # output (cable_sweep reports a lost case itself); its errors still show.
    logging.getLogger("distributed").setLevel(logging.ERROR)
    if scheduler:
        try:
            return Client(scheduler, timeout=CONNECT_TIMEOUT), None
        except (OSError, TimeoutError, ValueError) as e:
            raise ClusterError(f"cannot reach the Dask scheduler at {scheduler} within {CONNECT_TIMEOUT:g} s ({e})")
    cluster = LocalCluster(n_workers=workers or os.cpu_count() or 1, threads_per_worker=1, processes=True,
                           dashboard_address=None, silence_logs=logging.ERROR)
    return Client(cluster), cluster


def run_cases(client, sweep, cases, keep_dir=None):
    """Submits every case; yields (case, row or the exception that lost it) as each finishes, in the order
    they finish. A worker that dies takes no case with it: the scheduler runs its cases again elsewhere
    (a case that kills `distributed.scheduler.allowed-failures` + 1 workers is lost: KilledWorker)."""
    futures = {}
    for case in cases:
        keep = os.path.join(keep_dir, f"case_{case.index:04d}.csv") if keep_dir else None
        future = client.submit(run_case, sweep.config, case.overrides, sweep.duration, sweep.sample, keep,
                               key=f"cable_sweep-case-{case.index}-{abs(hash(case.identity)):x}", pure=False,
                               priority=-case.index)
        futures[future] = case
    for future in as_completed(futures):
        case = futures.pop(future)
        try:
            yield case, future.result()
        except Exception as e:  # noqa: BLE001 (KilledWorker, a case's OSError: reported, the sweep goes on)
            yield case, e
        future.release()
