"""A sweep on a Dask distributed cluster: the rows of `shotlab sweep`, farmed out to the workers in chunks.

    from dask.distributed import Client
    import shotlab.cluster
    rows = shotlab.cluster.sweep(Client("tcp://scheduler:8786"), "cut.json", ["cue.speed=1:3:50"])

or from a shell: python3 -m shotlab.cluster cut.json --scheduler tcp://scheduler:8786 --vary cue.speed=1:3:50 --out
results.csv. Every worker needs the same shotlab importable (docs/sweep.md says how to start them).
"""
import argparse
import math
import sys

from . import Sweep, _strings, rows, write_csv


def _chunk(sweep, begin, end):
    """One task: rows [begin, end) on the worker, one thread (Dask gives each task its own)."""
    return sweep.lines(begin, end, jobs=1)


def sweep_lines(client, sweep, chunk_size=None):
    """The CSV lines of every row of `sweep` (a shotlab.Sweep), computed on the cluster of `client` in chunks of
    chunk_size rows (default: about four chunks per worker thread), returned in row order."""
    n = len(sweep)
    if n == 0:
        return []
    if chunk_size is None:
        threads = sum(client.nthreads().values()) or 1
        chunk_size = max(1, math.ceil(n / (4 * threads)))
    shared = client.scatter(sweep, broadcast=True)  # the scene and plan travel once per worker, not once per task
    starts = range(0, n, chunk_size)
    futures = client.map(_chunk, [shared] * len(starts), starts, [min(n, b + chunk_size) for b in starts],
                         pure=False)
    return [line for chunk in client.gather(futures) for line in chunk]


def sweep(client, scene, vary, samples=0, seed=1, overrides=(), duration=None, timeout=60.0, max_events=100000,
          chunk_size=None):
    """shotlab.sweep() on the cluster of `client` (a dask.distributed.Client): the same rows, as dicts."""
    s = Sweep(scene, _strings("vary", vary), samples, seed, _strings("overrides", overrides), duration, timeout,
              max_events)
    return rows(s.header, sweep_lines(client, s, chunk_size))


def main(argv=None):
    p = argparse.ArgumentParser(prog="python3 -m shotlab.cluster",
                                description="Run `shotlab sweep` on a Dask cluster and write the same CSV.")
    p.add_argument("scene", help="scene file (JSON)")
    p.add_argument("--scheduler", required=True, help="the Dask scheduler's address, e.g. tcp://10.0.0.5:8786")
    p.add_argument("--vary", action="append", required=True, help="PATH=VALUES, as shotlab sweep takes it")
    p.add_argument("--samples", type=int, default=0, help="random sampling: this many runs instead of the grid")
    p.add_argument("--seed", type=int, default=1)
    p.add_argument("--set", dest="overrides", action="append", default=[], help="PATH=VALUE for every run")
    p.add_argument("--duration", type=float, help="simulated seconds per run (default: on to rest, up to 60 s)")
    p.add_argument("--timeout", type=float, default=60.0, help="wall seconds one run may take")
    p.add_argument("--max-events", type=int, default=100000)
    p.add_argument("--chunk", type=int, help="rows per task (default: about four tasks per worker thread)")
    p.add_argument("--out", required=True, help="CSV file to write")
    a = p.parse_args(argv)
    from dask.distributed import Client  # only the cluster form needs Dask
    try:
        s = Sweep(a.scene, a.vary, a.samples, a.seed, a.overrides, a.duration, a.timeout, a.max_events)
    except (ValueError, OSError) as e:
        print(f"shotlab: {e}", file=sys.stderr)
        return 1
    with Client(a.scheduler) as client:
        lines = sweep_lines(client, s, a.chunk)
    write_csv(a.out, s.header, lines)
    print(f"shotlab: sweep of {len(s)} runs on {a.scheduler} written to {a.out}", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
