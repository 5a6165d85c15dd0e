"""DIR/summary.png: the largest utilisation over the first two axes as a heat map, failed cases marked.

When no case has a utilisation (no `cable.limits` in the config: every utilisation is 0) the map shows the
largest link tension [N] instead (its colour bar says which). A cell holds the largest value over the
cases that share its two values (the other axes and the random draws); a cell with a failed case is
framed in red with the count of failures. Matplotlib with the Agg backend: no display needed."""
import math

import matplotlib

matplotlib.use("Agg")
import matplotlib.patches  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from .cases import flow  # noqa: E402


def _number(cell):
    return float(cell) if cell not in ("", None) else math.nan


def draw_summary(rows, sweep, path):
    """Draws the rows (results.read_rows) of `sweep` (sweep_file.Sweep) into the PNG at `path`."""
    metric = "max_utilisation" if any(r["max_utilisation"] for r in rows) else "max_tension"
    label = "largest utilisation [-]" if metric == "max_utilisation" else "largest link tension [N]"
    axes = list(sweep.axes)[:2]  # none for a sweep of random draws only: one cell, the largest of them all
    x_key = axes[0] if axes else None
    y_key = axes[1] if len(axes) > 1 else None
    x_values = [flow(v) for v in sweep.axes[x_key]] if x_key else ["all cases"]
    y_values = [flow(v) for v in sweep.axes[y_key]] if y_key else [""]
    grid = np.full((len(y_values), len(x_values)), np.nan)
    failed = np.zeros_like(grid, dtype=int)
    for r in rows:
        try:
            i = y_values.index(r[y_key]) if y_key else 0
            j = x_values.index(r[x_key]) if x_key else 0
        except ValueError:  # a row of an axis value the sweep file no longer has
            continue
        value = _number(r[metric])
        if r["status"] != "ok":
            failed[i, j] += 1
        elif not math.isnan(value):
            grid[i, j] = value if math.isnan(grid[i, j]) else max(grid[i, j], value)
    fig, ax = plt.subplots(figsize=(max(5.0, 2.8 + 1.2 * len(x_values)), max(3.5, 1.8 + 0.8 * len(y_values))),
                           dpi=100)
    image = ax.imshow(np.ma.masked_invalid(grid), origin="lower", aspect="auto", cmap="viridis")
    fig.colorbar(image, ax=ax, label=label)
    for i in range(len(y_values)):
        for j in range(len(x_values)):
            if not math.isnan(grid[i, j]):
                # Dark text on the light end of the colour map, white on the dark end.
                light = image.norm(grid[i, j]) > 0.6 if np.nanmax(grid) > np.nanmin(grid) else False
                ax.text(j, i + 0.12, f"{grid[i, j]:.4g}", ha="center", va="center", fontsize=9,
                        color="black" if light else "white")
            if failed[i, j]:
                ax.add_patch(matplotlib.patches.Rectangle((j - 0.47, i - 0.47), 0.94, 0.94, fill=False,
                                                          edgecolor="red", linewidth=2.5))
                ax.text(j, i - 0.22, f"x {failed[i, j]} failed", ha="center", va="center", color="red",
                        fontsize=8, fontweight="bold",
                        bbox={"facecolor": "white", "edgecolor": "none", "alpha": 0.8, "pad": 1})
    ax.set_xticks(range(len(x_values)), x_values, rotation=30 if max(map(len, x_values)) > 6 else 0)
    ax.set_yticks(range(len(y_values)), y_values)
    ax.set_xlabel(x_key or "")
    ax.set_ylabel(y_key or "")
    ax.set_title(f"{len(rows)} cases; red frame: a failed case (status not ok)", fontsize=9)
    fig.tight_layout()
    fig.savefig(path)
    plt.close(fig)
