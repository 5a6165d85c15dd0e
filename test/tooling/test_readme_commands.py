"""The commands README.md prints, run through bash as printed.

Every line of every ```sh block of README.md (comments and blank lines aside) is run in order from the
repository root, one bash shell per block (so a `source` line carries over to the lines after it), under
Xvfb with software GL (rviz opens a window), against a master on a port of its own. How a line is run
depends on what it is:
- `bash scripts/test.sh ...`: not run here (this test is part of it); .ci/run must run it as printed.
- `bash scripts/run.sh ...`: runs until roslaunch has started the node, rviz is through its start and
  RUN_SH_SECONDS more, then gets Ctrl-C (SIGINT), as a user stops it; it must still be running then.
- a line starting with `roslaunch `: started in the background, as in a terminal of its own, and stopped
  with SIGINT after every later block has run; it must still be running then.
- any other line: must finish within LINE_TIMEOUT with exit status 0.
The output of every line must have no error line (ERROR_PATTERN). What this does not check: that a
command's output is right (other tests check the tools), nor anything on the screen of rviz.
"""
import glob
import os
import re
import signal
import socket
import subprocess
import time

import pytest

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
START_TIMEOUT = 600  # s: run.sh's install check and (no-op) rebuild, then roslaunch, on a loaded 2-core machine
RUN_SH_SECONDS = 20  # s after the node has started: rviz starts and the demo runs
RVIZ_STARTED = "OpenGl version:"  # rviz's last start-up line in its log, after its render system is set up
NODE_STARTED = re.compile(r"process\[umbilical/cable_dynamics_node-\d+\]: started")
LINE_TIMEOUT = 300
ERROR_PATTERN = re.compile(r"\bError\b|\bERROR\b|\bFATAL\b|Traceback|File system loop|command not found")


def readme_blocks():
    """The README's ```sh blocks, each a list of its command lines."""
    blocks, current = [], None
    with open(os.path.join(REPO, "README.md")) as f:
        for line in f:
            stripped = line.rstrip("\n")
            if current is None and stripped.strip() == "```sh":
                current = []
            elif current is not None and stripped.strip() == "```":
                blocks.append(current)
                current = None
            elif current is not None and stripped.strip() and not stripped.strip().startswith("#"):
                current.append(stripped)
    assert current is None, "README.md: an unclosed ```sh block"
    return blocks


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


class Shell:
    """One bash per block: a line is sent on stdin, its output and exit status read back between markers."""

    started = []  # every shell, so that none outlives the test (stop_all)

    def __init__(self, env, log_dir, index):
        Shell.started.append(self)
        self.log = open(os.path.join(log_dir, f"block{index}.log"), "w+")
        self.proc = subprocess.Popen(["bash", "--noprofile", "--norc"], cwd=REPO, env=env, stdin=subprocess.PIPE,
                                     stdout=self.log, stderr=subprocess.STDOUT, text=True, start_new_session=True)
        self.count = 0

    def run(self, command, timeout, until=None):
        """Runs `command` in the shell (None: goes on waiting for the last one); returns (its exit status, or
        None when it is still running after `timeout` s or once its output matches `until`; its output)."""
        if command is not None:
            self.count += 1
            self.proc.stdin.write(f"echo @@begin{self.count}@@\n{command}\necho @@end{self.count}@@ $?\n")
            self.proc.stdin.flush()
        begin, end = f"@@begin{self.count}@@", f"@@end{self.count}@@"
        deadline = time.monotonic() + timeout
        while True:
            text = self._text().split(begin + "\n", 1)[-1]
            m = re.search(re.escape(end) + r" (\d+)", text)
            if m:
                return int(m.group(1)), text.split(end)[0]
            if self.proc.poll() is not None:
                return self.proc.returncode, text
            if (until is not None and until.search(text)) or time.monotonic() > deadline:
                return None, text
            time.sleep(0.5)

    def interrupt(self):
        """Ctrl-C to what runs in the shell's foreground (its process group)."""
        os.killpg(self.proc.pid, signal.SIGINT)

    def close(self):
        if self.proc.poll() is None:
            self.proc.stdin.close()
            try:
                self.proc.wait(timeout=60)
            except subprocess.TimeoutExpired:
                os.killpg(self.proc.pid, signal.SIGKILL)
                self.proc.wait()

    @classmethod
    def stop_all(cls):
        """Ctrl-C, then SIGKILL, to the process group of every shell still running (with what it started)."""
        for shell in cls.started:
            if shell.proc.poll() is None:
                shell.interrupt()
        deadline = time.monotonic() + 60
        for shell in cls.started:
            try:
                shell.proc.wait(timeout=max(1.0, deadline - time.monotonic()))
            except subprocess.TimeoutExpired:
                pass
            try:
                os.killpg(shell.proc.pid, signal.SIGKILL)  # what is left of its group
            except ProcessLookupError:
                pass
        cls.started = []

    def _text(self):
        self.log.flush()
        with open(self.log.name) as f:
            return f.read()


def errors(output):
    return [line for line in output.splitlines() if ERROR_PATTERN.search(line)]


def test_readme_has_the_everyday_commands():
    lines = [line for block in readme_blocks() for line in block]
    for command in ("bash scripts/run.sh", "bash scripts/test.sh", "source scripts/env.bash", "rosrun cable_dynamics",
                    "roslaunch cable_dynamics", "rostopic ", "rosservice call", "rosparam get", "rosbag info",
                    "rosmsg show"):
        assert any(line.startswith(command) for line in lines), f"README.md prints no `{command}` line"


def test_ci_runs_the_test_command_as_printed():
    lines = [line.split("#")[0].strip() for block in readme_blocks() for line in block]
    printed = [line for line in lines if line.startswith("bash scripts/test.sh")]
    assert printed == ["bash scripts/test.sh"]
    with open(os.path.join(REPO, ".ci", "run")) as f:
        assert "bash scripts/test.sh" in [line.strip() for line in f]


def test_readme_commands_run_as_printed(tmp_path):
    if not os.environ.get("DISPLAY"):
        # rviz needs a display: run under Xvfb (scripts/test.sh does).
        pytest.skip("no DISPLAY: run under xvfb-run (scripts/test.sh does)")
    env = dict(os.environ)
    log_dir = str(tmp_path / "ros_log")
    env.update(ROS_MASTER_URI=f"http://localhost:{free_port()}", ROS_LOG_DIR=log_dir, LIBGL_ALWAYS_SOFTWARE="1")
    failures, background = [], []
    rviz_checked, rviz_in_background = 0, 0  # rviz windows checked so far; started by background roslaunches
    try:
        for index, block in enumerate(readme_blocks()):
            shell = Shell(env, str(tmp_path), index)
            finished = []  # this block's earlier shells
            keep_open = False
            for line in block:
                command = line.split(" #")[0].strip()
                if command.startswith("bash scripts/test.sh"):
                    continue  # test_ci_runs_the_test_command_as_printed
                if command.startswith("bash scripts/run.sh"):
                    # Until roslaunch has started the node (after run.sh's install check and rebuild), then
                    # until rviz is through its start and RUN_SH_SECONDS more; then Ctrl-C.
                    status, output = shell.run(line, START_TIMEOUT, until=NODE_STARTED)
                    if status is not None or not NODE_STARTED.search(output):
                        failures.append(f"`{line}`: the node did not start (status {status}):\n{output[-3000:]}")
                    else:
                        rviz_checked += 1
                        if not wait_for_rviz(env):
                            failures.append(f"`{line}`: no rviz subscribed to the cable's markers")
                        status, output = shell.run(None, RUN_SH_SECONDS)
                        if status is not None:
                            failures.append(f"`{line}` stopped (status {status}) by itself:\n{output[-3000:]}")
                    shell.interrupt()
                    status, output = shell.run(None, 120)
                    if status is None:
                        failures.append(f"`{line}`: still running 120 s after Ctrl-C")
                    if shell.proc.poll() is not None:  # the shell went with it: the rest in a new one
                        finished.append(shell)
                        shell = Shell(env, str(tmp_path), f"{index}_{len(finished)}")
                elif command.startswith("roslaunch "):
                    shell.proc.stdin.write(line + "\n")  # a terminal of its own, running until Ctrl-C
                    shell.proc.stdin.flush()
                    wait_for_master(env)
                    rviz_in_background += "rviz:=true" in command
                    background.append((line, shell))
                    keep_open = True
                    break  # nothing after it in this terminal until it stops
                else:
                    status, output = shell.run(line, LINE_TIMEOUT)
                    if status != 0:
                        failures.append(f"`{line}`: exit status {status}:\n{output[-3000:]}")
                    bad = errors(output)
                    if bad:
                        failures.append(f"`{line}`: error lines:\n" + "\n".join(bad))
            if not keep_open:
                finished.append(shell)
            for done in finished:
                done.close()
                bad = errors(done._text())
                if bad:
                    failures.append(f"block {index}: error lines:\n" + "\n".join(bad))
        if rviz_in_background and not wait_for_rviz(env):
            failures.append("a roslaunch with rviz:=true: no rviz subscribed to the cable's markers")
        for line, shell in background:
            if shell.proc.poll() is not None:
                failures.append(f"`{line}` stopped before the blocks after it were done:\n{shell._text()[-3000:]}")
    finally:
        for line, shell in background:
            if shell.proc.poll() is None:
                shell.interrupt()
            shell.close()
            bad = errors(shell._text())
            if bad:
                failures.append(f"`{line}`: error lines:\n" + "\n".join(bad))
        Shell.stop_all()
    started = rviz_logs_through_start(log_dir)
    if started < rviz_checked + rviz_in_background:
        failures.append(f"{started} rviz logs reach '{RVIZ_STARTED}' of {rviz_checked + rviz_in_background} rviz started")
    assert not failures, "\n\n".join(failures)


def wait_for_rviz(env, seconds=180):
    """Until an rviz node subscribes to the cable's markers on the master of `env` (rviz subscribes once its
    render system and resources are set up, past where Debian's rviz asks for media_export). Bounded."""
    import rosgraph.masterapi  # Debian's python3-rosgraph

    master = rosgraph.masterapi.Master("/test_readme_commands", master_uri=env["ROS_MASTER_URI"])
    deadline = time.monotonic() + seconds
    while time.monotonic() < deadline:
        try:
            _, subscribers, _ = master.getSystemState()
            for topic, nodes in subscribers:
                if topic.endswith("/cable_markers") and any(n.startswith("/rviz") for n in nodes):
                    return True
        except (rosgraph.masterapi.Error, OSError):
            pass
        time.sleep(1)
    return False


def rviz_logs_through_start(log_dir):
    """How many rviz stdout logs (written out when rviz exits) reach RVIZ_STARTED."""
    done = 0
    for path in glob.glob(os.path.join(log_dir, "*", "rviz*-stdout.log")):
        if os.path.islink(os.path.dirname(path)):
            continue  # ros_log/latest
        with open(path, errors="replace") as f:
            done += RVIZ_STARTED in f.read()
    return done


def wait_for_master(env, seconds=90):
    """Until rosnode reaches the master the background roslaunch starts (bounded)."""
    deadline = time.monotonic() + seconds
    while time.monotonic() < deadline:
        if subprocess.run(["rosnode", "list"], env=env, capture_output=True, timeout=30).returncode == 0:
            return
        time.sleep(1)
    pytest.fail(f"no master at {env['ROS_MASTER_URI']} after {seconds} s")
