#!/usr/bin/python3
"""Whole shots to rest (issue 34), printed and written as markdown: the break (presets/break.json) and the cut
(presets/cut.json) timed by tests/benchmarks/shot_speed on one pinned core, this build's soft model against its rigid
model (docs/model.md#rigid-model) and, if given, a baseline build of the same benchmark (another commit's), in
alternated rounds; the plain all-ODE path once for reference; where
this build's steps and right-hand sides go, by the kind of island that took them; and what the cost follows: the same
shots at looser integrator tolerances and softer friction rate limits. With valgrind installed, also the instructions
a shot executes in each build: a count that does not move with the vCPU's speed, so that changes of a few per cent,
lost in the wall time's spread, still show.

usage: python3 scripts/speed_bench.py [--build build] [--baseline OTHER_BUILD] [--label TEXT] [--core 0]
                                      [--rounds 5] [--sweep-rounds 3] [--out docs/bench/speed.md]
"""
import argparse
import datetime
import os
import json
import re
import shutil
import statistics
import subprocess
import tempfile

from machine import describe, publish

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SCENES = ["break.json", "cut.json"]


# The variants of the sweep: (label, scene section, field, value); the first is the default, each other changes one
# number of it (docs/scene-format.md).
VARIANTS = [("default (tolerance 1e-7, rate limit 2e5 1/s)", None, None, None)] + \
    [(f"tolerance {t:.0e}", "integrator", None, t) for t in (1e-6, 1e-5, 1e-4, 1e-3)] + \
    [(f"rate limit {r:.0e} 1/s", "model", "friction_rate_limit", r) for r in (5e4, 2e4)]


def measure(build, core, runs, plain=False, paths=None, rigid=False):
    """{scene: (median ms, steps, rejected, redone, rhs, digest, first ms)} from one call of shot_speed pinned to
    `core`, of the presets or of `paths`; redone (first ms) is None from a build whose benchmark does not count it."""
    tool = os.path.join(build, "tests", "benchmarks", "shot_speed")
    args = ["taskset", "-c", str(core), tool, "--rounds", str(runs)] + (["--plain"] if plain else []) + \
        (["--rigid"] if rigid else [])
    paths = paths or [os.path.join(ROOT, "presets", s) for s in SCENES]
    text = subprocess.run(args + paths, check=True, capture_output=True, text=True).stdout
    out = {}
    for line in text.splitlines():
        f = line.split()
        v = dict(zip(f[1::2], f[2::2]))
        out[os.path.basename(f[0])] = (float(v["median_ms"]), int(v["steps"]), int(v["rejected"]),
                                       int(v["redone"]) if "redone" in v else None, int(v["rhs"]), v["digest"],
                                       float(v["first_ms"]) if "first_ms" in v else None)
    return out


def instructions(build, scene):
    """Instructions one shot of `scene` executes (callgrind's count), or None without valgrind: a run of three shots
    less a run of one, halved, so that the process's start and the scene's loading cancel."""
    if not shutil.which("valgrind"):
        return None
    tool = os.path.join(build, "tests", "benchmarks", "shot_speed")

    def refs(shots):
        args = ["valgrind", "--tool=callgrind", "--callgrind-out-file=/dev/null", tool, "--rounds", str(shots),
                os.path.join(ROOT, "presets", scene)]
        err = subprocess.run(args, check=True, capture_output=True, text=True).stderr
        return int(re.search(r"I\s+refs:\s+([\d,]+)", err).group(1).replace(",", ""))
    return (refs(3) - refs(1)) / 2


def census(build, core):
    """({"census": [(scene, kind, {steps, rhs, redone, rejected, limited, wall_us})], "phase": [(scene, phase,
    {steps, rhs, wall_us})]}: one run of each scene counted, ten timed; by the kind of island and by what the step
    resolves."""
    tool = os.path.join(build, "tests", "benchmarks", "shot_speed")
    text = subprocess.run(["taskset", "-c", str(core), tool, "--rounds", "1", "--census"] + [os.path.join(ROOT, "presets", s) for s in SCENES],
                          check=True, capture_output=True, text=True).stdout
    out = {"census": [], "phase": []}
    for line in text.splitlines():
        for tag in out:
            if f" {tag} " not in line:
                continue
            scene, rest = line.split(f" {tag} ", 1)
            kind, counts = rest.split(" steps ")
            f = ("steps " + counts).split()
            out[tag].append((os.path.basename(scene), kind, {k: float(n) if k == "wall_us" else int(n)
                                                             for k, n in zip(f[0::2], f[1::2])}))
    return out


def sweep(build, core, rounds):
    """[(label, {scene: (median ms, steps, rejected, redone, rhs, digest)})]: each variant of VARIANTS written beside
    the presets' scenes in a scratch folder, in rounds that alternate the variants; median of the rounds' medians."""
    times, last = {}, {}
    with tempfile.TemporaryDirectory() as tmp:
        files = {}
        for n, (label, section, field, value) in enumerate(VARIANTS):
            files[label] = []
            for s in SCENES:
                with open(os.path.join(ROOT, "presets", s)) as f:
                    scene = json.load(f)
                if section == "integrator":
                    scene["integrator"] = {"abs_tol": value, "rel_tol": value}
                elif section:
                    scene.setdefault(section, {})[field] = value
                path = os.path.join(tmp, f"{n}_{s}")
                with open(path, "w") as f:
                    json.dump(scene, f)
                files[label].append(path)
        for r in range(rounds):
            for label in (files if r % 2 == 0 else reversed(list(files))):
                last[label] = {k.split("_", 1)[1]: v[:6] for k, v in measure(build, core, 10, paths=files[label]).items()}
                times.setdefault(label, {s: [] for s in SCENES})
                for s in SCENES:
                    times[label][s].append(last[label][s][0])
    return [(label, {s: (statistics.median(times[label][s]),) + last[label][s][1:] for s in SCENES})
            for label, *_ in VARIANTS]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--build", default=os.path.join(ROOT, "build"))
    ap.add_argument("--baseline", help="a build directory of another commit with tests/benchmarks/shot_speed")
    ap.add_argument("--label", default="baseline", help="how the report names the baseline")
    ap.add_argument("--core", type=int, default=0)
    ap.add_argument("--rounds", type=int, default=5, help="alternated rounds of 10 shots of each scene")
    ap.add_argument("--out")
    ap.add_argument("--sweep-rounds", type=int, default=3, help="alternated rounds of the tolerance and rate-limit sweep")
    a = ap.parse_args()
    rigid = "this build, rigid model"
    sides = {"this build": a.build, rigid: a.build} | ({a.label: a.baseline} if a.baseline else {})
    times = {k: {s: [] for s in SCENES} for k in sides}
    last, first = {}, {s: [] for s in SCENES}
    for r in range(a.rounds):
        for k in (list(sides) if r % 2 == 0 else list(reversed(sides))):
            last[k] = measure(sides[k], a.core, 10, rigid=k == rigid)
            if k == rigid:
                for s in SCENES:
                    first[s].append(last[k][s][6])
            for s in SCENES:
                times[k][s].append(last[k][s][0])
    plain = measure(a.build, a.core, 1, plain=True)
    when = datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC")
    lines = ["# Whole shots to rest: the break and the cut", "",
             f"{describe(ROOT)}; {when}; pinned to CPU {a.core}; `python3 scripts/speed_bench.py"
             + (f" --baseline ... --label '{a.label}'" if a.baseline else "") + f" --rounds {a.rounds}`.", "",
             "Each figure is the median of the rounds' medians (a round: 10 shots of each scene, frames of 1/60 s to the "
             "first frame at rest, timed from the simulation's construction); the rounds alternate the builds. Steps, "
             "rejected steps, redone steps (accepted trials done again to end where a contact or friction law changes) "
             "and right-hand sides are exact.", "",
             "| scene | build | wall ms | steps | rejected | redone | right-hand sides |", "|---|---|---|---|---|---|---|"]
    for s in SCENES:
        for k in sides:
            _, steps, rej, redo, rhs, _, _ = last[k][s]
            if k == rigid:  # no steps: the events it handled, no right-hand sides
                lines.append(f"| {s} | {k} | {statistics.median(times[k][s]):.3f} | {steps} events | - | - | 0 |")
                continue
            lines.append(f"| {s} | {k} | {statistics.median(times[k][s]):.3f} | {steps} | {rej} | "
                         f"{'-' if redo is None else redo} | {rhs} |")
        _, steps, rej, redo, rhs, _, _ = plain[s]
        lines.append(f"| {s} | this build, plain path (one round) | {plain[s][0]:.1f} | {steps} | {rej} | {redo} | {rhs} |")
    lines += ["", "The rigid model is a different model (docs/model.md#rigid-model; its distance from the soft model is "
              "in [rigid.md](rigid.md)). The first shot in a process (each round is one) costs no more than the others: "
              "the break's first shot took " + ", ".join(f"{x:.1f}" for x in first["break.json"]) + " ms and "
              "the cut's " + ", ".join(f"{x:.2f}" for x in first["cut.json"]) + " ms (its restitution table is built "
              "with the engine, docs/model.md#rigid-model).", "",
              "| scene | wall time, rigid model / soft model |", "|---|---|"]
    for s in SCENES:
        ratios = [x / y for x, y in zip(times[rigid][s], times["this build"][s])]
        lines.append(f"| {s} | {statistics.median(ratios):.4f} ({min(ratios):.4f}-{max(ratios):.4f}) |")
    if a.baseline:
        lines += ["", "| scene | wall time, this build / " + a.label + " |", "|---|---|"]
        for s in SCENES:
            ratios = [x / y for x, y in zip(times["this build"][s], times[a.label][s])]
            lines.append(f"| {s} | {statistics.median(ratios):.3f} ({min(ratios):.3f}-{max(ratios):.3f}) |")
    counted_builds = ("this build",) + ((a.label,) if a.baseline else ())
    counts = {k: {s: instructions(sides[k], s) for s in SCENES} for k in counted_builds}
    if all(n is not None for c in counts.values() for n in c.values()):
        lines += ["", "Instructions a shot executes (callgrind: a run of three shots less a run of one, halved; exact, "
                  "unlike the wall time, and the same at any vCPU speed):", "",
                  "| scene | " + " | ".join(f"{k}, million" for k in counts) + (" | this build / " + a.label
                                                                               if a.baseline else "") + " |",
                  "|---|" + "---|" * (len(counts) + bool(a.baseline))]
        for s in SCENES:
            ratio = f" | {counts['this build'][s] / counts[a.label][s]:.4f}" if a.baseline else ""
            lines.append(f"| {s} | " + " | ".join(f"{c[s] / 1e6:.3f}" for c in counts.values()) + ratio + " |")
    lines += ["", "Where this build's steps go (one run of each scene; a lone ball in closed form rolls, slides or flies "
              "at one right-hand side a step). What shortens them: steps that ended at a contact or friction change "
              "(redone), trials the error control rejected, and steps that ended with a friction term inside a band "
              "widened by the rate limit, a linear damper at 2e5 1/s there (docs/model.md#rate-limit). The wall time "
              "of a kind (mean of ten runs on the same core) is what passed from one step's end to the end of its step: "
              "the step, and the regroups and frame ends before it:", "",
              "| scene | island | steps | right-hand sides | ended at a change | rejected trials | in a rate-limited band "
              "| wall ms (share) |",
              "|---|---|---|---|---|---|---|---|"]
    counted = census(a.build, a.core)
    rows = counted["census"]
    total = {s: sum(c["wall_us"] for t, _, c in rows if t == s) for s in SCENES}
    lines += [f"| {s} | {k} | {c['steps']} | {c['rhs']} | {c['redone']} | {c['rejected']} | {c['limited']} | "
              f"{c['wall_us'] / 1e3:.3f} ({100 * c['wall_us'] / total[s]:.0f} %) |" for s, k, c in rows]
    lines += ["", "The same steps by what they resolve, told by what touches at the step's end: a ball-ball contact, a "
              "cushion (or its jaw), a pocket (its liner, or a ball in its hole), else the bed alone (the hop a ball "
              "takes after a hit, its landings and its settling onto the cloth); closed-form steps, which also carry "
              "most frame ends (a lone ball rolls across many frames), apart:", "",
              "| scene | phase | steps | right-hand sides | wall ms (share) |", "|---|---|---|---|---|"]
    lines += [f"| {s} | {k} | {c['steps']} | {c['rhs']} | {c['wall_us'] / 1e3:.3f} "
              f"({100 * c['wall_us'] / total[s]:.0f} %) |" for s, k, c in counted["phase"]]
    lines += ["", "What the cost follows: this build on the same shots with one number changed, the integrator's "
              "tolerance (abs_tol = rel_tol) or the friction rate limit (docs/model.md#rate-limit; a change of the model, "
              f"not only of its accuracy), in {a.sweep_rounds} rounds that alternate the variants:", "",
              "| variant | break wall ms | steps | redone | right-hand sides | cut wall ms | steps | redone | "
              "right-hand sides |", "|---|---|---|---|---|---|---|---|---|"]
    for label, r in sweep(a.build, a.core, a.sweep_rounds):
        lines.append(f"| {label} | " + " | ".join(f"{r[s][0]:.3f} | {r[s][1]} | {r[s][3]} | {r[s][4]}" for s in SCENES)
                     + " |")
    publish(lines, a.out)


if __name__ == "__main__":
    main()
