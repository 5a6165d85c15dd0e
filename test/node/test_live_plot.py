#!/usr/bin/env python3
"""scripts/live_plot.py as a user starts it, headless: it subscribes to cable_state, draws off screen
(Agg, no DISPLAY) and writes its figure on SIGUSR1 and on exit (SIGINT). The PNG must hold the curves:
coloured pixels in the force panel and in the energy panel, far more than the legends' short sample
lines have (about 40 pixels a curve; a curve across the 640-pixel panel has more than 640). The test
cable hangs at rest: the curves are flat."""
import os
import re
import signal
import subprocess
import tempfile
import time
import unittest
import xmlrpc.client

import matplotlib

matplotlib.use("Agg")
import matplotlib.image  # noqa: E402
import numpy  # noqa: E402
import rosgraph  # noqa: E402
import rospkg  # noqa: E402
import rospy  # noqa: E402
import rosunit  # noqa: E402
from cable_msgs.msg import CableState  # noqa: E402

NS = "/plot_test"
def curve_pixels(image):
    """Coloured pixels: the curves (matplotlib's C0..C3, antialiased) and the legends' samples; axes,
    text and grid are grey."""
    rgb = image[:, :, :3]
    return int(numpy.sum(rgb.max(axis=2) - rgb.min(axis=2) > 0.25))


class LivePlot(unittest.TestCase):
    def wait(self, what, condition, seconds):
        deadline = time.time() + seconds
        while not condition() and time.time() < deadline:
            time.sleep(0.1)
        self.assertTrue(condition(), what)

    def wait_for_states(self, topic, count):
        """Waits until `count` more messages have come on `topic` (at most 60 s)."""
        received = []
        subscriber = rospy.Subscriber(topic, CableState, lambda m: received.append(1), queue_size=1000)
        try:
            self.wait("%d messages on %s" % (count, topic), lambda: len(received) >= count, 60.0)
        finally:
            subscriber.unregister()

    def test_draws_headless_and_writes_its_png(self):
        script = os.path.join(rospkg.RosPack().get_path("cable_dynamics"), "scripts", "live_plot.py")
        png = os.path.join(tempfile.mkdtemp(prefix="live_plot_"), "plot.png")
        env = dict(os.environ)
        env.pop("DISPLAY", None)  # headless, as on a server: the script picks Agg itself
        env.pop("MPLBACKEND", None)
        plot = subprocess.Popen([script, "__ns:=" + NS, "__name:=live_plot", "_png:=" + png, "_window:=30"],
                                env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        try:
            master = rosgraph.Master("/test_live_plot")

            def subscribed():
                _, subscribers, _ = master.getSystemState()
                return NS + "/live_plot" in dict(subscribers).get(NS + "/cable_state", [])

            self.wait("live_plot subscribes to %s/cable_state" % NS, subscribed, 60.0)
            # Counted, not timed: 300 states published after it subscribed, then 100 more (at most 60 s
            # each, for a loaded machine).
            self.wait_for_states(NS + "/cable_state", 300)
            plot.send_signal(signal.SIGUSR1)
            self.wait("the PNG on SIGUSR1", lambda: os.path.exists(png), 20.0)
            first = matplotlib.image.imread(png)
            self.wait_for_states(NS + "/cable_state", 100)
            plot.send_signal(signal.SIGINT)
            output, _ = plot.communicate(timeout=30.0)
        finally:
            if plot.poll() is None:
                plot.kill()
                plot.communicate()
        print(output)
        self.assertEqual(plot.returncode, 0, output)
        samples = re.search(r"live_plot: (\d+) samples, wrote", output)
        self.assertIsNotNone(samples, output)
        self.assertGreater(int(samples.group(1)), 200)  # of the 400 published while it listened
        image = matplotlib.image.imread(png)
        self.assertEqual(image.shape[:2], (480, 720))  # 9 x 6 in at 80 dpi
        self.assertEqual(first.shape, image.shape)
        top, bottom = image[: image.shape[0] // 2], image[image.shape[0] // 2:]
        # The legends' samples: at most 4 x 40 pixels a panel; two curves across a panel: over 1280.
        print("coloured pixels: forces %d, energies %d" % (curve_pixels(top), curve_pixels(bottom)))
        self.assertGreater(curve_pixels(top), 1000, "force curves")
        self.assertGreater(curve_pixels(bottom), 1000, "energy curves")

    def test_demo_launch_starts_it(self):
        """demo.launch plot:=true plot_png:=... (test/live_plot.test): the plot subscribes to the demo's
        cable_state and writes its PNG when signalled (SIGUSR1, to the pid the node reports)."""
        png = rospy.get_param("/umbilical/live_plot/png")  # as the launch gave it (plot_png)
        self.assertTrue(png.endswith(".png"), png)
        master = rosgraph.Master("/test_live_plot")

        def subscribed():
            _, subscribers, _ = master.getSystemState()
            return "/umbilical/live_plot" in dict(subscribers).get("/umbilical/cable_state", [])

        self.wait("the demo's live_plot subscribes to /umbilical/cable_state", subscribed, 60.0)
        self.wait_for_states("/umbilical/cable_state", 300)
        pid = xmlrpc.client.ServerProxy(master.lookupNode("/umbilical/live_plot")).getPid("/test_live_plot")[2]
        os.kill(pid, signal.SIGUSR1)
        self.wait("the demo's PNG on SIGUSR1", lambda: os.path.exists(png), 20.0)
        image = matplotlib.image.imread(png)
        print("demo plot: coloured pixels: forces %d, energies %d"
              % (curve_pixels(image[:240]), curve_pixels(image[240:])))
        self.assertGreater(curve_pixels(image[:240]), 1000, "force curves")
        self.assertGreater(curve_pixels(image[240:]), 1000, "energy curves")
        os.remove(png)


if __name__ == "__main__":
    rospy.init_node("test_live_plot", anonymous=True)
    rosunit.unitrun("cable_dynamics", "live_plot", LivePlot)
