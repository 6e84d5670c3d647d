#!/usr/bin/env python3
"""`shotlab margin` as the docs run it: the cut preset's margin with a map, written as JSON, CSV and a picture; bad
goals refused with a message and no file touched.

usage: margin_check.py SHOTLAB SOURCE_DIR
"""
import csv
import json
import os
import subprocess
import sys
import tempfile


def fail(message):
    print('FAIL:', message)
    sys.exit(1)


def main():
    shotlab, source = sys.argv[1], sys.argv[2]
    cut = os.path.join(source, 'presets', 'cut.json')
    with tempfile.TemporaryDirectory() as tmp:
        out, rows, picture = (os.path.join(tmp, n) for n in ('m.json', 'm.csv', 'm.svg'))
        r = subprocess.run([shotlab, 'margin', cut, '--goal', 'pocket:1@pocket-right-front', '--level', 'pro',
                            '--samples', '40', '--map', '6x4', '--out', out, '--csv', rows, '--picture', picture],
                           capture_output=True, text=True, timeout=600)
        if r.returncode != 0:
            fail(f'status {r.returncode}: {r.stderr}')
        if 'success' not in r.stdout or 'aim_deg' not in r.stdout:
            fail('no summary: ' + r.stdout)
        m = json.load(open(out))
        if not (0 < m['probability'] < 1) or not m['nominal_success']:
            fail(f"the cut preset pots at its intended stroke and sometimes misses under noise: {m['probability']}")
        if len(m['map']['success']) != 4 or len(m['map']['success'][0]) != 6:
            fail('the map is 4 speeds x 6 aims')
        with open(rows, newline='') as f:
            table = list(csv.DictReader(f))
        if len(table) != 40 or abs(sum(int(t['success']) for t in table) / 40 - m['probability']) > 1e-12:
            fail('the CSV has one row per replay and the same successes')
        text = open(picture).read() if os.path.exists(picture) else ''
        if '<svg' not in text:
            print('note: no picture (no python3 with matplotlib): ' + r.stderr.strip())
        with open(out, 'w') as f:
            f.write('kept')
        bad = subprocess.run([shotlab, 'margin', cut, '--goal', 'pocket:99', '--out', out], capture_output=True,
                             text=True, timeout=60)
        if bad.returncode != 1 or 'no ball "99"' not in bad.stderr:
            fail(f'a goal naming no ball: status {bad.returncode}, {bad.stderr}')
        if open(out).read() != 'kept':
            fail('a refused margin changed its --out file')
        # A misspelt pocket (a user trial's: front-right for right-front) is refused, not judged as a miss.
        bad = subprocess.run([shotlab, 'margin', cut, '--goal', 'pocket:1@pocket-front-right', '--out', out],
                             capture_output=True, text=True, timeout=60)
        if bad.returncode != 1 or 'no pocket "pocket-front-right"' not in bad.stderr or 'pocket-right-front' not in bad.stderr:
            fail(f'a goal naming no pocket: status {bad.returncode}, {bad.stderr}')
        if open(out).read() != 'kept':
            fail('a margin refused for its pocket changed its --out file')
    print('margin: ok')


if __name__ == '__main__':
    main()
