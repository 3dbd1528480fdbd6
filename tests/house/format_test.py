#!/usr/bin/env python3
"""The style as a check (issue 58): every C++ file in core/, app/, python/, tests/, bench/ and
examples/ is as clang-format 14 writes it with the project's .clang-format (100 columns, Google's
style, includes sorted within their blocks). Code written as others write it (the exercise's
headers, students' ropes, the house checks' planted defects) keeps its own form: a .clang-format
with DisableFormat in its folder. Fails naming each file and its first line that differs, with the
command that formats it. JavaScript in C++ (emscripten's EM_JS and EM_ASM blocks, in app/) must sit
between `// clang-format off` and `// clang-format on`: clang-format writes JavaScript's `=>` as
`= >` and `===` as `== =`, and the browser's build then fails. Fails too when it reads fewer than
MIN files (default 300; the tree has about 400), so that a scan that finds nothing cannot pass.
Usage:
  format_test.py ROOT [--min-files MIN] [--style FILE]
  format_test.py --self-test   (runs itself on tests/house/fixtures/format/, a planted file with
      a long line and unformatted braces beside a formatted one, with the project's style, and
      expects it to fail naming the planted file only; and with the default floor, and expects it
      to fail for reading too few)"""
import pathlib
import re
import shutil
import subprocess
import sys

from house_check import self_test_verdict, take_floor

HERE = pathlib.Path(__file__).resolve().parent
FIXTURE = HERE / "fixtures" / "format"
FOLDERS = ("core", "app", "python", "tests", "bench", "examples")
SUFFIXES = (".cpp", ".hpp", ".h", ".cc")


def clang_format():
    """clang-format 14, the version the tree was formatted with (another version writes some lines
    otherwise)."""
    for name in ("clang-format-14", "clang-format"):
        path = shutil.which(name)
        if not path:
            continue
        version = subprocess.run([path, "--version"], capture_output=True, text=True).stdout
        if re.search(r"version 14\.", version):
            return path
    print("format: clang-format 14 not found; install it with scripts/setup.sh (Debian's clang-format-14)")
    sys.exit(1)


def self_test():
    """Runs this check on the fixture; exit 0 when it failed as it should."""
    def run(*args):
        p = subprocess.run([sys.executable, __file__, str(FIXTURE), *args], capture_output=True, text=True)
        print(f"$ format_test.py tests/house/fixtures/format {' '.join(args)}  -> exit {p.returncode}")
        print(p.stdout + p.stderr, end="")
        return p.returncode, p.stdout + p.stderr
    style = str(HERE.parents[1] / ".clang-format")
    problems = []
    rc, out = run("--min-files", "3", "--style", style)
    if rc == 0:
        problems.append("the planted file passed")
    if "core/planted.cpp:1:" not in out:
        problems.append("core/planted.cpp (its first line over 100 columns) was not named at line 1")
    if "formatted.cpp" in out:
        problems.append("the formatted file was named")
    if "app/planted_js.cpp:3: JavaScript" not in out:
        problems.append("app/planted_js.cpp:3 (EM_JS outside clang-format off) was not named")
    rc, out = run("--style", style)  # the default floor: the fixture's 3 files are too few
    if rc == 0 or "too few" not in out:
        problems.append("reading the fixture's 3 files passed the default floor")
    self_test_verdict(problems, "the check fails on the planted file and on too few read")


args = sys.argv[1:]
if args == ["--self-test"]:
    self_test()
min_files = take_floor(args, "--min-files", 300)
style = "file"
if "--style" in args:
    k = args.index("--style")
    style = "file:" + args[k + 1]
    del args[k:k + 2]
root = pathlib.Path(args[0] if args else ".").resolve()
files = sorted(str(p.relative_to(root)) for folder in FOLDERS if (root / folder).is_dir()
               for p in (root / folder).rglob("*") if p.suffix in SUFFIXES and p.is_file())
tool = clang_format()
# --dry-run --Werror writes "FILE:LINE:COL: error: code should be clang-formatted" for each change.
p = subprocess.run([tool, f"--style={style}", "--dry-run", "--Werror", *files], cwd=root,
                   capture_output=True, text=True)
first = {}
for m in re.finditer(r"^(\S+?):(\d+):\d+: error: code should be clang-formatted", p.stderr, re.M):
    first.setdefault(m.group(1), int(m.group(2)))
if p.returncode != 0 and not first:
    print(f"format: {tool} failed (exit {p.returncode}):\n{p.stderr[-2000:]}")
    sys.exit(1)
print(f"format_test: {len(files)} files read in {', '.join(FOLDERS)} (at least {min_files} expected), "
      f"{len(first)} not formatted")
status = 0
for name, line in first.items():
    print(f"{name}:{line}: not as clang-format writes it; run: {pathlib.Path(tool).name} -i {name}")
    status = 1
# JavaScript blocks outside a clang-format off region.
for name in files:
    if not name.startswith("app/"):
        continue
    off = False
    for number, line in enumerate((root / name).read_text(encoding="utf-8").splitlines(), 1):
        stripped = line.strip()
        if stripped.startswith("// clang-format off"):
            off = True
        elif stripped.startswith("// clang-format on"):
            off = False
        elif re.match(r"EM_(JS|ASM)", stripped) and not off:
            print(f"{name}:{number}: JavaScript (EM_JS, EM_ASM) outside `// clang-format off`: "
                  "clang-format would break it (`=>` as `= >`)")
            status = 1
if len(files) < min_files:
    print(f"too few files read ({len(files)}, fewer than {min_files}): is {root} the project's root?")
    status = 1
if status == 0:
    print("format: every file as clang-format writes it")
sys.exit(status)
