#!/usr/bin/env python3
"""No function over 80 lines in app/, core/ or python/src/ without a reason (issues 43 and 58): a
function that long reads as several, and its parts want names. A function may be longer where the
comment just above its first line says why, in a line that begins "Long:" ("// Long: the table of
..." ). Fails naming each function over the limit (LIMIT lines, default 80), its file, first line
and length; fails too when it reads fewer than MIN functions (default 1000; the tree has about
1,680), so that a scan that finds nothing cannot pass. Usage:
  function_length_test.py ROOT [LIMIT] [--min-functions MIN]
  function_length_test.py --self-test   (runs itself on tests/house/fixtures/function_length/,
      planted 130- and 90-line functions with no reason, and expects it to fail naming both at the
      default limit and only the first at a limit of 100; and on the same fixture with the default
      floor, and expects it to fail for reading too few)"""
import pathlib
import re
import subprocess
import sys

from house_check import self_test_verdict, take_floor

FIXTURE = pathlib.Path(__file__).resolve().parent / "fixtures" / "function_length"


def self_test():
    """Runs this check on the fixture; exit 0 when it failed as it should."""
    def run(*args):
        p = subprocess.run([sys.executable, __file__, str(FIXTURE), *args], capture_output=True, text=True)
        print(f"$ function_length_test.py {FIXTURE.relative_to(FIXTURE.parents[3])} {' '.join(args)}  -> exit {p.returncode}")
        print(p.stdout + p.stderr, end="")
        return p.returncode, p.stdout + p.stderr
    problems = []
    long_named = "core/long_function.cpp:7: planted_long_function is 130 lines"
    ninety_named = "core/long_function.cpp:270: planted_ninety_line_function is 90 lines"
    rc, out = run("--min-functions", "4")  # the default limit, 80
    if rc == 0:
        problems.append("the planted long functions passed")
    if long_named not in out:
        problems.append("planted_long_function (core/long_function.cpp:7, 130 lines) was not named")
    if ninety_named not in out:
        problems.append("planted_ninety_line_function (core/long_function.cpp:270, 90 lines) was not "
                        "named at the default limit")
    if "long_with_a_reason" in out or "short_function" in out:
        problems.append("a function with a reason, or a short one, was named")
    rc, out = run("100", "--min-functions", "4")  # a limit given: the 90-line function is within it
    if rc == 0 or long_named not in out or "planted_ninety_line_function" in out:
        problems.append("at a limit of 100, not planted_long_function alone was named")
    rc, out = run()  # the default floor: the fixture's few functions are too few
    if rc == 0 or "too few" not in out:
        problems.append("reading the fixture's 4 functions passed the default floor")
    self_test_verdict(problems, "the check fails on the planted functions and on too few read")


args = sys.argv[1:]
if args == ["--self-test"]:
    self_test()
min_functions = take_floor(args, "--min-functions", 1000)
root = pathlib.Path(args[0] if args else ".")
limit = int(args[1]) if len(args) > 1 else 80
SCOPES = re.compile(r"\b(namespace|class|struct|union|enum)\b|extern\s*\"C\"")


def blank_literals(text):
    """The text with comments, strings and character literals blanked (newlines kept), so that
    braces in them are not counted."""
    out, i, n = [], 0, len(text)
    while i < n:
        c = text[i]
        if text.startswith("//", i):
            j = text.find("\n", i)
            j = n if j < 0 else j
            out.append(" " * (j - i))
            i = j
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
            out.append(re.sub(r"[^\n]", " ", text[i:j]))
            i = j
        elif text.startswith('R"', i) and (i == 0 or not (text[i - 1].isalnum() or text[i - 1] == "_")):
            m = re.match(r'R"([^(]*)\(', text[i:])
            end = text.find(")" + m.group(1) + '"', i) if m else -1
            j = n if end < 0 else end + len(m.group(1)) + 2
            out.append(re.sub(r"[^\n]", " ", text[i:j]))
            i = j
        elif c in "\"'":
            if c == "'" and i > 0 and text[i - 1].isalnum():  # a digit separator: 1'000
                out.append(c)
                i += 1
                continue
            j = i + 1
            while j < n and text[j] != c:
                j += 2 if text[j] == "\\" else 1
            out.append(" " * (j + 1 - i))
            i = j + 1
        else:
            out.append(c)
            i += 1
    return "".join(out)


def is_function(prefix):
    """Whether a block opened after `prefix` (the code since the last ; { or }) is a function's
    body: a parameter list, and no '=' outside parentheses (a table's or a lambda's initialiser)."""
    if "(" not in prefix or SCOPES.search(prefix):
        return False
    depth = 0
    for k, ch in enumerate(prefix):
        if ch == "(":
            depth += 1
        elif ch == ")":
            depth -= 1
        elif ch == "=" and depth == 0 and not prefix[:k].rstrip().endswith("operator") and prefix[k + 1:k + 2] != "=" \
                and prefix[k - 1:k] not in ("=", "!", "<", ">"):
            return False
    return True


def functions(path):
    text = blank_literals(path.read_text(encoding="utf-8"))
    stack = []  # per open brace: "scope", "function" (with its first line) or "block"
    last = 0  # where the current prefix starts
    line = 1
    for i, ch in enumerate(text):
        if ch == "\n":
            line += 1
        elif ch in ";":
            last = i + 1
        elif ch == "{":
            prefix = text[last:i]
            inside_function = any(kind == "function" for kind, _, _ in stack)
            if inside_function:
                kind = "block"
            elif SCOPES.search(prefix) and "(" not in prefix.split("{")[-1]:
                kind = "scope"
            elif is_function(prefix):
                kind = "function"
            else:
                kind = "block"
            first = line - (prefix.count("\n") - prefix[:len(prefix) - len(prefix.lstrip())].count("\n"))
            stack.append((kind, first, prefix.strip().split("(")[0].split()[-1] if kind == "function" and prefix.strip() else ""))
            last = i + 1
        elif ch == "}":
            if stack:
                kind, first, name = stack.pop()
                if kind == "function":
                    yield name, first, line - first + 1
            last = i + 1


def has_reason(lines, first):
    k = first - 2  # the line above the function's first, 0-based
    while k >= 0 and lines[k].strip().startswith("//"):
        if re.match(r"//+\s*Long:", lines[k].strip()):
            return True
        k -= 1
    return False


failures, seen = [], 0
for folder in ("app", "core", "python/src"):
    for path in sorted((root / folder).rglob("*")):
        if path.suffix not in (".cpp", ".hpp", ".h"):
            continue
        lines = path.read_text(encoding="utf-8").split("\n")
        for name, first, length in functions(path):
            seen += 1
            if length > limit and not has_reason(lines, first):
                failures.append(f"{path.relative_to(root)}:{first}: {name} is {length} lines (more than {limit}); "
                                f"split it into named parts, or say why above it in a line beginning '// Long:'")
print(f"function_length_test: {seen} functions read in app/, core/ and python/src/ "
      f"(at least {min_functions} expected), {len(failures)} over {limit} lines without a reason")
if seen < min_functions:
    failures.append(f"too few functions read ({seen}, fewer than {min_functions}): is {root} the project's root, "
                    f"or has the scan stopped finding functions?")
for f in failures:
    print(f, file=sys.stderr)
sys.exit(1 if failures else 0)
