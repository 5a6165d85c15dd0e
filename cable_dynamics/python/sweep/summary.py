"""A run reduced to the numbers a design check reads, sample by sample (the samples cable_sim writes), in
the worker: only this summary travels back, never the time series.

Columns (docs/CLI.md): the top tension's largest and smallest [N] (the tension at the top of the
deployed cable, cable_sim's `top_tension`), the largest link tension [N] and its link (1 = the base's),
the winch's largest line pull [N] (with a winch only), the largest force on the load [N] (|load_force|),
the smallest bend radius [m] and its link, the largest utilisation [-], the grounded length's range [m],
the touchdown point's range (arc length from the base [m], over the samples where the cable touches),
the most slack links at once.
"""
import numpy as np

COLUMNS = ["max_top_tension", "min_top_tension", "max_tension", "max_tension_link", "max_line_pull",
           "max_load_force", "min_bend_radius", "min_bend_radius_link", "max_utilisation",
           "min_grounded_length", "max_grounded_length", "min_touchdown", "max_touchdown", "max_slack_links"]


class Summary:
    """Fed every sample's Snapshot (add), gives the summary's columns (values): floats, ints, or None
    where a column does not apply (no winch; nothing touched the bottom; no sample at all)."""

    def __init__(self, has_winch):
        self.has_winch = has_winch
        self.samples = 0
        self.top = []  # [N], one per sample
        self.max_tension, self.max_tension_link = -np.inf, None
        self.max_load_force = -np.inf
        self.grounded = []  # [m]
        self.touchdown = []  # [m], samples where it touches
        self.max_slack = 0
        self.limits = _Limits()

    def add(self, s):
        self.samples += 1
        self.top.append(s.line_pull)
        k = int(np.argmax(s.tension))  # the first link of the largest, as numpy's argmax on the CSV's row
        if s.tension[k] > self.max_tension:
            self.max_tension, self.max_tension_link = float(s.tension[k]), k + 1
        self.max_load_force = max(self.max_load_force, float(np.linalg.norm(s.load_force)))
        self.grounded.append(s.grounded_length)
        if s.touchdown_arc_length >= 0.0:
            self.touchdown.append(s.touchdown_arc_length)
        self.max_slack = max(self.max_slack, s.slack_links)
        self.limits.add(s)

    def values(self):
        if self.samples == 0:
            return {c: None for c in COLUMNS}
        v = {"max_top_tension": max(self.top), "min_top_tension": min(self.top),
             "max_tension": self.max_tension, "max_tension_link": self.max_tension_link,
             "max_line_pull": max(self.top) if self.has_winch else None,
             "max_load_force": self.max_load_force,
             "min_grounded_length": min(self.grounded), "max_grounded_length": max(self.grounded),
             "min_touchdown": min(self.touchdown) if self.touchdown else None,
             "max_touchdown": max(self.touchdown) if self.touchdown else None,
             "max_slack_links": self.max_slack}
        v.update(self.limits.values())
        return v


class _Limits:
    """The bend radius and the utilisation (cable.limits, docs/MODEL.md section 13), from the Snapshot's
    `min_bend_radius` (inf while every joint is straight), `min_bend_radius_link` (0-based: reported 1 at the
    base, as max_tension_link) and `max_utilisation` (0 without limits)."""

    def __init__(self):
        self.min_bend_radius, self.min_bend_radius_link, self.max_utilisation = None, None, None

    def add(self, s):
        if self.min_bend_radius is None or s.min_bend_radius < self.min_bend_radius:
            self.min_bend_radius, self.min_bend_radius_link = float(s.min_bend_radius), int(s.min_bend_radius_link) + 1
        if self.max_utilisation is None or s.max_utilisation > self.max_utilisation:
            self.max_utilisation = float(s.max_utilisation)

    def values(self):
        return {"min_bend_radius": self.min_bend_radius, "min_bend_radius_link": self.min_bend_radius_link,
                "max_utilisation": self.max_utilisation}
