#!/usr/bin/env python3
"""No include cycle between the app's rooms (issue 43): each folder under app/ is a room; a file
in room A that includes "B/..." makes A depend on B. Fails, naming the cycle and the includes
that make it, when the rooms' graph has one. Fails too when it reads fewer than MIN #include lines
from one room into another (default 80; the app has about 160), so that a reader that finds no
include cannot pass. Usage:
  include_cycles_test.py ROOT [--min-includes MIN]
  include_cycles_test.py --self-test   (runs itself on tests/house/fixtures/include_cycles/, where
      app/alpha/alpha.hpp and app/beta/beta.hpp include each other, and expects it to fail naming
      that cycle; and with the default floor, and expects it to fail for reading too few)"""
import pathlib
import re
import subprocess
import sys

from house_check import self_test_verdict, take_floor

FIXTURE = pathlib.Path(__file__).resolve().parent / "fixtures" / "include_cycles"


def self_test():
    """Runs this check on the fixture; exit 0 when it failed as it should."""
    def run(*args):
        p = subprocess.run([sys.executable, __file__, str(FIXTURE), *args], capture_output=True, text=True)
        print(f"$ include_cycles_test.py {FIXTURE.relative_to(FIXTURE.parents[3])} {' '.join(args)}  -> exit {p.returncode}")
        print(p.stdout + p.stderr, end="")
        return p.returncode, p.stdout + p.stderr
    problems = []
    rc, out = run("--min-includes", "3")
    if rc == 0:
        problems.append("the planted cycle passed")
    for want in ("include cycle between alpha, beta:",
                 'alpha -> beta: app/alpha/alpha.hpp includes "beta/beta.hpp"',
                 'beta -> alpha: app/beta/beta.hpp includes "alpha/alpha.hpp"'):
        if want not in out:
            problems.append(f"not said: {want}")
    if "gamma" in out.split("include cycle", 1)[-1]:
        problems.append("gamma, which only uses alpha, was named in a cycle")
    rc, out = run()  # the default floor: the fixture's 3 includes are too few
    if rc == 0 or "too few" not in out:
        problems.append("reading the fixture's 3 includes passed the default floor")
    self_test_verdict(problems, "the check fails on the planted cycle and on too few read")


def read_rooms(project):
    """The app's rooms and the dependencies between them: (rooms, edges, files_read, includes_read),
    edges mapping (a, b) to the first 'file includes "b/..."' seen. Shared with rooms_table_test.py."""
    root = pathlib.Path(project) / "app"
    rooms = {p.name for p in root.iterdir() if p.is_dir()} if root.is_dir() else set()
    edges = {}  # (a, b) -> first "file includes b/..." seen
    files_read = includes_read = 0  # includes_read: #include lines from one room into another
    for f in sorted(root.rglob("*")):
        if f.suffix not in (".cpp", ".hpp", ".h") or f.parent == root:
            continue
        files_read += 1
        a = f.relative_to(root).parts[0]
        for m in re.finditer(r'^#include "([a-z_]+)/[^"]+"', f.read_text(encoding="utf-8"), re.M):
            b = m.group(1)
            if b in rooms and b != a:
                includes_read += 1
                edges.setdefault((a, b), f"{f.relative_to(root.parent)} includes \"{m.group(0)[10:-1]}\"")
    return rooms, edges, files_read, includes_read


def find_cycles(rooms, edges):
    """Tarjan's strongly connected components: a component of more than one room is a cycle."""
    graph = {r: sorted(b for (a, b) in edges if a == r) for r in rooms}
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
    return cycles


def main():
    args = sys.argv[1:]
    if args == ["--self-test"]:
        self_test()
    min_includes = take_floor(args, "--min-includes", 80)
    project = pathlib.Path(args[0] if args else ".")
    rooms, edges, files_read, includes_read = read_rooms(project)
    cycles = find_cycles(rooms, edges)

    print(f"include_cycles_test: {files_read} files in {len(rooms)} rooms read, {includes_read} #include lines from "
          f"one room into another (at least {min_includes} expected), {len(edges)} dependencies between rooms")
    for component in cycles:
        print("include cycle between " + ", ".join(component) + ":")
        for (a, b), why in sorted(edges.items()):
            if a in component and b in component:
                print(f"  {a} -> {b}: {why}")
    too_few = includes_read < min_includes
    if too_few:
        print(f"too few #include lines between rooms read ({includes_read}, fewer than {min_includes}): is "
              f"{project} the project's root, or has the reader stopped finding includes?")
    sys.exit(1 if cycles or too_few else 0)


if __name__ == "__main__":
    main()
