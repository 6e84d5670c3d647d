"""shotlab: billiard-ball physics (docs/python.md).

Simulation and run() simulate one scene; sweep() runs a scene over a grid or a random sample of scene values on every
core, as `shotlab sweep` does; shotlab.cluster runs the same sweep on a Dask cluster.
"""
import csv

from ._core import InputError, Simulation, Sweep, run, version

__all__ = ["InputError", "Simulation", "Sweep", "run", "sweep", "rows", "write_csv", "version"]


def _value(text):
    """A CSV field as Python: an int or a float where it is a number, else the text."""
    for kind in (int, float):
        try:
            return kind(text)
        except ValueError:
            pass
    return text


# Columns that hold names or messages (docs/sweep.md): text even where they read as a number (a ball called "1").
_TEXT = {"status", "reason", "pocketed", "first_contact", "first_ball"}


def _is_text(name):
    return name in _TEXT or name.endswith(".motion")


def _strings(name, values):
    """A list of PATH=VALUE(S) strings; a lone string is a TypeError (its characters would be read one by one)."""
    if isinstance(values, (str, bytes)):
        raise TypeError(f"{name}: a list of PATH=VALUES strings, got a lone string (put it in a list: [{values!r}])")
    return list(values)


def rows(header, lines):
    """The sweep's CSV lines as dicts keyed by the header's columns (numbers as int or float; names and messages as
    text)."""
    names = next(csv.reader([header]))
    return [{n: f if _is_text(n) else _value(f) for n, f in zip(names, fields)} for fields in csv.reader(lines)]


def write_csv(path, header, lines):
    """Writes a sweep's header and lines as the CSV file `shotlab sweep --out` writes."""
    with open(path, "w", newline="") as out:
        out.write(header)
        out.writelines(lines)


def sweep(scene, vary, samples=0, seed=1, overrides=(), duration=None, timeout=60.0, max_events=100000, jobs=0):
    """Runs `scene` (path, JSON text or dict) over `vary` (PATH=VALUES strings as `shotlab sweep --vary` takes them)
    on `jobs` threads (0: one per core) and returns one dict per run, in run order (docs/sweep.md lists the columns).
    samples=0 runs the full grid; samples=N draws N runs at random with `seed`."""
    s = Sweep(scene, _strings("vary", vary), samples, seed, _strings("overrides", overrides), duration, timeout,
              max_events)
    return rows(s.header, s.lines(jobs=jobs))
