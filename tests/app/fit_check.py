#!/usr/bin/env python3
"""`shotlab fit` on a shot the engine made, as docs/fit.md suggests for trying it without a tracker: the
three-cushion preset run for 2 s with its trajectory written at 50 Hz, then fitted back from that file. The preset's
strike (3.1 m/s, -33.7 deg, side 0.4 R, height 0.2 R) must come back, and the run's file is read as a measured shot
(its columns by name). A joint fit held to 2 iterations a round counts its steps and warns, also with -q. A file
without the z column is refused by name.

usage: fit_check.py SHOTLAB SOURCE_DIR
"""
import json
import os
import subprocess
import sys
import tempfile


SOLVES = 5  # joint solves at most: kJointRounds (6, engine/io/fit.cpp), each but the last followed by one


def fail(message):
    print('FAIL:', message)
    sys.exit(1)


def run(*args):
    r = subprocess.run(args, capture_output=True, text=True, timeout=600)
    print(' '.join(os.path.basename(a) for a in args[:3]), '->', r.returncode)
    return r


def main():
    shotlab, source = sys.argv[1], sys.argv[2]
    scene = os.path.join(source, 'presets', 'three_cushion.json')
    with tempfile.TemporaryDirectory() as tmp:
        shot, out = os.path.join(tmp, 'shot.csv'), os.path.join(tmp, 'fit.json')
        r = run(shotlab, 'run', scene, '--duration', '2', '--trajectory', shot, '--sample-rate', '50')
        if r.returncode != 0:
            fail(f'run: status {r.returncode}: {r.stderr}')
        r = run(shotlab, 'fit', shot, '--scene', scene, '--jobs', '1', '--out', out)
        if r.returncode != 0:
            fail(f'fit: status {r.returncode}: {r.stderr}')
        with open(out) as f:
            cue = json.load(f)['shots'][0]['cue']
        truth = {'speed': 3.1, 'aim_deg': -33.7, 'side': 0.4, 'height': 0.2}
        for key, value in truth.items():
            if abs(cue[key] - value) > 1e-4:
                fail(f'the fitted {key} is {cue[key]}, the preset strikes at {value}')
        print('recovered', {k: round(cue[k], 6) for k in truth})
        # A shot made with more rolling resistance than the scene's, fitted with it held to 2 iterations a round: the
        # count is the rounds' steps, and -q still warns that the last round stopped short.
        slower = os.path.join(tmp, 'slower.csv')
        r = run(shotlab, 'run', scene, '--duration', '2', '--trajectory', slower, '--sample-rate', '50',
                '--set', 'materials.ball_cloth.rolling_resistance=0.006')
        if r.returncode != 0:
            fail(f'run: status {r.returncode}: {r.stderr}')
        r = run(shotlab, 'fit', slower, '--scene', scene, '--fit', 'materials.ball_cloth.rolling_resistance',
                '--iterations', '2', '-q', '--out', out)
        with open(out) as f:
            iterations = json.load(f)['iterations']
        if r.returncode != 0 or 'stopped at 2 iterations before it converged' not in r.stderr:
            fail(f'a fit held to 2 iterations: status {r.returncode}, said {r.stderr!r}')
        if not 0 < iterations <= 2 * SOLVES:
            fail(f'{iterations} iterations for at most {SOLVES} joint solves of 2')
        with open(shot) as f:
            lines = f.read().splitlines()
        bad = os.path.join(tmp, 'no_z.csv')
        with open(bad, 'w') as f:
            f.write('\n'.join([lines[0].replace(',z,', ',depth,')] + lines[1:]) + '\n')
        r = run(shotlab, 'fit', bad, '--scene', scene, '--out', out)
        if r.returncode != 1 or "no_z.csv: line 1: the header names no column 'z'" not in r.stderr:
            fail(f'a file without z: status {r.returncode}, said {r.stderr!r}')
    print('ok')


if __name__ == '__main__':
    main()
