"""The sweep's progress: on a terminal one line rewritten in place (a bar, cases done, failed, time
left); otherwise one plain line a finished case."""
import sys
import time


def _clock(seconds):
    seconds = int(round(seconds))
    return f"{seconds // 3600}:{seconds // 60 % 60:02d}:{seconds % 60:02d}"


class Progress:
    def __init__(self, total, stream=None):
        self.stream = stream or sys.stdout
        self.tty = self.stream.isatty()
        self.total, self.done, self.failed = total, 0, 0
        self.start = time.monotonic()

    def line(self):
        elapsed = time.monotonic() - self.start
        left = elapsed / self.done * (self.total - self.done) if self.done else None
        eta = _clock(left) if left is not None else "?"
        return f"{self.done}/{self.total} cases done, {self.failed} failed, {eta} left ({_clock(elapsed)} so far)"

    def case_done(self, ok):
        self.done += 1
        self.failed += 0 if ok else 1
        if self.tty:
            width = 30
            filled = width * self.done // max(self.total, 1)
            self.stream.write(f"\r[{'#' * filled}{' ' * (width - filled)}] {self.line()}   ")
        else:
            self.stream.write(f"cable_sweep: {self.line()}\n")
        self.stream.flush()

    def finish(self):
        if self.tty:
            self.stream.write("\n")
            self.stream.flush()
