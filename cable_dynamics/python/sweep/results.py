"""DIR/results.csv: one row a case, appended (and flushed to disk) as each case finishes, so an
interrupted sweep keeps every case that finished; a rerun reads it back and runs only the others."""
import csv
import os

from .summary import COLUMNS as SUMMARY_COLUMNS


class ResultsError(RuntimeError):
    """DIR/results.csv belongs to another sweep (other columns) or cannot be read or written."""


def columns(keys):
    """The table's columns for a sweep setting `keys`."""
    return ["case"] + list(keys) + ["status", "reason"] + SUMMARY_COLUMNS + ["wall_time"]


def _cell(value):
    """A value as its CSV cell: repr for floats (they read back as the same double), '' for None."""
    if value is None:
        return ""
    if isinstance(value, float):
        return repr(value)
    return str(value)


class ResultsTable:
    """The results file of a sweep whose cases set `keys`."""

    def __init__(self, path, keys):
        self.path, self.keys, self.columns = path, list(keys), columns(keys)

    def done(self):
        """The identities (tuples of "key=value") of the cases the file already has. Drops a last line cut
        short by an interrupted write."""
        if not os.path.exists(self.path):
            return set()
        with open(self.path, "rb+") as f:
            data = f.read()
            if data and not data.endswith(b"\n"):  # a row cut short when the sweep was killed
                f.truncate(data.rfind(b"\n") + 1)
        with open(self.path, newline="") as f:
            reader = csv.reader(f)
            header = next(reader, None)
            if header is None:
                return set()
            if header != self.columns:
                raise ResultsError(f"{self.path} has the columns of another sweep ({', '.join(header[:6])}, ...): "
                                   "use another --output directory, or remove it")
            key_columns = range(1, 1 + len(self.keys))
            return {tuple(f"{header[i]}={row[i]}" for i in key_columns) for row in reader if row}

    def open(self):
        """Opens the file for appending (writing the header when it is new)."""
        new = not os.path.exists(self.path) or os.path.getsize(self.path) == 0
        try:
            self._file = open(self.path, "a", newline="")
        except OSError as e:
            raise ResultsError(f"cannot write {self.path}: {e.strerror}")
        self._writer = csv.writer(self._file)
        if new:
            self._writer.writerow(self.columns)
            self._file.flush()

    def append(self, case, row):
        """Writes the row of `case` (a cases.Case) with `row` (run_case's dict), and flushes it to disk."""
        key_cells = [o.split("=", 1)[1] for o in case.overrides]
        cells = [str(case.index)] + key_cells + [row["status"], row["reason"]]
        cells += [_cell(row[c]) for c in SUMMARY_COLUMNS] + [_cell(row["wall_time"])]
        self._writer.writerow(cells)
        self._file.flush()
        os.fsync(self._file.fileno())

    def close(self):
        self._file.close()


def read_rows(path):
    """The rows of a results file as dicts of strings (for the picture and the tests)."""
    with open(path, newline="") as f:
        return list(csv.DictReader(f))
