#!/usr/bin/env python3
"""Plot one cable-simulator run (CSV) as a single PNG.

Usage:
    /usr/bin/python3 scripts/plot_run.py run.csv run.png [--title TEXT] [--snapshots N]

The CSV has one header line naming every column, then one row per output time. Columns used:
  time [s]; endK_x, endK_y, endK_z for K = 1..n (far end of link K, paper frame: base at the origin,
  x, y horizontal, z DOWN) [m]; top_tension [N]; kinetic_energy, potential_energy, elastic_energy,
  dissipated_energy, total_energy [J]. Other columns (joint angles and rates, per-link tensions,
  load force) are ignored. n is the number of endK_x columns.

The figure (about 1400x800 px):
  left         cable shape snapshots, evenly spaced in time and coloured by time, side view in the
               vertical plane through the load's mean horizontal displacement (x if there is none),
               depth increasing downward, equal aspect; base and load marked;
  right top    top tension versus time;
  right bottom energies versus time (series that are identically zero are left out).

Needs numpy and matplotlib (Debian: python3-numpy, python3-matplotlib); renders headless (Agg).
"""

import argparse
import os
import re
import sys

import numpy as np
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib import cm, colors  # noqa: E402

ENERGY_SERIES = [
    # column, legend label, style
    ("kinetic_energy", "kinetic", dict(color="tab:orange")),
    ("potential_energy", "potential", dict(color="tab:blue")),
    ("elastic_energy", "elastic", dict(color="tab:green")),
    ("dissipated_energy", "dissipated", dict(color="tab:red")),
    ("total_energy", "total", dict(color="black", linewidth=2.0)),
]

END_COLUMN = re.compile(r"^end(\d+)_x$")


def fail(message):
    sys.stderr.write("plot_run.py: error: %s\n" % message)
    sys.exit(2)


def read_csv(path):
    """Returns (dict column name -> 1-D float array, list of link indices 1..n)."""
    try:
        with open(path, "r") as f:
            header = f.readline()
    except OSError as e:
        fail("cannot read %s: %s" % (path, e))
    names = [h.strip().strip('"') for h in header.strip().split(",")]
    if not names or names == [""]:
        fail("%s: empty header" % path)
    index = {}
    for i, name in enumerate(names):
        if name and name not in index:
            index[name] = i

    links = sorted(int(m.group(1)) for m in (END_COLUMN.match(n) for n in names) if m)
    if not links:
        fail("%s: no endK_x columns, cannot tell the number of links" % path)
    n = len(links)
    if links != list(range(1, n + 1)):
        fail("%s: endK_x columns are not numbered 1..n: %s" % (path, links))

    wanted = ["time"]
    for k in links:
        wanted += ["end%d_x" % k, "end%d_y" % k, "end%d_z" % k]
    missing = [w for w in wanted if w not in index]
    if missing:
        fail("%s: missing column(s) %s" % (path, ", ".join(missing)))
    wanted += [c for c in ["top_tension", "base_x", "base_y", "base_z"] + [e[0] for e in ENERGY_SERIES] if c in index]

    usecols = [index[w] for w in wanted]
    try:
        data = np.loadtxt(path, delimiter=",", skiprows=1, usecols=usecols, ndmin=2, dtype=float)
    except ValueError as e:
        fail("%s: cannot parse numbers: %s" % (path, e))
    if data.shape[0] == 0:
        fail("%s: no data rows" % path)
    keep = np.isfinite(data[:, 0])
    data = data[keep]
    if data.shape[0] == 0:
        fail("%s: no row with a finite time" % path)
    return {w: data[:, j] for j, w in enumerate(wanted)}, links


def horizontal_axis(load_x, load_y):
    """Unit horizontal direction (ux, uy) for the side view, and a label for it.

    The direction of the load's mean horizontal displacement; if that mean is negligible (e.g. a
    symmetric swing about the vertical) the direction of largest RMS horizontal excursion; x if
    the load never leaves the vertical."""
    ok = np.isfinite(load_x) & np.isfinite(load_y)
    x, y = load_x[ok], load_y[ok]
    if x.size == 0:
        return 1.0, 0.0, "x [m]"
    mean = np.array([x.mean(), y.mean()])
    rms = np.sqrt(np.mean(x * x + y * y))
    tiny = 1e-9
    if np.hypot(*mean) > max(tiny, 0.1 * rms):
        u = mean / np.hypot(*mean)
    elif rms > tiny:
        moment = np.array([[np.mean(x * x), np.mean(x * y)], [np.mean(x * y), np.mean(y * y)]])
        w, v = np.linalg.eigh(moment)
        u = v[:, np.argmax(w)]
        if u[np.argmax(np.abs(u))] < 0:  # point along +x or +y rather than -x or -y
            u = -u
    else:
        u = np.array([1.0, 0.0])
    ux, uy = float(u[0]), float(u[1])
    snap = np.sin(np.radians(0.5))  # within half a degree of an axis: use the axis itself
    if abs(uy) < snap:
        ux, uy = (1.0 if ux > 0 else -1.0), 0.0
    elif abs(ux) < snap:
        ux, uy = 0.0, (1.0 if uy > 0 else -1.0)
    if uy == 0.0:
        label = "x [m]" if ux > 0 else "\u2212x [m]"
    elif ux == 0.0:
        label = "y [m]" if uy > 0 else "\u2212y [m]"
    else:
        angle = np.degrees(np.arctan2(uy, ux))
        label = "horizontal, azimuth %.0f\u00b0 from +x toward +y [m]" % angle
    return ux, uy, label


def snapshot_rows(t, count):
    """Row indices of `count` snapshots evenly spaced in time, first and last row included."""
    if count == 1:
        return np.array([len(t) - 1])
    targets = np.linspace(t[0], t[-1], count)
    order = np.argsort(t, kind="stable")
    ts = t[order]
    pos = np.clip(np.searchsorted(ts, targets), 1, len(ts) - 1) if len(ts) > 1 else np.zeros(count, int)
    if len(ts) > 1:
        left = pos - 1
        nearer_left = np.abs(targets - ts[left]) <= np.abs(ts[pos] - targets)
        pos = np.where(nearer_left, left, pos)
    rows = order[pos]
    _, first = np.unique(rows, return_index=True)
    return rows[np.sort(first)]


def plot_shape(ax, fig, cols, links, count):
    t = cols["time"]
    n = links[-1]
    ex = np.column_stack([cols["end%d_x" % k] for k in links])
    ey = np.column_stack([cols["end%d_y" % k] for k in links])
    ez = np.column_stack([cols["end%d_z" % k] for k in links])
    ux, uy, hlabel = horizontal_axis(ex[:, -1], ey[:, -1])

    t0, t1 = float(t.min()), float(t.max())
    if t1 <= t0:
        t1 = t0 + 1.0
    norm = colors.Normalize(vmin=t0, vmax=t1)
    cmap = matplotlib.colormaps["viridis"] if hasattr(matplotlib, "colormaps") else cm.get_cmap("viridis")

    rows = snapshot_rows(t, count)
    # Largest distance of any drawn point from the viewing plane (hidden by the projection).
    off_plane = np.nanmax(np.abs(ex[rows] * uy - ey[rows] * ux)) if len(rows) else 0.0
    # The base's position (it may move: a heaving vessel); older CSVs without base_x.. have it at the origin.
    zeros = np.zeros(len(t))
    bx, by, bz = (cols.get("base_x", zeros), cols.get("base_y", zeros), cols.get("base_z", zeros))
    for r in rows:
        s = np.concatenate([[bx[r] * ux + by[r] * uy], ex[r] * ux + ey[r] * uy])
        z = np.concatenate([[bz[r]], ez[r]])
        c = cmap(norm(t[r]))
        ax.plot(s, z, "-", color=c, linewidth=1.8, marker="o", markersize=3.0, zorder=2)
        ax.plot(s[-1], z[-1], "o", color=c, markersize=10, markeredgecolor="black",
                markeredgewidth=0.8, zorder=3)

    # Legend proxies: base (its rest position, the origin) and load (end of the last link).
    ax.plot(0.0, 0.0, marker="^", color="black", markersize=12, linestyle="none", zorder=4,
            label="base (rest position)")
    ax.plot([], [], "o", color="lightgray", markersize=10, markeredgecolor="black",
            markeredgewidth=0.8, linestyle="none", label="load (end of link %d)" % n)

    ax.set_aspect("equal", adjustable="datalim")
    ax.invert_yaxis()  # z is down: depth grows downward on the plot, base at the top
    ax.set_xlabel(hlabel)
    ax.set_ylabel("depth z [m] (down)")
    ax.grid(True, alpha=0.3)
    ax.axhline(0.0, color="gray", linewidth=0.6)
    ax.axvline(0.0, color="gray", linewidth=0.6, linestyle=":")
    ax.legend(loc="best", fontsize=10, framealpha=0.85)
    title = "cable shape, %d snapshot%s, n = %d links" % (len(rows), "" if len(rows) == 1 else "s", n)
    extent = np.nanmax(np.abs(np.concatenate([ex[rows].ravel(), ey[rows].ravel(), ez[rows].ravel()])))
    if np.isfinite(off_plane) and off_plane > 1e-3 * max(extent, 1e-9):
        title += "\n(side view; out of plane up to %.3g m)" % off_plane
    ax.set_title(title)

    sm = cm.ScalarMappable(norm=norm, cmap=cmap)
    sm.set_array([])
    bar = fig.colorbar(sm, ax=ax, fraction=0.05, pad=0.02)
    bar.set_label("time [s]")


def no_data(ax, text):
    ax.text(0.5, 0.5, text, transform=ax.transAxes, ha="center", va="center", color="gray")


def plot_tension(ax, cols):
    t = cols["time"]
    ax.set_title("top tension")
    ax.set_xlabel("time [s]")
    ax.set_ylabel("tension [N]")
    ax.grid(True, alpha=0.3)
    if "top_tension" not in cols:
        no_data(ax, "no top_tension column")
        return
    ax.plot(t, cols["top_tension"], color="tab:purple", linewidth=1.2, marker="o" if len(t) < 3 else None)
    ax.set_xlim(t.min(), t.max() if t.max() > t.min() else t.min() + 1.0)


def plot_energies(ax, cols):
    t = cols["time"]
    ax.set_title("energies")
    ax.set_xlabel("time [s]")
    ax.set_ylabel("energy [J]")
    ax.grid(True, alpha=0.3)
    drawn = 0
    for name, label, style in ENERGY_SERIES:
        if name not in cols:
            continue
        v = cols[name]
        if not np.any(np.isfinite(v) & (v != 0.0)):
            continue  # identically zero (or no data)
        if name == "total_energy":
            fin = np.flatnonzero(np.isfinite(v))
            if fin.size >= 2:
                change = v[fin[-1]] - v[fin[0]]
                # Relative to the energy that moves around (the largest of the terms), not to the total,
                # which may sit near zero.
                terms = [np.abs(cols[n]) for n, _, _ in ENERGY_SERIES if n in cols and n != "total_energy"]
                ref = max((np.nanmax(a) for a in terms), default=0.0)
                label = "total (change %+.3g J%s)" % (
                    change, ", %+.2g%% of the largest term" % (100.0 * change / ref) if ref > 0 else "")
        style = dict(style)
        ax.plot(t, v, label=label, linewidth=style.pop("linewidth", 1.3), marker="o" if len(t) < 3 else None,
                **style)
        drawn += 1
    if drawn == 0:
        no_data(ax, "no nonzero energy series")
        return
    ax.set_xlim(t.min(), t.max() if t.max() > t.min() else t.min() + 1.0)
    ax.axhline(0.0, color="gray", linewidth=0.6)
    ax.legend(loc="best", fontsize=9, framealpha=0.85, ncol=2)


def main(argv=None):
    parser = argparse.ArgumentParser(description="Plot a cable simulator run (CSV) to a PNG.")
    parser.add_argument("csv", help="run CSV (header line, one row per output time)")
    parser.add_argument("png", help="output PNG path")
    parser.add_argument("--title", default=None, help="figure title (default: the CSV's file name)")
    parser.add_argument("--snapshots", type=int, default=8, metavar="N",
                        help="number of cable-shape snapshots, evenly spaced in time (default 8)")
    args = parser.parse_args(argv)
    if args.snapshots < 1:
        parser.error("--snapshots must be at least 1")

    cols, links = read_csv(args.csv)

    plt.rcParams.update({"font.size": 11, "axes.titlesize": 12, "axes.labelsize": 11})
    fig = plt.figure(figsize=(14, 8), dpi=100, constrained_layout=True)
    grid = fig.add_gridspec(2, 2, width_ratios=[1.15, 1.0])
    ax_shape = fig.add_subplot(grid[:, 0])
    ax_tension = fig.add_subplot(grid[0, 1])
    ax_energy = fig.add_subplot(grid[1, 1], sharex=ax_tension)

    plot_shape(ax_shape, fig, cols, links, args.snapshots)
    plot_tension(ax_tension, cols)
    plot_energies(ax_energy, cols)

    fig.suptitle(args.title if args.title is not None else os.path.basename(args.csv), fontsize=14)
    fig.savefig(args.png, dpi=100)
    plt.close(fig)
    return 0


if __name__ == "__main__":
    sys.exit(main())
