#!/usr/bin/env python3
"""The bench's figures (scripts/bench_plots.py) and how `shotlab bench` hands its CSV files to it.

    python3 tests/app/bench_plots_check.py SHOTLAB_BINARY SOURCE_DIR

1. The script draws all five figures from tiny CSV files, as SVG (and PNG with --png), and refuses a CSV that is not
   the bench's in one line.
2. `shotlab bench` without a Python that has matplotlib (SHOTLAB_PYTHON=/nonexistent) writes its CSV, says in one line
   how to draw the figures, and exits 0; with one, its figures appear.
Without matplotlib anywhere, part 2's first half runs and the test is skipped (exit 77): scripts/setup.sh installs it.
"""
import os
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET

RESULTS_HEADER = ('case,scene,method,path,adaptive,setting,status,pos_err,vel_err,err,missed,energy_drift,momentum_err,'
                  'wall_s,repeats,steps,rejected,rhs,contacts,steps_per_contact,sim_time_s,tol_ratio_pv,tol_ratio_spin,'
                  'tol_ratio_pv_end,tol_ratio_spin_end,label')
RESULTS_ROWS = [  # case, method, path, adaptive, setting, err, wall_s, contacts, steps_per_contact, label
    ('S1-2-damped', 'euler', 'fast', 0, '1e-4', '1.2e-01', '2e-5', 1, '5.0', 'S1 head-on 2 m/s, damped'),
    ('S1-2-damped', 'euler', 'fast', 0, '1e-5', '1.3e-02', '2e-4', 1, '46.0', 'S1 head-on 2 m/s, damped'),
    ('S1-2-damped', 'cash_karp54', 'fast', 1, '1e-6', '3.1e-07', '3e-5', 1, '18.0', 'S1 head-on 2 m/s, damped'),
    ('S1-2-damped', 'cash_karp54', 'fast', 1, '1e-7', '0.00e+00', '4e-5', 1, '24.0', 'S1 head-on 2 m/s, damped'),
    ('S1-2-damped', 'cash_karp54', 'plain', 1, '1e-6', '3.0e-07', '2e-5', 1, '17.0', 'S1 head-on 2 m/s, damped'),
    ('S1-2-damped', 'cash_karp54', 'plain', 1, '1e-7', '9.2e-09', '3e-5', 1, '24.0', 'S1 head-on 2 m/s, damped'),
    ('S3', 'dopri5', 'fast', 1, '1e-6', '6.6e-15', '6e-6', 0, '0.0', 'S3 stun shot, slide to roll'),
    ('S3', 'dopri5', 'fast', 1, '1e-7', '1.0e+116', '6e-6', 0, '0.0', 'S3 stun shot, slide to roll'),
    ('S7', 'cash_karp54', 'fast', 1, '1e-7', '', '0.0156', 800, '30.0', 'S7 full break to rest'),  # timed only
]
FIGURES = {  # file: a text it must hold
    'work_precision.svg': 'Work-precision', 'tolerance_error.svg': 'achieved = requested',
    'steps_per_contact.svg': 'S1 head-on 2 m/s, damped', 'scaling_scenes.svg': 'plain path',
    'scaling_rhs.svg': 'O(n) from n = 16'}
RESULTS_FIGURES = ['work_precision.svg', 'tolerance_error.svg', 'steps_per_contact.svg']


def fail(message):
    print('FAIL: ' + message)
    sys.exit(1)


def write_csvs(d):
    with open(os.path.join(d, 'results.csv'), 'w') as f:
        f.write(RESULTS_HEADER + '\n')
        for c, m, path, adaptive, setting, err, wall, contacts, spc, label in RESULTS_ROWS:
            f.write(f'{c},{c[:2]},{m},{path},{adaptive},{setting},ok,,,{err},0,,,{wall},3,10,0,60,{contacts},{spc},'
                    f'0.1,,,,,"{label}"\n')
    with open(os.path.join(d, 'scaling.csv'), 'w') as f:
        f.write('resting_balls,path,simulated_s,wall_s,steps,rejected,rhs\n16,fast,3.5,0.00043,316,9,711\n'
                '1000,fast,3.5,0.0005,316,9,711\n16,plain,3.5,0.106,9712,3214,74450\n'
                '1000,plain,3.5,5.7,9712,3214,74450\n')
    with open(os.path.join(d, 'scaling_rhs.csv'), 'w') as f:
        f.write('balls,seconds_per_call\n16,1.03e-06\n100,6.64e-06\n1000,6.72e-05\n')


def check_svg(path, text):
    if not os.path.isfile(path):
        fail(path + ' not written')
    root = ET.parse(path).getroot()
    if not root.tag.endswith('svg'):
        fail(path + ': not an SVG document')
    if text not in ''.join(root.itertext()):
        fail(f'{path}: no "{text}" in its text')


def check_script(python, script, tmp):
    d = os.path.join(tmp, 'tiny')
    os.mkdir(d)
    write_csvs(d)
    r = subprocess.run([python, script, d, '--png'], capture_output=True, text=True, timeout=300)
    if r.returncode != 0:
        fail(f'bench_plots.py on tiny CSVs: status {r.returncode}\n{r.stdout}{r.stderr}')
    for name, text in FIGURES.items():
        check_svg(os.path.join(d, name), text)
        if not os.path.getsize(os.path.join(d, name.replace('.svg', '.png'))):
            fail(name + ': no PNG beside it')
    bad = os.path.join(tmp, 'bad')
    os.mkdir(bad)
    with open(os.path.join(bad, 'results.csv'), 'w') as f:
        f.write('a,b\n1,2\n')
    r = subprocess.run([python, script, bad], capture_output=True, text=True, timeout=300)
    if r.returncode == 0 or 'not a bench CSV' not in r.stderr or len(r.stderr.strip().splitlines()) != 1:
        fail(f'bench_plots.py on a foreign CSV: status {r.returncode}, stderr:\n{r.stderr}')


def run_bench(shotlab, out, python):
    env = dict(os.environ, SHOTLAB_PYTHON=python)
    cmd = [shotlab, 'bench', '--quick', '--scenes', 'S2', '--repeats', '1', '--out-dir', out]
    r = subprocess.run(cmd, capture_output=True, text=True, env=env, timeout=600)
    if r.returncode != 0:
        fail(f'{" ".join(cmd)} with SHOTLAB_PYTHON={python}: status {r.returncode}\n{r.stderr}')
    if not os.path.isfile(os.path.join(out, 'results.csv')):
        fail(out + '/results.csv not written')
    return r


def python_with_matplotlib():
    """The interpreter `shotlab bench` would pick (app/plot_script.cpp), or None."""
    chosen = os.environ.get('SHOTLAB_PYTHON')
    for python in [chosen] if chosen else ['python3', '/usr/bin/python3']:
        try:
            if subprocess.run([python, '-c', 'import matplotlib'], capture_output=True, timeout=120).returncode == 0:
                return python
        except OSError:
            pass
    return None


def main():
    shotlab, source = sys.argv[1], sys.argv[2]
    script = os.path.join(source, 'scripts', 'bench_plots.py')
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, 'no_matplotlib')
        r = run_bench(shotlab, out, '/nonexistent/python3')
        notes = [line for line in r.stderr.splitlines() if 'figures not drawn' in line]
        if len(notes) != 1 or 'bench_plots.py' not in notes[0] or any(n.endswith('.svg') for n in os.listdir(out)):
            fail('without matplotlib: expected one line on how to draw the figures and no SVG; stderr:\n' + r.stderr)
        python = python_with_matplotlib()
        if python is None:
            print('SKIP: no python3 with matplotlib (scripts/setup.sh installs python3-matplotlib)')
            sys.exit(77)
        check_script(python, script, tmp)
        out = os.path.join(tmp, 'with_matplotlib')
        run_bench(shotlab, out, python)
        for name in RESULTS_FIGURES:
            check_svg(os.path.join(out, name), 'S2 glancing cut, offset 0.9')
    print('bench_plots: ok')


if __name__ == '__main__':
    main()
