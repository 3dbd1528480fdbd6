#!/usr/bin/env python3
"""No dead functions (issue 58): every function declared or defined in core/ and app/ is mentioned
somewhere besides its own declarations and definitions, in the C++ of core/, app/, python/src/,
tests/, bench/ or examples/, or in the browser's JavaScript and HTML and the CMake lists (where
emscripten's exports are named with a leading _). A function nothing names is dead code: remove
it (or, if a user of the library is meant to call it, call it from a test). The scan reads
declarations and definitions by their shape (a type, a name, a parameter list, then ; or {), a
definition in a .cpp only where it opens a body; comments are left out. Usage:
  dead_code_test.py ROOT [--min-functions MIN]   (fails reading fewer than MIN, default 800: the
      tree has about 1,200, so that a scan that finds nothing cannot pass)
  dead_code_test.py --self-test   (on tests/house/fixtures/dead_code/: it must name the planted
      never_called, and neither a function called only from a return statement nor one called
      only from JavaScript)
On the tree as it was before this check (commit fb404f7) it named the seven the issue found by
reading: describe_limit, Simulation::initial_state, Session::script_next, broadcast,
has_damping, team_size and team_index."""
import pathlib
import re
import subprocess
import sys

from house_check import self_test_verdict, take_floor

FIXTURE = pathlib.Path(__file__).resolve().parent / "fixtures" / "dead_code"
DIRS = ["core", "app", "python/src", "tests", "bench", "examples"]
SCRIPTS = (".js", ".cjs", ".html")
DECLARATION = re.compile(
    r"^[ \t]*(?:(?:inline|static|constexpr|virtual|explicit|\[\[nodiscard\]\])\s+)*(?:[\w:<>,*&]+\s+)+[*&]?(?:\w+::)*"
    r"(~?\w+)\s*\([^;{()]*(?:\([^()]*\)[^;{()]*)*\)\s*(?:const)?\s*(?:noexcept)?\s*(?:override|final)?"
    r"\s*(?:->\s*[\w:<>]+\s*)?[;{]", re.M)
NOT_A_TYPE = {"return", "else", "throw", "case", "co_return", "new", "delete", "goto"}
NOT_A_FUNCTION = {"if", "for", "while", "switch", "return", "main", "sizeof", "catch"}


def self_test():
    run = subprocess.run([sys.executable, __file__, str(FIXTURE), "--min-functions", "3"], capture_output=True, text=True)
    out = run.stdout + run.stderr
    print(out, end="")
    problems = []
    if run.returncode == 0 or "never_called" not in out:
        problems.append("the planted never_called was not named")
    for alive in ("called_from_a_return", "called_inline", "exported_to_javascript", " user"):
        if alive + "\n" in out:
            problems.append(f"{alive.strip()}, which is called, was named")
    self_test_verdict(problems, "the check names the planted dead function and no live one")


def main(args):
    min_functions = take_floor(args, "--min-functions", 800)
    root = pathlib.Path(args[0]).resolve()
    files = [p for d in DIRS if (root / d).is_dir() for p in sorted((root / d).rglob("*"))
             if p.is_file() and "fixtures" not in p.relative_to(root).parts
             and (p.suffix in (".cpp", ".hpp", ".h", ".cc") + SCRIPTS or p.name == "CMakeLists.txt")]
    mentions, sites, where = {}, {}, {}
    for path in files:
        text = re.sub(r"//[^\n]*", "", path.read_text(errors="replace"))
        script = path.suffix in SCRIPTS or path.name == "CMakeLists.txt"
        for word in re.findall(r"\b\w+\b", text):
            word = word.lstrip("_") if script else word  # (emscripten's _name)
            mentions[word] = mentions.get(word, 0) + 1
        own = path.relative_to(root).parts[0] in ("core", "app")
        if script or not own or path.suffix not in (".hpp", ".cpp"):
            continue
        for m in DECLARATION.finditer(text):
            name, head = m.group(1), m.group(0).split()[0]
            if head in NOT_A_TYPE or (path.suffix == ".cpp" and not m.group(0).rstrip().endswith("{")):
                continue  # a call (return f(x);) or, in a .cpp, a statement, not a definition
            sites[name] = sites.get(name, 0) + 1
            if path.suffix == ".hpp" or name not in where:
                where[name] = f"{path.relative_to(root)}:{text[:m.start(1)].count(chr(10)) + 1}"
    dead = sorted(f"{where[n]}: {n}" for n in sites
                  if n not in NOT_A_FUNCTION and not n.startswith("~") and mentions.get(n, 0) <= sites[n])
    print(f"dead_code_test: {len(files)} files read, {len(sites)} functions declared or defined in core/ and app/, "
          f"{len(dead)} named nowhere else")
    for line in dead:
        print(f"{line}\n  is named only where it is declared or defined: remove it, or call it from a test")
    if len(sites) < min_functions:
        print(f"too few functions read ({len(sites)} < {min_functions}): the scan is broken", file=sys.stderr)
        return 1
    return 1 if dead else 0


if __name__ == "__main__":
    if sys.argv[1:] == ["--self-test"]:
        self_test()
    sys.exit(main(sys.argv[1:]))
