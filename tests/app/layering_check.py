#!/usr/bin/env python3
"""The engine's public face stays closed: ui/ and app/ include the engine only through its public headers
(engine/include/shotlab/, included as "shotlab/..."), and a public header includes only other public headers, so
nothing of the stepping's internals reaches a user even indirectly.

usage: layering_check.py SOURCE_DIR
"""
import os
import re
import sys

INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.M)


def includes(path):
    with open(path, encoding='utf-8') as f:
        return INCLUDE.findall(f.read())


def sources(folder):
    for dirpath, _, files in os.walk(folder):
        for name in sorted(files):
            if name.endswith(('.cpp', '.hpp', '.h')):
                yield os.path.join(dirpath, name)


def main():
    root = sys.argv[1]
    public_dir = os.path.join(root, 'engine', 'include', 'shotlab')
    public = {os.path.relpath(p, public_dir) for p in sources(public_dir)}
    problems = []
    for path in sources(public_dir):
        for name in includes(path):
            if not (name.startswith('shotlab/') and name[len('shotlab/'):] in public):
                problems.append(f'{os.path.relpath(path, root)} (public) includes "{name}", which is not public')
    for folder in ('ui', 'app'):
        for path in sources(os.path.join(root, folder)):
            for name in includes(path):
                if name.startswith('engine/'):
                    problems.append(f'{os.path.relpath(path, root)} includes "{name}", an engine internal')
                elif name.startswith('shotlab/') and name[len('shotlab/'):] not in public:
                    problems.append(f'{os.path.relpath(path, root)} includes "{name}", which does not exist')
    for p in problems:
        print('FAIL', p)
    print(f'layering: {len(public)} public engine headers, {len(problems)} problems')
    return 1 if problems else 0


if __name__ == '__main__':
    sys.exit(main())
