#!/usr/bin/python3
"""Throughput of the embedding (issue 32), printed and written as markdown: sweeps of 1000 cut shots and 100 breaks on
1 and 2 threads, the C API's overhead on the break, the Python module's cost per advance() call, and Dask's overhead
per task on a local cluster of two worker processes. Timings are alternated rounds and medians; the single-core
figures run pinned to one core.

usage: /usr/bin/python3 scripts/throughput.py [--build build] [--rounds 3] [--out docs/bench/throughput.md]
(Debian's python3 for its numpy and distributed; the package is imported from BUILD/python.)
"""
import argparse
import datetime
import os
import statistics
import subprocess
import sys
import tempfile
import time

from machine import describe, publish

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
CUT = ["cue.speed=1:3:25", "cue.aim_deg=-77:-73:40"]  # 1000 cut shots
BREAKS = ["cue.speed=8:12:100"]                        # 100 breaks
PIN = ["taskset", "-c", "1"]
REST = '{"table": {"type": "pool"}, "balls": [{"id": "a", "position": [0, 0.028575, 0]}], "duration": 1}'


def sweep_seconds(shotlab, scene, vary, jobs, pin):
    args = pin + [shotlab, "sweep", os.path.join(ROOT, "presets", scene), "--jobs", str(jobs), "-q", "--out", os.devnull]
    t0 = time.perf_counter()
    subprocess.run(args + [a for v in vary for a in ("--vary", v)], check=True)
    return time.perf_counter() - t0


def sweeps(shotlab, rounds):
    """Shots per second of each sweep on 1 thread pinned to each core and on 2 threads, the rounds alternated. The two
    vCPUs here may run at different speeds: the 2-thread figure is compared with the mean of the two cores'."""
    settings = {"core 0": (1, ["taskset", "-c", "0"]), "core 1": (1, ["taskset", "-c", "1"]), "2 threads": (2, [])}
    out = {}
    for name, scene, vary, rows in (("cut", "cut.json", CUT, 1000), ("break", "break.json", BREAKS, 100)):
        times = {k: [] for k in settings}
        for r in range(rounds):
            for k in (list(settings) if r % 2 == 0 else list(reversed(settings))):
                times[k].append(sweep_seconds(shotlab, scene, vary, *settings[k]))
        rate = {k: rows / statistics.median(v) for k, v in times.items()}
        one = (rate["core 0"] + rate["core 1"]) / 2
        out[name] = (rows, rate["core 0"], rate["core 1"], rate["2 threads"], rate["2 threads"] / one)
    return out


def capi(build, rounds):
    tool = os.path.join(build, "tests", "benchmarks", "capi_overhead")
    text = subprocess.run(PIN + [tool, os.path.join(ROOT, "presets", "break.json"), str(10 * rounds)],
                          check=True, capture_output=True, text=True).stdout
    return dict((k, float(v)) for k, v in (line.split() for line in text.splitlines()))


def python_call(build, calls=200000):
    """Microseconds per Simulation.advance() call on a resting ball, and per shotlab_advance() of the C API."""
    with tempfile.NamedTemporaryFile("w", suffix=".json", delete=False) as f:
        f.write(REST)
    try:
        code = ("import shotlab, time\n"
                f"s = shotlab.Simulation({f.name!r}); s.advance(1.0)\n"
                "t = time.perf_counter()\n"
                f"for _ in range({calls}): s.advance(0.001)\n"
                f"print(1e6 * (time.perf_counter() - t) / {calls})\n")
        env = dict(os.environ, PYTHONPATH=os.path.join(build, "python"))
        py = min(float(subprocess.run(PIN + [sys.executable, "-c", code], env=env, check=True, capture_output=True,
                                      text=True).stdout) for _ in range(3))
        tool = os.path.join(build, "tests", "benchmarks", "capi_overhead")
        c = min(float(subprocess.run(PIN + [tool, "--advance-calls", f.name, str(calls), "0.001"], check=True,
                                     capture_output=True, text=True).stdout.split()[1]) for _ in range(3))
    finally:
        os.remove(f.name)
    return py, c


def dask_overhead(rounds):
    """Seconds for 400 cut shots threaded (2 threads) and on a LocalCluster of 2 processes in 400 and in 4 tasks."""
    import shotlab
    import shotlab.cluster
    from dask.distributed import Client, LocalCluster

    s = shotlab.Sweep(os.path.join(ROOT, "presets", "cut.json"), ["cue.speed=1:3:10", "cue.aim_deg=-77:-73:40"])
    n = len(s)
    times = {"threads": [], "tasks_1": [], "tasks_100": []}
    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as lc, \
            Client(lc) as client:
        shotlab.cluster.sweep_lines(client, s, 50)  # workers warm: the package imported, the sweep received
        for _ in range(rounds):
            t0 = time.perf_counter()
            s.lines(jobs=2)
            times["threads"].append(time.perf_counter() - t0)
            for chunk in (1, 100):
                t0 = time.perf_counter()
                shotlab.cluster.sweep_lines(client, s, chunk)
                times[f"tasks_{chunk}"].append(time.perf_counter() - t0)
    med = {k: statistics.median(v) for k, v in times.items()}
    per_task = (med["tasks_1"] - med["threads"]) / n * 2  # worker-seconds lost per task (2 workers)
    return n, med, per_task


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--build", default=os.path.join(ROOT, "build"))
    p.add_argument("--rounds", type=int, default=3)
    p.add_argument("--out", help="write the figures as markdown here too")
    a = p.parse_args()
    build = os.path.abspath(a.build)
    sys.path.insert(0, os.path.join(build, "python"))
    shotlab = os.path.join(build, "app", "shotlab")
    sw = sweeps(shotlab, a.rounds)
    c = capi(build, max(a.rounds, 4))
    py, c_call = python_call(build)
    n, dk, per_task = dask_overhead(a.rounds)
    lines = [
        "# Throughput of sweeps and the embedding",
        "",
        f"`scripts/throughput.py`, {datetime.date.today()}, {describe(ROOT)}. Medians of {a.rounds} alternated rounds.",
        "",
        "| sweep (`shotlab sweep`, whole command) | runs | shots/s, 1 thread on core 0 / core 1 | shots/s, 2 threads | "
        "speed-up over the cores' mean |",
        "|---|---|---|---|---|",
    ]
    for name, (rows, c0, c1, s2, up) in sw.items():
        lines.append(f"| {name} ({' '.join('--vary ' + v for v in (CUT if name == 'cut' else BREAKS))}) | {rows} | "
                     f"{c0:.0f} / {c1:.0f} | {s2:.0f} | {up:.2f}x |")
    lines += [
        "",
        "| embedding | figure |",
        "|---|---|",
        f"| break to rest through libshotlab (420 frames of 1/60 s, states read each frame), pinned | "
        f"{c['c_api_ms']:.2f} ms |",
        f"| the same through the engine's C++ headers | {c['engine_ms']:.2f} ms |",
        f"| C API overhead (median ratio of {int(c['rounds'])} alternated pairs) | {100 * (c['ratio'] - 1):+.2f} % |",
        f"| Python `Simulation.advance()` per call, balls asleep, pinned | {py:.3f} us |",
        f"| C `shotlab_advance()` per call, same scene | {c_call:.3f} us |",
        f"| Python per-call overhead | {py - c_call:.3f} us |",
        f"| {n} cut shots on 2 threads (one process) | {dk['threads']:.3f} s |",
        f"| the same on a LocalCluster of 2 worker processes, {n} tasks of 1 row | {dk['tasks_1']:.3f} s |",
        f"| the same in {n // 100} tasks of 100 rows | {dk['tasks_100']:.3f} s |",
        f"| Dask overhead per task (worker time, tasks of 1 row) | {1e3 * per_task:.2f} ms |",
    ]
    publish(lines, a.out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
