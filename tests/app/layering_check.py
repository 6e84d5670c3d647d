#!/usr/bin/env python3
"""The engine's public face stays closed: ui/ and app/ include only the engine's public headers, and a public header
includes only other public headers, so nothing of the stepping's internals reaches a user even indirectly.

usage: layering_check.py SOURCE_DIR PUBLIC_HEADER...   (the list is engine/CMakeLists.txt's SHOTLAB_PUBLIC_HEADERS)
"""
import os
import re
import sys

INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.M)


def engine_includes(path, root):
    """The engine headers a file includes, as paths relative to engine/."""
    here = os.path.relpath(os.path.dirname(path), os.path.join(root, 'engine'))
    out = []
    with open(path, encoding='utf-8') as f:
        for name in INCLUDE.findall(f.read()):
            if name.startswith('engine/'):
                out.append(name[len('engine/'):])
            elif not here.startswith('..'):  # an engine file's own relative include
                candidate = os.path.normpath(os.path.join(here, name))
                if os.path.exists(os.path.join(root, 'engine', candidate)):
                    out.append(candidate)
    return out


def main():
    root, public = sys.argv[1], set(sys.argv[2:])
    problems = []
    for header in sorted(public):
        for inc in engine_includes(os.path.join(root, 'engine', header), root):
            if inc not in public:
                problems.append(f'engine/{header} (public) includes engine/{inc}, which is not public')
    for folder in ('ui', 'app'):
        for dirpath, _, files in os.walk(os.path.join(root, folder)):
            for name in sorted(files):
                if name.endswith(('.cpp', '.hpp')):
                    path = os.path.join(dirpath, name)
                    for inc in engine_includes(path, root):
                        if inc not in public:
                            problems.append(f'{os.path.relpath(path, root)} includes engine/{inc}, an engine internal')
    for p in problems:
        print('FAIL', p)
    print(f'layering: {len(public)} public engine headers, {len(problems)} problems')
    return 1 if problems else 0


if __name__ == '__main__':
    sys.exit(main())
