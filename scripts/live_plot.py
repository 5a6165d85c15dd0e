#!/usr/bin/env python3
"""Live plot of one cable's cable_state: top tension, line pull and the load force [N] in one panel, the
energies [J] in the other, over the last `~window` seconds of simulated time (matplotlib; rqt is not
packaged on Debian 12).

    rosrun cable_dynamics live_plot.py __ns:=umbilical [_window:=60] [_png:=run.png] [_save_period:=0]

With a display it opens a window; without one (or with MPLBACKEND=Agg) it draws off screen. `~png`: the
figure is written there on exit (Ctrl-C, SIGTERM, rosnode kill), on SIGUSR1, and every `~save_period`
seconds when that is > 0 (written to a temporary file and renamed, so a reader never sees half a PNG).
"""
import collections
import math
import os
import signal
import sys
import threading

import matplotlib

if not os.environ.get("DISPLAY") and "MPLBACKEND" not in os.environ:
    matplotlib.use("Agg")  # headless: draw off screen
import matplotlib.pyplot as plt  # noqa: E402  (after the backend is chosen)
import rospy  # noqa: E402
from cable_msgs.msg import CableState  # noqa: E402

# The curves: (label, how to read it from a CableState, panel, line style).
FORCES = [
    ("top tension", lambda m: m.top_tension, "-"),
    ("line pull", lambda m: m.line_pull, "--"),
    ("load force |F|", lambda m: math.sqrt(m.load_force.x ** 2 + m.load_force.y ** 2 + m.load_force.z ** 2), ":"),
]
ENERGIES = [
    ("kinetic", lambda m: m.kinetic_energy, "-"),
    ("potential", lambda m: m.potential_energy, "-"),
    ("elastic", lambda m: m.elastic_energy, "-"),
    ("dissipated", lambda m: m.dissipated_energy, "--"),
]


class LivePlot:
    def __init__(self, window):
        self.window = window  # [s] of simulated time shown
        self.lock = threading.Lock()
        self.times = collections.deque()
        self.series = {label: collections.deque() for label, _, _ in FORCES + ENERGIES}
        self.samples = 0
        self.figure, (self.force_axes, self.energy_axes) = plt.subplots(2, 1, sharex=True, figsize=(9, 6))
        self.lines = {}
        for axes, curves in ((self.force_axes, FORCES), (self.energy_axes, ENERGIES)):
            for label, _, style in curves:
                (self.lines[label],) = axes.plot([], [], style, label=label)
            axes.grid(True, alpha=0.3)
            axes.legend(loc="upper left", fontsize="small")
        self.force_axes.set_ylabel("force [N]")
        self.energy_axes.set_ylabel("energy [J]")
        self.energy_axes.set_xlabel("simulated time [s]")
        self.title = self.figure.suptitle("waiting for cable_state")
        self.figure.tight_layout()

    def on_state(self, msg):
        values = [read(msg) for _, read, _ in FORCES + ENERGIES]
        if not all(math.isfinite(v) for v in values):
            return  # the node never publishes these; a bad bag replay should not break the plot
        with self.lock:
            if self.times and msg.sim_time < self.times[-1]:  # the reset service: start afresh
                self.times.clear()
                for s in self.series.values():
                    s.clear()
            self.times.append(msg.sim_time)
            for (label, _, _), v in zip(FORCES + ENERGIES, values):
                self.series[label].append(v)
            while self.times and self.times[0] < msg.sim_time - self.window:
                self.times.popleft()
                for s in self.series.values():
                    s.popleft()
            self.samples += 1

    def redraw(self):
        with self.lock:
            t = list(self.times)
            data = {label: list(s) for label, s in self.series.items()}
            samples = self.samples
        for label, line in self.lines.items():
            line.set_data(t, data[label])
        for axes in (self.force_axes, self.energy_axes):
            axes.relim()
            axes.autoscale_view()
        if t:
            self.force_axes.set_xlim(t[0], max(t[-1], t[0] + 1e-3))
            self.title.set_text("%s: top tension %.1f N at t = %.2f s (%d samples)"
                                % (rospy.resolve_name("cable_state"), data["top tension"][-1], t[-1], samples))
        self.figure.canvas.draw_idle()

    def save(self, path):
        self.redraw()
        tmp = path + ".tmp.png"
        self.figure.savefig(tmp, dpi=80)
        os.replace(tmp, path)


def main():
    rospy.init_node("live_plot", disable_signals=False)
    window = float(rospy.get_param("~window", 60.0))
    png = rospy.get_param("~png", "")
    save_period = float(rospy.get_param("~save_period", 0.0))
    if not (window > 0.0 and math.isfinite(window)):
        rospy.logfatal("live_plot: ~window = %r: expected a number of seconds > 0", window)
        sys.exit(2)
    plot = LivePlot(window)
    save_now = threading.Event()
    signal.signal(signal.SIGUSR1, lambda *_: save_now.set())
    rospy.Subscriber("cable_state", CableState, plot.on_state, queue_size=100)
    headless = matplotlib.get_backend().lower() == "agg"
    if not headless:
        plt.show(block=False)
    rospy.loginfo("live_plot: %s on %s, %s", rospy.resolve_name("cable_state"),
                  "off screen (Agg)" if headless else "screen", "png " + png if png else "no png")
    last_save = rospy.get_time()
    try:
        while not rospy.is_shutdown():
            if headless:
                rospy.sleep(0.2)
            else:
                plot.redraw()
                plt.pause(0.2)  # the GUI's event loop
            due = save_period > 0.0 and rospy.get_time() - last_save >= save_period
            if png and (save_now.is_set() or due):
                save_now.clear()
                plot.save(png)
                last_save = rospy.get_time()
    except rospy.ROSInterruptException:
        pass
    if png:
        plot.save(png)
    print("live_plot: %d samples%s" % (plot.samples, ", wrote " + png if png else ""), flush=True)


if __name__ == "__main__":
    main()
