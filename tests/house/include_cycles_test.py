#!/usr/bin/env python3
"""No include cycle between the app's rooms (issue 43): each folder under app/ is a room; a file
in room A that includes "B/..." makes A depend on B. Fails, naming the cycle and the includes
that make it, when the rooms' graph has one. Usage: include_cycles_test.py ROOT."""
import pathlib
import re
import sys

root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else ".") / "app"
rooms = {p.name for p in root.iterdir() if p.is_dir()}
edges = {}  # (a, b) -> first "file includes b/x.hpp" seen
for f in sorted(root.rglob("*")):
    if f.suffix not in (".cpp", ".hpp", ".h") or f.parent == root:
        continue
    a = f.relative_to(root).parts[0]
    for m in re.finditer(r'^#include "([a-z_]+)/[^"]+"', f.read_text(encoding="utf-8"), re.M):
        b = m.group(1)
        if b in rooms and b != a:
            edges.setdefault((a, b), f"{f.relative_to(root.parent)} includes \"{m.group(0)[10:-1]}\"")

graph = {r: sorted(b for (a, b) in edges if a == r) for r in rooms}

# Tarjan's strongly connected components: a component of more than one room is a cycle.
index, low, stack, on, cycles, counter = {}, {}, [], set(), [], [0]


def visit(v):
    index[v] = low[v] = counter[0]
    counter[0] += 1
    stack.append(v)
    on.add(v)
    for w in graph[v]:
        if w not in index:
            visit(w)
            low[v] = min(low[v], low[w])
        elif w in on:
            low[v] = min(low[v], index[w])
    if low[v] == index[v]:
        component = []
        while True:
            w = stack.pop()
            on.discard(w)
            component.append(w)
            if w == v:
                break
        if len(component) > 1:
            cycles.append(sorted(component))


for r in sorted(rooms):
    if r not in index:
        visit(r)

print(f"include_cycles_test: {len(rooms)} rooms, {len(edges)} dependencies between them")
for component in cycles:
    print("include cycle between " + ", ".join(component) + ":")
    for (a, b), why in sorted(edges.items()):
        if a in component and b in component:
            print(f"  {a} -> {b}: {why}")
sys.exit(1 if cycles else 0)
