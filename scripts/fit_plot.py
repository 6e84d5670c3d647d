#!/usr/bin/python3
"""The picture of a calibration: for each measured shot, the table from above with every ball's measured centres
(dots) and its fitted simulated path (line), titled with the cue ball's error. Reads what `shotlab fit --out` writes;
the format follows the file's extension (.png, .svg).

usage: fit_plot.py [--] FIT.json PICTURE.png|svg   (`shotlab fit --picture` runs it)
"""
import json
import math
import sys
import textwrap

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

COLOURS = {"white": "#9a9a9a", "yellow": "#d4a017", "red": "#d62728"}


def draw_shot(ax, shot, table):
    if table:
        hx, hz = table["length"] / 2, table["width"] / 2
        ax.plot([-hx, hx, hx, -hx, -hx], [-hz, -hz, hz, hz, -hz], color="#5a3b1a", lw=2)
    for i, (ball, track) in enumerate(sorted(shot["measured"].items())):
        colour = COLOURS.get(ball, f"C{i}")
        ax.scatter([p[1] for p in track], [p[2] for p in track], s=4, color=colour, zorder=3)
        sim = shot["simulated"].get(ball, [])
        ax.plot([p[1] for p in sim], [p[2] for p in sim], color=colour, lw=1, zorder=2, label=ball)
    cue = shot["cue_ball"]
    ax.set_title(f"{shot['name']}: {cue} off by {shot['rms_mm'][cue]:.0f} mm rms", fontsize=8)
    ax.set_aspect("equal")
    ax.invert_yaxis()
    ax.set_xticks([])
    ax.set_yticks([])


def main(argv):
    args = [a for a in argv if a != "--"]
    if len(args) != 2:
        print(__doc__, file=sys.stderr)
        return 2
    with open(args[0]) as f:
        fit = json.load(f)
    shots = fit["shots"]
    cols = min(len(shots), 3 if len(shots) > 4 else 2 if len(shots) > 1 else 1)
    rows = math.ceil(len(shots) / cols)
    fig, axes = plt.subplots(rows, cols, figsize=(4.2 * cols, 2.4 * rows + 0.6), squeeze=False)
    for ax, shot in zip(axes.flat, shots):
        draw_shot(ax, shot, fit.get("table"))
    for ax in list(axes.flat)[len(shots):]:
        ax.axis("off")
    axes[0][0].legend(fontsize=7, loc="upper right")
    title = f"measured (dots) and fitted (lines); median cue-ball error {fit['median_cue_rms_mm']:.0f} mm"
    # Wrapped to the figure's width (about 12 characters an inch at this size): one shot's figure cut it at both ends.
    fig.suptitle(textwrap.fill(title, width=int(4.2 * cols * 12), break_on_hyphens=False), fontsize=10)
    fig.tight_layout()
    fig.savefig(args[1], dpi=110)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
