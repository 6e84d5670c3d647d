#!/usr/bin/python3
"""The picture of a shot margin: the table from above with where every replay left the balls (the goal's ball green
where the shot succeeded, red where it failed; the cue ball grey), and the map of success over aim x speed when the
margin has one. Reads what `shotlab margin --out` writes; the format follows the file's extension (.png, .svg).

usage: margin_plot.py [--] MARGIN.json PICTURE.png|svg   (`shotlab margin --picture` runs it)
"""
import json
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.patches import Circle  # noqa: E402


def draw_table(ax, m):
    for x1, z1, x2, z2 in m["table"]["lines"]:
        ax.plot([x1, x2], [z1, z2], color="#5a3b1a", lw=2.5, solid_capstyle="round", zorder=1)
    for x, z, r in m["table"]["holes"]:
        ax.add_patch(Circle((x, z), r, color="black", zorder=1))
    goal = m["goal"]
    if goal["kind"] == "zone":
        ax.add_patch(Circle((goal["x"], goal["z"]), goal["radius"], fill=False, ls="--", color="navy", lw=1.5,
                            zorder=2, label="target zone"))
    for ball, (x, z, r) in m["start"].items():
        ax.add_patch(Circle((x, z), r, fill=False, color="black", lw=1, zorder=3))
        ax.annotate(ball, (x, z), ha="center", va="center", fontsize=7, zorder=4)


def draw_ends(ax, m):
    goal = m["goal"]["ball"]
    cue = m["cue_ball"]
    layers = [(goal, lambda ok: "#2ca02c" if ok else "#d62728")]
    if cue != goal:
        layers.insert(0, (cue, lambda ok: "#7f7f7f"))
    for ball, colour_of in layers:
        ends = m["ends"].get(ball)
        if not ends:
            continue
        colours = [colour_of(ok) for ok in ends["success"]]
        ax.scatter(ends["x"], ends["z"], s=8, c=colours, alpha=0.6, zorder=5, linewidths=0)
    ax.set_aspect("equal")
    ax.invert_yaxis()  # z grows towards the player at the bottom of the picture
    ax.set_xlabel("x (m)")
    ax.set_ylabel("z (m)")
    where = m["goal"].get("pocket") or "a pocket" if m["goal"]["kind"] == "pocket" else "the zone"
    ax.set_title(f"{m.get('scene') or 'shot'}: {goal} in {where}: success {100 * m['probability']:.1f} % "
                 f"(+- {100 * m['standard_error']:.1f}, {m['samples']} replays)\n"
                 f"ends of {goal} (green: success, red: miss)" + (f" and of {cue} (grey)" if cue != goal else ""),
                 fontsize=9)


def draw_map(ax, m):
    mp = m["map"]
    a0, a1 = mp["aim_deg"]
    s0, s1 = mp["speed"]
    da = (a1 - a0) / max(1, mp["aims"] - 1) / 2
    ds = (s1 - s0) / max(1, mp["speeds"] - 1) / 2
    im = ax.imshow(mp["success"], origin="lower", aspect="auto", cmap="viridis", vmin=0, vmax=1,
                   extent=(a0 - da, a1 + da, s0 - ds, s1 + ds))
    ax.plot(*mp["nominal"], marker="+", color="white", ms=12, mew=2)
    ax.set_xlabel("intended aim (deg)")
    ax.set_ylabel("intended speed (m/s)")
    ax.set_title(f"success over aim x speed ({mp['aims']} x {mp['speeds']} cells, {m['samples']} replays each)",
                 fontsize=9)
    plt.colorbar(im, ax=ax, label="success probability")


def main(argv):
    args = [a for a in argv if a != "--"]
    if len(args) != 2:
        print(__doc__, file=sys.stderr)
        return 2
    with open(args[0]) as f:
        m = json.load(f)
    panels = 2 if "map" in m else 1
    fig, axes = plt.subplots(1, panels, figsize=(7 * panels, 4.5), squeeze=False)
    draw_table(axes[0][0], m)
    draw_ends(axes[0][0], m)
    if panels == 2:
        draw_map(axes[0][1], m)
    fig.tight_layout()
    fig.savefig(args[1], dpi=120)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
