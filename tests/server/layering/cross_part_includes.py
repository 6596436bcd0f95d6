#!/usr/bin/env python3
"""Every include from one part of server/ into another, counted per pair of
parts, and those a part's links do not allow listed one by one.

The compiler refuses a forbidden include only once it is written; this shows
the whole picture before a change (which parts lean on which, and how much).
A part is a folder of server/ with a CMakeLists.txt; what it may include is
what its target_link_libraries names among the server's parts, and what
those name in turn, except a link set apart under a comment beginning
"# Against the direction" (a debt named where it is taken).

  tests/server/layering/cross_part_includes.py [server dir]
"""
import os
import re
import sys

server = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), '..', '..', '..', 'server')
parts = sorted(d for d in os.listdir(server) if os.path.isfile(os.path.join(server, d, 'CMakeLists.txt')))

links = {}
home = {}  # header -> part
for part in parts:
    text = open(os.path.join(server, part, 'CMakeLists.txt')).read()
    text = re.sub(r'# Against the direction.*\n(?:#.*\n)*[^(]*\([^)]*\)', '', text)
    links[part] = {p for p in re.findall(r'fw(?:::|_)server_(\w+)', text) if p in parts and p != part}
    for name in os.listdir(os.path.join(server, part)):
        home[name] = part


def reachable(part, seen=None):
    seen = set() if seen is None else seen
    for below in links[part]:
        if below not in seen:
            seen.add(below)
            reachable(below, seen)
    return seen


counts = {}
against = []
for part in parts:
    allowed = reachable(part)
    for name in sorted(os.listdir(os.path.join(server, part))):
        if not name.endswith(('.cpp', '.hpp')):
            continue
        for line in open(os.path.join(server, part, name)):
            match = re.match(r'\s*#\s*include\s+"([^"]+)"', line)
            target = home.get(match.group(1)) if match else None
            if target is None or target == part:
                continue
            counts[(part, target)] = counts.get((part, target), 0) + 1
            if target not in allowed:
                against.append(f'{part}/{name} -> {target}/{match.group(1)}')

for (part, target), count in sorted(counts.items()):
    print(f'{part:>11} -> {target:<11} {count}')
print(f'\n{len(against)} against the links:')
for line in against:
    print('  ' + line)
sys.exit(1 if against else 0)
