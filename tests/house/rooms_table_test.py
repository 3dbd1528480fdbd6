#!/usr/bin/env python3
"""The rooms table in docs/architecture.md (under "## The app's rooms": a row per room, `| `session/`
| ... | util |`) says what the includes say (issue 56): each row's "depends on" set is the set of
rooms its files include, as tests/house/include_cycles_test.py reads them ("(core only)": none).
Fails, naming the row's line, the room and the difference (a dependency missing, with the include
that makes it, or one too many, that no include makes), when they differ; when a room under app/
has no row, or a row or its "depends on" names no room; when a room has two rows. Fails too when
it reads fewer than MIN #include lines between rooms (default 80), like include_cycles_test.py.
Usage:
  rooms_table_test.py ROOT [--min-includes MIN]
  rooms_table_test.py --self-test   (runs itself on tests/house/fixtures/rooms_table/, whose table
      leaves out a dependency, adds one, has a row for no room and none for one room, and expects
      it to fail naming each)"""
import pathlib
import re
import subprocess
import sys

from house_check import self_test_verdict, take_floor

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from include_cycles_test import read_rooms  # noqa: E402  (the same reading of the includes)

FIXTURE = pathlib.Path(__file__).resolve().parent / "fixtures" / "rooms_table"
DOCUMENT = "docs/architecture.md"
HEADING = "## The app's rooms"


def self_test():
    """Runs this check on the fixture; exit 0 when it failed as it should, naming each planted defect."""
    p = subprocess.run([sys.executable, __file__, str(FIXTURE), "--min-includes", "2"],
                       capture_output=True, text=True)
    out = p.stdout + p.stderr
    print(f"$ rooms_table_test.py tests/house/fixtures/rooms_table --min-includes 2  -> exit {p.returncode}")
    print(out, end="")
    problems = []
    if p.returncode == 0:
        problems.append("the planted table passed")
    for want in ('docs/architecture.md:7: alpha/ depends on beta by its includes; the table says (core only): '
                 'beta missing (app/alpha/alpha.hpp includes "beta/beta.hpp")',
                 "docs/architecture.md:8: beta/ depends on nothing by its includes; the table says alpha, omega: "
                 'alpha too many (no file in app/beta/ includes "alpha/...")',
                 "docs/architecture.md:8: beta/'s \"depends on\" names omega, which is no room",
                 "docs/architecture.md:9: the row for gamma/ names no room (no folder app/gamma/)",
                 "docs/architecture.md: the rooms table has no row for delta/ (it depends on beta)"):
        if want not in out:
            problems.append(f"not said: {want}")
    self_test_verdict(problems, "the check fails on each planted difference")


def read_table(path):
    """The rows of the table under HEADING: [(line, room cell, depends-on cell)]."""
    rows, in_section, columns = [], False, None
    for number, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1):
        if line.startswith("#"):
            if in_section and rows:
                break
            in_section = line.strip() == HEADING
            continue
        if not in_section:
            continue
        if not line.startswith("|"):
            if rows:
                break  # the table's end
            continue
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if columns is None:  # the header: which columns are the room and its dependencies
            names = [c.lower() for c in cells]
            if "room" not in names or "depends on" not in names:
                return None, f"{DOCUMENT}:{number}: the rooms table's header has no 'room' or 'depends on' column"
            columns = (names.index("room"), names.index("depends on"), len(cells))
            continue
        if set(line) <= set("|-: "):
            continue  # the header's rule
        if len(cells) != columns[2]:
            return None, f"{DOCUMENT}:{number}: a row of {len(cells)} cells, not {columns[2]} (a '|' in a cell?)"
        rows.append((number, cells[columns[0]], cells[columns[1]]))
    return rows, None


def main():
    args = sys.argv[1:]
    if args == ["--self-test"]:
        self_test()
    min_includes = take_floor(args, "--min-includes", 80)
    project = pathlib.Path(args[0] if args else ".")
    rooms, edges, files_read, includes_read = read_rooms(project)
    depends = {r: {b for (a, b) in edges if a == r} for r in rooms}

    failures = []
    rows, problem = read_table(project / DOCUMENT)
    if problem:
        failures.append(problem)
        rows = []
    elif not rows:
        failures.append(f"{DOCUMENT}: no table under '{HEADING}'")
    seen = {}
    for number, room_cell, depends_cell in rows:
        where = f"{DOCUMENT}:{number}"
        m = re.fullmatch(r"`([a-z_]+)/`", room_cell)
        if not m:
            failures.append(f"{where}: the row's room {room_cell!r} is not a folder written `room/`")
            continue
        room = m.group(1)
        if room not in rooms:
            failures.append(f"{where}: the row for {room}/ names no room (no folder app/{room}/)")
            continue
        if room in seen:
            failures.append(f"{where}: a second row for {room}/ (the first is at line {seen[room]})")
            continue
        seen[room] = number
        said = set()
        if depends_cell not in ("(core only)", ""):
            for word in (w.strip() for w in depends_cell.split(",")):
                if word in rooms:
                    said.add(word)
                else:
                    failures.append(f"{where}: {room}/'s \"depends on\" names {word}, which is no room")
        if said != depends[room]:
            differences = [f"{b} missing ({edges[(room, b)]})" for b in sorted(depends[room] - said)]
            differences += [f"{b} too many (no file in app/{room}/ includes \"{b}/...\")"
                            for b in sorted(said - depends[room])]
            failures.append(f"{where}: {room}/ depends on {', '.join(sorted(depends[room])) or 'nothing'} by its "
                            f"includes; the table says {depends_cell or 'nothing'}: " + "; ".join(differences))
    for room in sorted(rooms - set(seen)):
        failures.append(f"{DOCUMENT}: the rooms table has no row for {room}/ (it depends on "
                        f"{', '.join(sorted(depends[room])) or 'nothing'})")

    print(f"rooms_table_test: {len(rows)} rows of {DOCUMENT}'s rooms table against {len(rooms)} rooms, "
          f"{len(edges)} dependencies between them ({includes_read} #include lines from one room into another "
          f"read, at least {min_includes} expected)")
    if includes_read < min_includes:
        failures.append(f"too few #include lines between rooms read ({includes_read}, fewer than {min_includes}): "
                        f"is {project} the project's root, or has the reader stopped finding includes?")
    for f in failures:
        print(f)
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
