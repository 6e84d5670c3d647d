#!/usr/bin/env python3
"""The command line fuzzer: shotlab started with random arguments, as a user's typos and scripts produce them.

Every option of `shotlab run`, `shotlab sweep`, `shotlab bench` and the GUI (started with no display, so it checks and explains) is
given values from a list of good, odd and broken ones; tokens are mangled at random. Each case must end on its own
(no hang) with status 0, 1 or 3 as docs/scene-format.md says, never by a signal or a sanitizer report; a refusal
(status 1) says why on stderr in a few lines and leaves an existing output file as it was; a success writes what it
was asked to; no preset changes.

usage: cli_fuzz.py SHOTLAB SOURCE_DIR    (SHOTLAB_FUZZ_SEED, SHOTLAB_FUZZ_CASES: default 1 and 300)
A longer run: docs/testing.md.
"""
import hashlib
import json
import os
import random
import subprocess
import sys
import tempfile
import time

TIMEOUT_S = 90  # per case; a sanitizer build runs the longest valid case (the cradle for 20 s) in about 5 s
KEEP = b'{"kept": true}\n'


def tree_hash(root):
    h = hashlib.sha256()
    for dirpath, _, files in sorted(os.walk(root)):
        for name in sorted(files):
            path = os.path.join(dirpath, name)
            h.update(path.encode())
            with open(path, 'rb') as f:
                h.update(f.read())
    return h.hexdigest()


class Vocabulary:
    """Values for each option: good ones (kept short so a valid run ends in seconds), odd ones, broken ones."""

    def __init__(self, src, tmp):
        presets = os.path.join(src, 'presets')
        good = sorted(os.path.join(presets, f) for f in os.listdir(presets) if f.endswith('.json'))
        os.makedirs(os.path.join(tmp, 'dir'), exist_ok=True)
        with open(os.path.join(tmp, 'empty.json'), 'wb'):
            pass
        with open(os.path.join(tmp, 'bad.json'), 'wb') as f:
            f.write(b'{"balls": [ {"id": "cue", ')
        odd = os.path.join(tmp.encode(), b'odd\xe9name.json')  # a Latin-1 byte in a UTF-8 system's path
        with open(good[0], 'rb') as f, open(odd, 'wb') as g:
            g.write(f.read())
        self.tmp = tmp
        self.scenes = good + [os.path.join(presets, 'bench', 's8_break.json'), os.path.join(tmp, 'missing.json'),
                              os.path.join(tmp, 'dir'), '/dev/zero', '/dev/null', os.path.join(tmp, 'empty.json'),
                              os.path.join(tmp, 'bad.json'), odd, 'x' * 5000, '',
                              '-', b'\xff\xfe.json']
        self.durations = ['0', '1e-9', '0.5', '2', '20', '3600.1', '1e9', '-1', 'nan', 'inf', '-inf', '1e400',
                          '1e-400', '', 'abc', '0x10', '1,5', ' 2', '1.6e17']
        self.rates = ['0.001', '1', '60', '1000', '100001', '1e9', '0', '-1', 'nan', 'inf', '1e-300', '1e19', 'abc', '']
        self.max_samples = ['0', '-5', '10', '1000', 'abc', '1e400', '18446744073709551616', '1000000', '']
        self.set_paths = ['duration', 'balls[0].mass', 'balls[0].position', 'balls.cue.velocity', 'balls[99].id',
                          'rack.rows', 'rack.seed', 'materials.ball_ball.stiffness', 'integrator.method',
                          'integrator.max_steps_per_call', 'table.length', 'cue.speed', 'cue.side', '.', 'a..b',
                          'balls[-1]', 'balls[99999999999999999999999].mass', 'gravity', '']
        self.set_values = ['1', '-1', '0', '1e400', 'nan', '[1,2,3]', '{}', '{bad', '"s"', 'rk4', 'null', 'true',
                           '18446744073709551616', b'\xff', '[' * 200 + ']' * 200, '{"a":1,"a":2}', '']
        self.sizes = ['-5', '0', '100', '800', '100000', 'abc', '', '1e3']
        self.bench_bad = [['--repeats', '0'], ['--repeats', '101'], ['--repeats', 'abc'], ['--budget', 'nan'],
                          ['--budget', '-1'], ['--budget', 'inf'], ['--budget', '1e400'], ['--scenes', 'S99'],
                          ['--scenes', 'S1,S99'], ['--out-dir', '/dev/null/x'], ['--out-dir', os.path.join(tmp, 'keep')],
                          ['--bogus']]
        self.bench_good = [['--quick'], ['--scenes', 'S1'], ['--repeats', '1'], ['--budget', '0.01'],
                           ['--out-dir', os.path.join(tmp, 'bench')]]

        self.vary_values = ['1,2', '0.5:3:3', '[1,2]', '1:2', '2:1:2', 'rk4,dopri5', '[[1,0,0],[0,0,1]]', '1,,2',
                            '0:1:20000000', '1:x:3', '', 'nan', '1e400:1:2', '"a,b",c', b'\xff,1']
        self.sweep_options = [['--samples', '2'], ['--samples', '0'], ['--samples', '-1'], ['--samples', 'abc'],
                              ['--samples', '18446744073709551616'], ['--samples', '20000000'], ['--seed', '7'],
                              ['--seed', '-3'], ['--jobs', '2'], ['--jobs', '0'], ['--jobs', '-1'], ['--jobs', '5000'],
                              ['--timeout', '0'], ['--timeout', 'nan'], ['--max-events', '10'],
                              ['--max-events', '-1'], ['-q']]

    def output(self, rng, kind):
        return rng.choice([os.path.join(self.tmp, 'keep'), os.path.join(self.tmp, 'new.' + kind), '/dev/null',
                           '/dev/full', os.path.join(self.tmp, 'dir'), os.path.join(self.tmp, 'missing', 'x'), '',
                           os.path.join(self.tmp, 'new.' + kind)])


def run_args(rng, v):
    args = ['run', rng.choice(v.scenes)]
    for _ in range(rng.randrange(0, 5)):
        option = rng.choice(['--duration', '--set', '--out', '--trajectory', '--sample-rate', '--max-samples',
                             '--until-rest', '-q'])
        if option == '--duration':
            args += [option, rng.choice(v.durations)]
        elif option == '--set':
            value = rng.choice(v.set_values)
            path = rng.choice(v.set_paths)
            args += [option, path.encode() + b'=' + (value if isinstance(value, bytes) else value.encode())]
        elif option in ('--out', '--trajectory'):
            args += [option, v.output(rng, 'json' if option == '--out' else 'csv')]
        elif option == '--sample-rate':
            args += [option, rng.choice(v.rates)]
        elif option == '--max-samples':
            args += [option, rng.choice(v.max_samples)]
        else:
            args.append(option)
    return args


def sweep_args(rng, v):
    # Runs are cut at 2 s of wall time (a later --timeout may change it) so that a valid sweep of a few runs ends soon.
    args = ['sweep', rng.choice(v.scenes), '--timeout', '2']
    for _ in range(rng.randrange(1, 3)):
        value = rng.choice(v.vary_values)
        path = rng.choice(v.set_paths)
        args += ['--vary', path.encode() + b'=' + (value if isinstance(value, bytes) else value.encode())]
    for _ in range(rng.randrange(0, 4)):
        option = rng.choice(['--set', '--out', '--duration', 'other'])
        if option == '--set':
            value = rng.choice(v.set_values)
            args += [option, rng.choice(v.set_paths).encode() + b'=' + (value if isinstance(value, bytes) else value.encode())]
        elif option == '--out':
            args += [option, v.output(rng, 'csv')]
        elif option == '--duration':
            args += [option, rng.choice(v.durations)]
        else:
            args += rng.choice(v.sweep_options)
    return args


def bench_args(rng, v):
    # Always one bad option: a valid bench runs for minutes, which is not what this test is about.
    parts = [rng.choice(v.bench_bad)] + rng.sample(v.bench_good, rng.randrange(0, 3))
    rng.shuffle(parts)
    return ['bench'] + [a for p in parts for a in p]


def gui_args(rng, v):
    args = []
    for _ in range(rng.randrange(0, 4)):
        option = rng.choice(['--scene', '--script', '--width', '--height', '--dump-state'])
        if option in ('--width', '--height'):
            args += [option, rng.choice(v.sizes)]
        elif option == '--dump-state':
            args += [option, v.output(rng, 'json')]
        else:
            args += [option, rng.choice(v.scenes)]
    return args


def mangle(rng, args):
    """Breaks one token: a byte changed, cut short, doubled, or an unknown option or a stray value added."""
    if not args or rng.random() < 0.6:
        return args
    k = rng.randrange(len(args))
    token = args[k] if isinstance(args[k], bytes) else args[k].encode()
    how = rng.randrange(5)
    if how == 0 and token:
        i = rng.randrange(len(token))
        token = token[:i] + bytes([rng.randrange(1, 256)]) + token[i + 1:]
    elif how == 1:
        token = token[:rng.randrange(len(token) + 1)]
    elif how == 2:
        return args[:k + 1] + args[k:]
    elif how == 3:
        return args[:k] + [rng.choice(['--bogus', '--', '-', '--help', '--duration', 'extra'])] + args[k:]
    else:
        return args[:k]  # an option left without its value, or a command without its scene
    return args[:k] + [token] + args[k + 1:]


def last_value(args, option):
    value = None
    for a, b in zip(args, args[1:]):
        if a == option:
            value = b
    return value


def check(args, proc, v):
    """The problems with one case's outcome (an empty list when it behaved)."""
    problems = []
    err = proc.stderr.decode('utf-8', 'replace')
    if proc.returncode < 0:
        problems.append(f'killed by signal {-proc.returncode}')
    elif proc.returncode not in (0, 1, 3):
        problems.append(f'exit status {proc.returncode} (documented: 0, 1, 3)')
    if 'Sanitizer' in err or 'runtime error:' in err:
        problems.append('sanitizer report')
    if proc.returncode == 1:
        longest = max((len(a) for a in args), default=0)
        if not err.strip():
            problems.append('refused without a message on stderr')
        elif len(err) > 2 * longest + 3000:
            problems.append(f'a refusal of {len(err)} characters')
        with open(os.path.join(v.tmp, 'keep'), 'rb') as f:
            if f.read() != KEEP:
                problems.append('a refused run changed an existing output file')
    if proc.returncode == 0 and args and args[0] == 'run' and '--help' not in args:  # help: prints, runs nothing
        out = last_value(args, '--out')
        if out == os.path.join(v.tmp, 'new.json'):
            try:
                with open(out) as f:
                    json.load(f)
            except (OSError, ValueError) as e:
                problems.append(f'status 0 but --out is not a JSON result: {e}')
        trajectory = last_value(args, '--trajectory')
        if trajectory == os.path.join(v.tmp, 'new.csv'):
            with open(trajectory, 'rb') as f:
                if not f.readline().startswith(b'time,ball,'):
                    problems.append('status 0 but --trajectory has no header')
    if proc.returncode == 0 and args and args[0] == 'sweep' and '--help' not in args:
        out = last_value(args, '--out')
        if out == os.path.join(v.tmp, 'new.csv'):
            with open(out, 'rb') as f:
                if not f.readline().startswith(b'run,'):
                    problems.append('status 0 but the sweep --out has no header')
    return problems


def main():
    shotlab, src = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
    seed = int(os.environ.get('SHOTLAB_FUZZ_SEED') or 1)
    cases = int(os.environ.get('SHOTLAB_FUZZ_CASES') or 300)
    rng = random.Random(seed)
    env = {k: val for k, val in os.environ.items() if k not in ('DISPLAY', 'WAYLAND_DISPLAY')}
    env['ASAN_OPTIONS'] = env.get('ASAN_OPTIONS', '') + ':exitcode=86'
    env['UBSAN_OPTIONS'] = env.get('UBSAN_OPTIONS', '') + ':exitcode=87:print_stacktrace=1'
    presets_before = tree_hash(os.path.join(src, 'presets'))
    counts, failures, slowest = {}, [], (0.0, None)
    with tempfile.TemporaryDirectory(prefix='shotlab-cli-fuzz-') as tmp:
        env['HOME'] = env['XDG_CONFIG_HOME'] = tmp  # settings, if any command wrote them, stay here
        v = Vocabulary(src, tmp)
        for case in range(cases):
            for name in ('new.json', 'new.csv'):
                if os.path.exists(os.path.join(tmp, name)):
                    os.remove(os.path.join(tmp, name))
            with open(os.path.join(tmp, 'keep'), 'wb') as f:
                f.write(KEEP)
            maker = rng.choices([run_args, sweep_args, bench_args, gui_args], weights=[6, 3, 1, 2])[0]
            args = maker(rng, v)
            if maker is not bench_args:  # a bench keeps its bad option: a valid one runs for minutes
                args = mangle(rng, args)
            shown = ' '.join(repr(a) if isinstance(a, bytes) or ' ' in a or not a else a for a in args)[:600]
            t0 = time.monotonic()
            try:
                proc = subprocess.run([shotlab] + args, cwd=tmp, env=env, stdin=subprocess.DEVNULL,
                                      capture_output=True, timeout=TIMEOUT_S)
            except subprocess.TimeoutExpired:
                failures.append(f'case {case}: shotlab {shown}\n  hang: no end within {TIMEOUT_S} s')
                continue
            elapsed = time.monotonic() - t0
            slowest = max(slowest, (elapsed, shown))
            counts[proc.returncode] = counts.get(proc.returncode, 0) + 1
            for p in check(args, proc, v):
                tail = proc.stderr.decode('utf-8', 'replace')[-800:]
                failures.append(f'case {case}: shotlab {shown}\n  {p}\n  stderr: {tail}')
    if tree_hash(os.path.join(src, 'presets')) != presets_before:
        failures.append('a preset file changed')
    summary = ', '.join(f'status {k}: {n}' for k, n in sorted(counts.items()))
    print(f'cli fuzz: seed {seed}, {cases} cases ({summary}); slowest {slowest[0]:.2f} s: shotlab {slowest[1]}')
    for f in failures:
        print('FAIL', f)
    return 1 if failures else 0


if __name__ == '__main__':
    sys.exit(main())
