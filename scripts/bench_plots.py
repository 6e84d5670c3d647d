#!/usr/bin/env python3
"""Draws the bench's figures from the CSV files of a directory (docs/bench/README.md).

    python3 scripts/bench_plots.py DIR [--png]

results.csv (`shotlab bench`) gives work_precision.svg, tolerance_error.svg and steps_per_contact.svg; scaling.csv
(`shotlab bench --scaling`) scaling_scenes.svg; scaling_rhs.csv (tests/benchmarks/rhs_benchmark) scaling_rhs.svg.
Each figure is drawn when its CSV is there; --png writes a PNG beside each SVG. Needs python3 and matplotlib only
(Debian: python3-matplotlib). `shotlab bench` runs this on its output directory.
"""
import argparse
import csv
import math
import os
import sys
import textwrap

import matplotlib

matplotlib.use('Agg')  # no display needed
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.lines import Line2D  # noqa: E402

# Text stays text (small, searchable files); a fixed salt and no date make a redraw of the same CSV byte-identical.
plt.rcParams.update({'svg.fonttype': 'none', 'svg.hashsalt': 'shotlab-bench', 'font.size': 8})

# A fixed colour per method, so a method looks the same in every panel and figure.
COLORS = {'euler': '#9e9e9e', 'rk4': '#8d5a2b', 'cash_karp54': '#1f77b4', 'dopri5': '#d62728',
          'bulirsch_stoer': '#2ca02c', 'rosenbrock4': '#9467bd', 'rigid': '#ff7f0e'}

PANEL_W, PANEL_H = 3.3, 2.5  # inches per panel, labels included


class Series:
    def __init__(self, name, color, dashed=False):
        self.name, self.color, self.dashed, self.points = name, color, dashed, []


class Panel:
    def __init__(self, title, series=()):
        self.title, self.series = title, list(series)


def read_csv(path):
    with open(path, newline='') as f:
        return list(csv.DictReader(f))


def floored(error):
    """Errors under the references' agreement are not resolved, and a blown-up run (Euler on the cradle reaches 1e116)
    would stretch its panel over a hundred decades: both are drawn at the ends of 1e-14 .. 1e3."""
    return min(max(error, 1e-14), 1e3)


def decades(values):
    """Whole decades (exponents) that hold every value, at least one decade wide."""
    lo = math.floor(math.log10(min(values)) + 1e-9)
    hi = math.ceil(math.log10(max(values)) - 1e-9)
    return lo, max(hi, lo + 1)


def result_panels(rows, wanted, point):
    """One panel per error-measured case (S7 and S8 have no error), one series per method and path (plain: dashed),
    in the CSV's order; `wanted` picks the rows, `point` gives a row's (x, y)."""
    panels = {}
    for row in rows:
        if not row['err'] or row['status'] != 'ok' or not wanted(row):
            continue
        panel = panels.setdefault(row['case'], Panel(row.get('label') or row['case']))
        plain = row['path'] == 'plain'
        name = row['method'] + (' plain' if plain else '')
        series = next((s for s in panel.series if s.name == name), None)
        if series is None:
            series = Series(name, COLORS.get(row['method'], 'black'), plain)
            panel.series.append(series)
        x, y = point(row)
        if x > 0 and y > 0 and math.isfinite(x) and math.isfinite(y):
            series.points.append((x, y))
    return list(panels.values())


def draw_panel(ax, panel, labels, diagonal):
    ax.set_title(panel.title, loc='left', fontweight='bold', fontsize=8.5)
    points = [p for s in panel.series for p in s.points]
    if not points:
        ax.set_axis_off()
        return
    xa, xb = decades([x for x, _ in points])
    ya, yb = decades([y for _, y in points])
    ax.set(xscale='log', yscale='log', xlim=(10.0 ** xa, 10.0 ** xb), ylim=(10.0 ** ya, 10.0 ** yb),
           xlabel=labels[0], ylabel=labels[1])
    ax.grid(True, which='major', color='#e4e4e4', linewidth=0.6)
    if diagonal and max(xa, ya) < min(xb, yb):  # y = x where both axes cover it
        ends = [10.0 ** max(xa, ya), 10.0 ** min(xb, yb)]
        ax.plot(ends, ends, color='#888', linestyle=(0, (5, 4)), linewidth=1)
    for s in panel.series:
        if s.points:
            xs, ys = zip(*s.points)
            ax.plot(xs, ys, color=s.color, linestyle='--' if s.dashed else '-', linewidth=1.3, marker='o',
                    markersize=2.5, clip_on=False)


def legend_handles(panels, diagonal):
    """One legend for every panel, in order of first appearance."""
    seen = {}
    for s in (s for p in panels for s in p.series):
        seen.setdefault(s.name, s)
    handles = [Line2D([], [], color=s.color, linestyle='--' if s.dashed else '-', linewidth=2, marker='o',
                      markersize=3, label=s.name) for s in seen.values()]
    if diagonal:
        handles.append(Line2D([], [], color='#888', linestyle=(0, (5, 4)), label='achieved = requested'))
    return handles


def loglog_grid(title, subtitle, labels, panels, columns=4, diagonal=False):
    """A grid of log-log panels under one title, one subtitle saying how to read them, and one legend."""
    cols = min(columns, len(panels)) or columns  # an empty figure keeps the width its title needs
    rows = max(1, -(-len(panels) // cols))
    width = cols * PANEL_W + 0.45
    sub = textwrap.wrap(subtitle, int(width * 15))
    header = 1.05 + 0.16 * len(sub)  # inches: title, subtitle lines, legend, panel titles
    height = header + rows * PANEL_H
    fig, axes = plt.subplots(rows, cols, figsize=(width, height), squeeze=False)
    fig.subplots_adjust(left=0.7 / width, right=1 - 0.15 / width, bottom=0.45 / height, top=1 - header / height,
                        wspace=0.38, hspace=0.55)
    fig.text(0.1 / width, 1 - 0.25 / height, title, fontsize=12, fontweight='bold')
    fig.text(0.1 / width, 1 - 0.42 / height, '\n'.join(sub), fontsize=8.5, color='#333', va='top')
    fig.legend(handles=legend_handles(panels, diagonal), loc='upper left', frameon=False, fontsize=8.5,
               ncol=9 if cols > 2 else 3, bbox_to_anchor=(0.05 / width, 1 - (0.47 + 0.16 * len(sub)) / height),
               handlelength=2.6, columnspacing=1.4)
    if not panels:  # e.g. steps per contact of a run without contacts
        fig.text(0.5, 0.4, 'nothing to draw: no run of this kind in the CSV', ha='center', color='#555')
    for k, ax in enumerate(axes.flat):
        if k < len(panels):
            draw_panel(ax, panels[k], labels, diagonal)
        else:
            ax.remove()
    return fig


def results_figures(rows):
    """work_precision, tolerance_error and steps_per_contact from results.csv."""
    adaptive = lambda r: r['adaptive'] == '1'  # noqa: E731
    err = lambda r: floored(float(r['err']))  # noqa: E731
    clamp = 'errors clamped to 1e-14 .. 1e3'
    return {
        'work_precision': loglog_grid(
            'Work-precision: wall time against error',
            'Lower left is better. Error = max(|dp|/R, |dv|/v0) at the end time against the reference (plain path; '
            + clamp + '); dashed: plain path.', ('error', 'wall time (s), median'),
            result_panels(rows, lambda r: True, lambda r: (err(r), float(r['wall_s'])))),
        'tolerance_error': loglog_grid(
            'Achieved error against requested tolerance (adaptive methods)',
            'On or below the dashed line: the tolerance is a trustworthy knob. Far above it: error control is fooled '
            '(contact onsets, friction switch). ' + clamp.capitalize() + '; dashed lines: plain path.',
            ('requested tolerance', 'achieved error'),
            result_panels(rows, adaptive, lambda r: (float(r['setting']), err(r))), diagonal=True),
        'steps_per_contact': loglog_grid(
            'Integrator steps per contact (ball-ball and cushion contacts; the thesis reports '
            '20-60)', 'Mean number of steps overlapping each contact. Fewer is cheaper, but a contact needs enough '
            'steps to resolve its force pulse. Dashed: plain path.', ('requested tolerance', 'steps per contact'),
            result_panels(rows, lambda r: adaptive(r) and int(r['contacts']) > 0,
                          lambda r: (float(r['setting']), float(r['steps_per_contact'])))),
    }


def scaling_figure(rows):
    """scaling_scenes from scaling.csv: n resting balls and one moving ball, both paths."""
    def paths():
        return [Series('fast path', '#1f77b4'), Series('plain path', '#1f77b4', True)]
    total, per_rhs = Panel('wall time of the run', paths()), Panel('wall time per rhs evaluation', paths())
    for r in rows:
        k, n, wall = int(r['path'] == 'plain'), float(r['resting_balls']), float(r['wall_s'])
        total.series[k].points.append((n, wall))
        per_rhs.series[k].points.append((n, wall / float(r['rhs'])))
    return loglog_grid('n resting balls and one moving ball, to rest',
                       'The moving ball rolls at 0.5 m/s into one resting ball; the rest are never touched. Dashed: '
                       'plain path.', ('resting balls', 'seconds, inside advance()'), [total, per_rhs], columns=2)


def rhs_figure(rows):
    """scaling_rhs from scaling_rhs.csv: one right-hand-side call against n, with the O(n) line through the first n."""
    calls = sorted((float(r['balls']), float(r['seconds_per_call'])) for r in rows)
    n0, s0 = calls[0]
    per_call = Panel('cost of one rhs call', [Series('measured', '#1f77b4'),
                                              Series('O(n) from n = %g' % n0, '#888', True)])
    per_ball = Panel('cost per ball', [Series('measured', '#1f77b4')])
    for n, s in calls:
        per_call.series[0].points.append((n, s))
        per_call.series[1].points.append((n, s0 * n / n0))
        per_ball.series[0].points.append((n, s / n))
    return loglog_grid('Right-hand side cost against ball count (rhs_benchmark)',
                       'Balls scattered over a flat bed at constant density, all sliding. Linear in n: on the dashed '
                       'line, flat per ball.', ('balls', 'seconds'), [per_call, per_ball], columns=2)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    parser.add_argument('dir', help='directory with results.csv, scaling.csv or scaling_rhs.csv')
    parser.add_argument('--png', action='store_true', help='also write each figure as PNG')
    a = parser.parse_args()
    makers = [('results.csv', results_figures), ('scaling.csv', lambda rows: {'scaling_scenes': scaling_figure(rows)}),
              ('scaling_rhs.csv', lambda rows: {'scaling_rhs': rhs_figure(rows)})]
    written = []
    for name, make in makers:
        source = os.path.join(a.dir, name)
        if not os.path.exists(source):
            continue
        try:
            figures = make(read_csv(source))
        except (KeyError, ValueError, IndexError) as e:
            sys.exit('bench_plots.py: %s: not a bench CSV (%s: %s)' % (source, type(e).__name__, e))
        for stem, fig in figures.items():
            for ext in ('svg', 'png') if a.png else ('svg',):
                fig.savefig(os.path.join(a.dir, stem + '.' + ext), dpi=110, metadata={'Date': None} if ext == 'svg'
                            else {'Software': None})
                written.append(stem + '.' + ext)
            plt.close(fig)
    if not written:
        sys.exit('bench_plots.py: %s: no results.csv, scaling.csv or scaling_rhs.csv' % a.dir)
    print('bench_plots.py: wrote %s in %s' % (', '.join(written), a.dir))


if __name__ == '__main__':
    main()
