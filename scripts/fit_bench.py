#!/usr/bin/python3
"""The calibration benchmark (issue 33): `shotlab fit` on the measured three-cushion shots with one shared set of
materials and a cue strike per shot; prints and writes the error of every ball of every shot, the fitted materials,
the median cue-ball error and the time it took, with the machine, date and commit.

usage: fit_bench.py [--shotlab build/app/shotlab] [--measured ../shared/reference/measured] [--out docs/bench/fit.md]
"""
import argparse
import datetime
import glob
import json
import os
import subprocess
import sys
import tempfile

from machine import describe, publish

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
PATHS = ["materials.ball_cloth.friction", "materials.ball_cloth.rolling_resistance",
         "materials.ball_cloth.spin_friction", "materials.ball_cushion.friction", "materials.ball_cushion.damping",
         "materials.ball_ball.friction"]
TARGET_MM = 50


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--shotlab", default=os.path.join(ROOT, "build", "app", "shotlab"))
    p.add_argument("--measured", default=os.path.join(ROOT, "..", "shared", "reference", "measured"))
    p.add_argument("--out", help="write the figures as markdown here too (and the picture beside it)")
    a = p.parse_args()
    shots = sorted(glob.glob(os.path.join(a.measured, "shot_*.csv")))
    if not shots:
        print(f"no measured shots in {a.measured}", file=sys.stderr)
        return 77
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "fit.json")
        args = [a.shotlab, "fit", *shots, "--scene", os.path.join(ROOT, "presets", "three_cushion.json"), "--out", out,
                "-q"]
        for path in PATHS:
            args += ["--fit", path]
        if a.out:
            args += ["--picture", os.path.splitext(a.out)[0] + ".png"]
        subprocess.run(args, check=True)
        with open(out) as f:
            fit = json.load(f)
    lines = ["# Calibration on the measured three-cushion shots", "",
             f"`scripts/fit_bench.py`, {datetime.date.today()}, {describe(ROOT)}: `shotlab fit` on the {len(shots)} shots "
             f"of ../shared/reference/measured with one shared set of materials and a cue strike per shot; "
             f"{fit['seconds']:.0f} s. Errors: root mean square distance between simulated and measured centres "
             "over the whole shot, mm.", "",
             "| shot | cue ball | cue ball | other balls | fitted strike |", "|---|---|---|---|---|"]
    for s in fit["shots"]:
        cue = s["cue_ball"]
        others = ", ".join(f"{b} {v:.0f}" for b, v in sorted(s["rms_mm"].items()) if b != cue)
        c = s["cue"]
        lines.append(f"| {s['name']} | {cue} | {s['rms_mm'][cue]:.0f} | {others} | {c['speed']:.2f} m/s, "
                     f"{c['aim_deg']:.2f} deg, side {c['side']:+.2f}, height {c['height']:+.2f} |")
    median = fit["median_cue_rms_mm"]
    lines += ["", f"Median cue-ball error: **{median:.0f} mm** (target {TARGET_MM} mm; the web simulator's own fit of "
              "these ten: 200 mm).", "", "| value | scene | fitted | sd |", "|---|---|---|---|"]
    for v in fit["values"]:
        sd = "-" if v["sd"] is None else f"{v['sd']:.3g}"
        lines.append(f"| {v['path']} | {v['start']:.4g} | {v['value']:.4g} | {sd} |")
    lines += ["", f"Optimiser: {fit['report']}"]
    if a.out:
        lines += ["", f"![measured and fitted paths]({os.path.basename(os.path.splitext(a.out)[0])}.png)"]
    publish(lines, a.out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
