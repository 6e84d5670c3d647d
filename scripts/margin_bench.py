#!/usr/bin/python3
"""The margin map's cost (issue 33's target: 40 x 20 aim-speed cells of 100 replays each for a cut shot in under 60 s
on this machine's two cores): times `shotlab margin presets/cut.json --map 40x20 --samples 100` and the default
margin, and writes the figures with the machine, date and commit.

usage: margin_bench.py [--shotlab build/app/shotlab] [--out docs/bench/margin.md]
"""
import argparse
import datetime
import json
import os
import subprocess
import sys
import tempfile
import time

from machine import describe, publish

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
TARGET_S = 60


def timed(args):
    t0 = time.perf_counter()
    subprocess.run(args, check=True, stdout=subprocess.DEVNULL)
    return time.perf_counter() - t0


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--shotlab", default=os.path.join(ROOT, "build", "app", "shotlab"))
    p.add_argument("--out")
    a = p.parse_args()
    cut = os.path.join(ROOT, "presets", "cut.json")
    goal = ["--goal", "pocket:1@pocket-right-front"]
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "m.json")
        t_map = timed([a.shotlab, "margin", cut, *goal, "--map", "40x20", "--samples", "100", "--no-sensitivity",
                       "--out", out, "-q"])
        with open(out) as f:
            m = json.load(f)["map"]
        t_default = timed([a.shotlab, "margin", cut, *goal, "--out", out, "-q"])
        with open(out) as f:
            d = json.load(f)
    best = max(max(row) for row in m["success"])
    lines = ["# Shot margin: cost", "",
             f"`scripts/margin_bench.py`, {datetime.date.today()}, {describe(ROOT)}.", "",
             "| run | replays | wall |", "|---|---|---|",
             f"| `shotlab margin presets/cut.json --map 40x20 --samples 100 --no-sensitivity` | 80 000 | "
             f"{t_map:.1f} s (target {TARGET_S} s) |",
             f"| `shotlab margin presets/cut.json` (200 replays, per-source ensembles, windows) | about 1 300 | "
             f"{t_default:.2f} s |", "",
             f"The map's best cell pots the 1 ball in {100 * best:.0f} % of 100 amateur tries; at the preset's own aim "
             f"and speed {100 * d['probability']:.0f} % of 200."]
    publish(lines, a.out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
