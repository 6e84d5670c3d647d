#!/usr/bin/python3
"""How far the rigid model (docs/model.md#rigid-model) lands from the soft one (issue 34): every table preset the rigid
model runs, played to rest on both with `shotlab run`, compared ball by ball over the whole shot and at rest; and, if
given, the two models' fits to the measured shots (`shotlab fit` JSON of each).

usage: python3 scripts/rigid_report.py [--shotlab build/app/shotlab] [--fit-soft A.json --fit-rigid B.json [C.json ...]]
                                       [--out docs/bench/rigid.md]
"""
import argparse
import csv
import datetime
import glob
import json
import math
import os
import statistics
import subprocess
import tempfile

from machine import describe, publish

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
RATE = 100  # trajectory samples per second
LONGEST = 60  # s: both models reach rest well before


def play(shotlab, scene, contact, tmp):
    """(result JSON, {ball: [(t, x, z)]}) of the scene to rest on the given contact model, or None if refused."""
    out, traj = os.path.join(tmp, f"{contact}.json"), os.path.join(tmp, f"{contact}.csv")
    args = [shotlab, "run", scene, "--until-rest", "--out", out, "--trajectory", traj, "--sample-rate", str(RATE),
            "--set", f"duration={LONGEST}", "--set", f"model.contact={contact}", "-q"]
    done = subprocess.run(args, capture_output=True, text=True)
    if done.returncode != 0:
        return None, done.stderr.strip().splitlines()[-1]
    paths = {}
    with open(traj) as f:
        for row in csv.DictReader(f):
            paths.setdefault(row["ball"], []).append((float(row["time"]), float(row["x"]), float(row["z"])))
    with open(out) as f:
        return json.load(f), paths


def compare(soft, rigid):
    """Per ball: RMS distance over the shot (mm; each path held at its end once it stops), distance at rest (mm)."""
    (s_res, s_paths), (r_res, r_paths) = soft, rigid
    rows = {}
    for ball in s_paths:
        a, b = s_paths[ball], r_paths[ball]
        n = max(len(a), len(b))
        sq = [(a[min(k, len(a) - 1)][1] - b[min(k, len(b) - 1)][1]) ** 2 +
              (a[min(k, len(a) - 1)][2] - b[min(k, len(b) - 1)][2]) ** 2 for k in range(n)]
        rows[ball] = (1e3 * math.sqrt(sum(sq) / n), 1e3 * math.sqrt(sq[-1]))
    pocketed = [sorted(b["id"] for b in res["balls"] if b["motion"] == "pocketed") for res in (s_res, r_res)]
    return rows, pocketed, (s_res["time"], r_res["time"])


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--shotlab", default=os.path.join(ROOT, "build", "app", "shotlab"))
    ap.add_argument("--fit-soft")
    ap.add_argument("--fit-rigid", nargs="+", help="one or more runs of the rigid fit: the table shows the first")
    ap.add_argument("--out")
    a = ap.parse_args()
    lines = ["# The rigid model against the soft model", "",
             f"`scripts/rigid_report.py`, {datetime.date.today()}, {describe(ROOT)}. Each preset the rigid model runs, "
             f"played to rest on the soft model (the default) and on the rigid model (`--set model.contact=rigid`), "
             f"sampled at {RATE} Hz. *Over the shot*: root mean square distance between the two models' centres over "
             "the samples (a ball at rest keeps its last place), mm; *at rest*: the distance where they stop, mm.", "",
             "| preset | ball | over the shot | at rest | pocketed, soft / rigid | to rest, soft / rigid (s) |",
             "|---|---|---|---|---|---|"]
    refused = []
    for scene in sorted(glob.glob(os.path.join(ROOT, "presets", "*.json"))):
        name = os.path.basename(scene)
        with tempfile.TemporaryDirectory() as tmp:
            rigid = play(a.shotlab, scene, "rigid", tmp)
            if rigid[0] is None:
                refused.append(f"- {name}: {rigid[1]}")
                continue
            rows, pocketed, ends = compare(play(a.shotlab, scene, "soft", tmp), rigid)
        first = True
        for ball, (over, rest) in rows.items():
            head = (f"| {name} | {ball} | {over:.0f} | {rest:.0f} | {', '.join(pocketed[0]) or '-'} / "
                    f"{', '.join(pocketed[1]) or '-'} | {ends[0]:.2f} / {ends[1]:.2f} |") if first else \
                f"| | {ball} | {over:.0f} | {rest:.0f} | | |"
            lines.append(head)
            first = False
    lines += ["", "How to read it: a ball that only slides and rolls follows the same closed forms on both models, so "
              "shots without cushions differ by what the collisions leave out (contact time, the hop after an "
              "impact). A cushion is an impact integrated over its impulse on the rigid model, the ball held on the "
              "bed, and a contact of about 1.6 ms on the soft one, with the ball pressed into the bed and hopping off "
              "it: each cushion adds a little to the distance. A break "
              "is chaotic on both (a micrometre early on becomes a different game): compare how the balls spread and "
              "what drops, not where each ball stops.",
              "", "Refused by the rigid model, as scenes should be that it cannot run:", ""] + refused
    if a.fit_soft and a.fit_rigid:
        fits = {}
        for label, path in (("soft", a.fit_soft), ("rigid", a.fit_rigid[0])):
            with open(path) as f:
                fits[label] = json.load(f)
        runs = []
        for path in a.fit_rigid:
            with open(path) as f:
                runs.append(json.load(f))
        lines += ["", "Both models fitted to the ten measured three-cushion shots (`shotlab fit`, one shared set of "
                  "materials and a cue strike per shot, as [fit.md](fit.md); the rigid fit with `--set "
                  "model.contact=rigid`). Root mean square distance between simulated and measured centres over the "
                  "shot, mm:", "", "| shot | cue ball | soft | rigid |", "|---|---|---|---|"]
        rigid_shots = {s["name"]: s for s in fits["rigid"]["shots"]}
        for s in fits["soft"]["shots"]:
            cue = s["cue_ball"]
            lines.append(f"| {s['name']} | {cue} | {s['rms_mm'][cue]:.0f} | "
                         f"{rigid_shots[s['name']]['rms_mm'][cue]:.0f} |")
        lines += ["", f"Median cue-ball error: soft {fits['soft']['median_cue_rms_mm']:.0f} mm in "
                  f"{fits['soft']['seconds']:.0f} s, rigid {fits['rigid']['median_cue_rms_mm']:.0f} mm in "
                  f"{fits['rigid']['seconds']:.0f} s."]
        if len(runs) > 1:
            medians = [r["median_cue_rms_mm"] for r in runs]
            lines += ["", "The rigid fit run again gives " +
                      ", ".join(f"{r['median_cue_rms_mm']:.0f} mm in {r['seconds']:.0f} s" for r in runs[1:]) +
                      (": its rounds (docs/fit.md) can end differently from run to run, since Ceres' threads change "
                       "the last bits of a joint fit and a three-cushion path is chaotic."
                       if max(medians) - min(medians) > 1 else ".")]
    publish(lines, a.out)


if __name__ == "__main__":
    main()
