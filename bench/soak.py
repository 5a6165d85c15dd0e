#!/usr/bin/env python3
"""A long run of the node (issue 27: "a 30-minute soak of rov_dive in the node (payout and haul-in), memory
flat after warm-up, real-time factor 1.0, no retried step").

Starts `roslaunch cable_dynamics umbilical.launch config:=CONFIG` (with a roscore if none runs), replays the
config's dive by calling `reset` every PERIOD seconds (a reset plays the winch's schedule again from t = 0:
rov_dive pays out 30 -> 150 m and hauls back in over 400 s), and samples every SAMPLE seconds:
  - the node's resident memory (VmRSS of the cable_dynamics_node process) [MB];
  - cable_state: real_time_factor, retried_steps, diverged_steps, links added and removed, deployed length,
    and whether any published number is not finite.
Prints a line per sample and a summary; exits 1 when memory grew after the first period by more than
--growth MB, when a step was retried or diverged, when the median real-time factor is below 0.98, or when a
published number was not finite.

    source scripts/env.bash && /usr/bin/python3 bench/soak.py --minutes 30
"""
import argparse
import math
import os
import signal
import statistics
import subprocess
import sys
import time

import rospy
from cable_msgs.msg import CableState
from cable_msgs.srv import Reset


def node_pid():
    """The pid of the cable_dynamics_node process, or None."""
    for pid in os.listdir("/proc"):
        if not pid.isdigit():
            continue
        try:
            with open("/proc/%s/cmdline" % pid, "rb") as f:
                if b"cable_dynamics_node" in f.read().split(b"\0")[0]:
                    return int(pid)
        except OSError:
            continue
    return None


def resident_mb(pid):
    with open("/proc/%d/status" % pid) as f:
        for line in f:
            if line.startswith("VmRSS:"):
                return int(line.split()[1]) / 1024.0
    return float("nan")


def finite_message(m):
    values = [m.top_tension, m.kinetic_energy, m.potential_energy, m.elastic_energy, m.dissipated_energy,
              m.line_pull, m.deployed_length, m.load_force.x, m.load_force.y, m.load_force.z]
    return all(math.isfinite(v) for v in values) and all(math.isfinite(v) for v in m.tension)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--config", default=os.path.join(os.path.dirname(__file__), "..", "config", "rov_dive.yaml"))
    parser.add_argument("--minutes", type=float, default=30.0)
    parser.add_argument("--period", type=float, default=400.0, help="seconds between resets (the dive's length)")
    parser.add_argument("--sample", type=float, default=10.0, help="seconds between samples")
    parser.add_argument("--growth", type=float, default=5.0, help="allowed memory growth after warm-up [MB]")
    args = parser.parse_args()

    started_core = None
    if subprocess.run(["rosnode", "list"], capture_output=True).returncode != 0:
        started_core = subprocess.Popen(["roscore"], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                                        preexec_fn=os.setsid)
        time.sleep(5.0)
    launch = subprocess.Popen(["roslaunch", "cable_dynamics", "umbilical.launch",
                               "config:=" + os.path.abspath(args.config)],
                              stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, preexec_fn=os.setsid)
    rospy.init_node("soak", anonymous=True)
    latest = {}
    not_finite = [0]

    def on_state(m):
        latest["m"] = m
        if not finite_message(m):
            not_finite[0] += 1

    rospy.Subscriber("/umbilical/cable_state", CableState, on_state, queue_size=1)
    reset = rospy.ServiceProxy("/umbilical/reset", Reset)
    reset.wait_for_service(timeout=120.0)
    deadline = time.time() + 120.0
    while "m" not in latest and time.time() < deadline:
        time.sleep(0.1)
    pid = node_pid()
    if pid is None or "m" not in latest:
        print("soak: the node did not start")
        return 1

    start = time.time()
    next_reset = start + args.period
    rows, periods = [], []
    retried = diverged = added = removed = 0
    try:
        while time.time() - start < args.minutes * 60.0:
            time.sleep(args.sample)
            m = latest["m"]
            row = (time.time() - start, resident_mb(pid), m.real_time_factor, m.sim_time, m.deployed_length,
                   m.retried_steps, m.diverged_steps, m.links_added, m.links_removed)
            rows.append(row)
            print("%7.0f s  RSS %7.2f MB  RTF %5.3f  sim %7.1f s  deployed %6.1f m  retried %d  diverged %d  "
                  "added %d  removed %d" % row, flush=True)
            if time.time() >= next_reset:
                # The counters are since the last reset: book this period's before resetting.
                retried += m.retried_steps
                diverged += m.diverged_steps
                added += m.links_added
                removed += m.links_removed
                periods.append(row)
                response = reset()
                if not response.success:
                    print("soak: reset refused: " + response.message)
                next_reset += args.period
        m = latest["m"]
        retried += m.retried_steps
        diverged += m.diverged_steps
        added += m.links_added
        removed += m.links_removed
    finally:
        os.killpg(launch.pid, signal.SIGINT)
        launch.wait(timeout=30)
        if started_core is not None:
            os.killpg(started_core.pid, signal.SIGINT)
            started_core.wait(timeout=30)

    warm = [r for r in rows if r[0] >= args.period]  # after the first dive
    rss_warm = warm[0][1] if warm else rows[-1][1]
    rss_end, rss_max = rows[-1][1], max(r[1] for r in rows)
    rtf = [r[2] for r in rows]
    print("soak: %.1f min, %d dives; RSS %.2f MB after the first dive, %.2f MB at the end, %.2f MB at most; "
          "real-time factor median %.3f, least %.3f; retried %d, diverged %d steps; links added %d, removed %d; "
          "non-finite messages %d" % ((rows[-1][0]) / 60.0, len(periods) + 1, rss_warm, rss_end, rss_max,
                                      statistics.median(rtf), min(rtf), retried, diverged, added, removed,
                                      not_finite[0]))
    ok = (rss_end - rss_warm <= args.growth and retried == 0 and diverged == 0 and statistics.median(rtf) >= 0.98
          and not_finite[0] == 0)
    print("soak: " + ("passed" if ok else "FAILED"))
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
