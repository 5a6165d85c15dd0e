"""cable_sweep's library: design sweeps of cable_dynamics configs on Dask (docs/CLI.md, "cable_sweep").

One module a job: sweep_file (the sweep file, read and checked), cases (the cases it asks for), run_case
(one case in a worker, reduced to its summary there), summary (the reduction), results (DIR/results.csv,
resume), cluster (the Dask cluster and the cases on it), progress (the terminal's progress line), picture
(DIR/summary.png), cli (the command). The entry script is scripts/cable_sweep.
"""
