"""The sweep file (YAML): read and checked before any case runs.

    config: umbilical.yaml          # a cable_dynamics config, relative to the sweep file or absolute
    duration: 2.0                   # [s] simulated per case (> 0)
    sample: 0.01                    # [s] optional, cable_sim's --sample (default 0.01)
    axes:                           # optional: config keys, each a non-empty list; the cases are their product
      fluid.current: [[0.5, 0, 0], [1.0, 0, 0]]
      cable.links: [10, 20]
    samples:                        # optional: seeded random draws (Monte Carlo), `count` of them per axes case
      seed: 1
      count: 8
      keys:
        load.mass: {uniform: [5.0, 20.0]}     # low, high
        fluid.drag_normal: {normal: [1.2, 0.1]}  # mean, standard deviation

Anything else, an empty axis or a value of the wrong type raises SweepFileError naming the key, the value
and what is expected; cable_sweep prints it and exits with status 2.
"""
import math
import os

import yaml

TOP_KEYS = ("config", "duration", "sample", "axes", "samples")
SAMPLES_KEYS = ("seed", "count", "keys")
DISTRIBUTIONS = {"uniform": "[low, high], low < high", "normal": "[mean, standard deviation], deviation > 0"}


class SweepFileError(ValueError):
    """A sweep file cable_sweep refuses (exit status 2)."""


class Sweep:
    """A checked sweep file: config (absolute path), duration and sample [s], axes (dict key -> list of
    values, in the file's order), samples (None, or dict seed, count, keys: key -> (distribution, a, b))."""

    def __init__(self, path, config, duration, sample, axes, samples):
        self.path, self.config, self.duration, self.sample = path, config, duration, sample
        self.axes, self.samples = axes, samples

    def keys(self):
        """The config keys the cases set: the axes', then the sampled ones."""
        sampled = list(self.samples["keys"]) if self.samples else []
        return list(self.axes) + [k for k in sampled if k not in self.axes]


def _number(where, value, lowest=None, integer=False):
    """`value` as a finite number (an int when `integer`), > `lowest` when given; SweepFileError otherwise."""
    kind = "an integer" if integer else "a number"
    ok_type = isinstance(value, int) if integer else isinstance(value, (int, float))
    if isinstance(value, bool) or not ok_type or not math.isfinite(value):
        raise SweepFileError(f"{where} = {value!r}: expected {kind}" + (f" > {lowest}" if lowest is not None else ""))
    if lowest is not None and not value > lowest:
        raise SweepFileError(f"{where} = {value!r}: expected {kind} > {lowest}")
    return value


def _config_key(where, key):
    if not isinstance(key, str) or not key or any(not part for part in key.split(".")) or "=" in key:
        raise SweepFileError(f"{where}: key {key!r}: expected a dotted config key, e.g. cable.links")
    return key


def _axis_value(where, value):
    """An axis value: a number, a string, a bool or a (nested) list of them; never a mapping or null."""
    if isinstance(value, list):
        for item in value:
            _axis_value(where, item)
        return value
    if value is None or isinstance(value, dict):
        raise SweepFileError(f"{where}: value {value!r}: expected a number, a string, a bool or a list of them")
    if isinstance(value, float) and not math.isfinite(value):
        raise SweepFileError(f"{where}: value {value!r}: expected a finite number")
    return value


def _axes(raw):
    if raw is None:
        return {}
    if not isinstance(raw, dict):
        raise SweepFileError(f"axes = {raw!r}: expected a mapping of config keys to lists of values")
    axes = {}
    for key, values in raw.items():
        _config_key("axes", key)
        if not isinstance(values, list):
            raise SweepFileError(f"axes.{key} = {values!r}: expected a list of values, e.g. [10, 20]")
        if not values:
            raise SweepFileError(f"axes.{key} is empty: expected at least one value")
        axes[key] = [_axis_value(f"axes.{key}", v) for v in values]
    return axes


def _samples(raw):
    if raw is None:
        return None
    if not isinstance(raw, dict):
        raise SweepFileError(f"samples = {raw!r}: expected a mapping with seed, count and keys")
    for key in raw:
        if key not in SAMPLES_KEYS:
            raise SweepFileError(f"samples.{key}: unknown key; expected one of {', '.join(SAMPLES_KEYS)}")
    for key in SAMPLES_KEYS:
        if key not in raw:
            raise SweepFileError(f"samples.{key} is missing")
    seed = _number("samples.seed", raw["seed"], lowest=-1, integer=True)
    count = _number("samples.count", raw["count"], lowest=0, integer=True)
    if not isinstance(raw["keys"], dict) or not raw["keys"]:
        raise SweepFileError(f"samples.keys = {raw['keys']!r}: expected a non-empty mapping of config keys to "
                             "{uniform: [low, high]} or {normal: [mean, deviation]}")
    keys = {}
    for key, spec in raw["keys"].items():
        _config_key("samples.keys", key)
        where = f"samples.keys.{key}"
        if not isinstance(spec, dict) or len(spec) != 1 or next(iter(spec)) not in DISTRIBUTIONS:
            raise SweepFileError(f"{where} = {spec!r}: expected one of {{uniform: [low, high]}}, "
                                 "{normal: [mean, deviation]}")
        kind, args = next(iter(spec.items()))
        if not isinstance(args, list) or len(args) != 2:
            raise SweepFileError(f"{where}.{kind} = {args!r}: expected {DISTRIBUTIONS[kind]}")
        a = _number(f"{where}.{kind}[0]", args[0])
        b = _number(f"{where}.{kind}[1]", args[1])
        if (kind == "uniform" and not a < b) or (kind == "normal" and not b > 0):
            raise SweepFileError(f"{where}.{kind} = {args!r}: expected {DISTRIBUTIONS[kind]}")
        keys[key] = (kind, float(a), float(b))
    return {"seed": seed, "count": count, "keys": keys}


def load_sweep(path):
    """Reads and checks the sweep file at `path`; returns a Sweep. Raises SweepFileError."""
    try:
        with open(path) as f:
            raw = yaml.safe_load(f)
    except OSError as e:
        raise SweepFileError(f"{path}: cannot read the sweep file ({e.strerror})")
    except yaml.YAMLError as e:
        raise SweepFileError(f"{path}: not valid YAML ({e})")
    if not isinstance(raw, dict):
        raise SweepFileError(f"{path}: expected a mapping with the keys {', '.join(TOP_KEYS)}")
    for key in raw:
        if key not in TOP_KEYS:
            raise SweepFileError(f"{key}: unknown key in the sweep file; expected one of {', '.join(TOP_KEYS)}")
    for key in ("config", "duration"):
        if key not in raw:
            raise SweepFileError(f"{key} is missing from the sweep file")
    if not isinstance(raw["config"], str) or not raw["config"]:
        raise SweepFileError(f"config = {raw['config']!r}: expected the path of a config file")
    config = os.path.join(os.path.dirname(os.path.abspath(path)), os.path.expanduser(raw["config"]))
    if not os.path.isfile(config):
        raise SweepFileError(f"config = {raw['config']!r}: no such file ({config})")
    duration = float(_number("duration", raw["duration"], lowest=0))
    sample = float(_number("sample", raw.get("sample", 0.01), lowest=0))
    axes = _axes(raw.get("axes"))
    samples = _samples(raw.get("samples"))
    if not axes and not samples:
        raise SweepFileError("the sweep file has neither axes nor samples: expected at least one of them")
    return Sweep(os.path.abspath(path), config, duration, sample, axes, samples)
