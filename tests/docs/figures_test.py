#!/usr/bin/env python3
"""The figures the documents state (docs/lessons.md, docs/methods.md, docs/homework.md,
docs/numerics.md), checked against what the program prints now, so that they cannot drift. Each
figure is found in its sentence in the document and in the output of the command that gives it;
the program's value, rounded to the digits the document shows, must be the document's (or, for a
bound, within it). docs/methods.md's method table is checked against `springlab list`: its rows,
orders and what each keeps, and the count of built-in methods it and the README state. Usage:
figures_test.py SPRINGLAB ROOT. Deterministic figures only (no timings); about ten seconds."""
import re
import subprocess
import sys
from decimal import Decimal

springlab, root = sys.argv[1], sys.argv[2]
NUMBER = r"([-+]?[0-9]*\.?[0-9]+(?:[eE][-+]?[0-9]+)?)"
CHAIN = "run chain --dt 0.0333333 --substeps 1 --duration 30 --method "
HOMEWORK = "homework check --lang en tests/homework/"
VERLET_D = "run spring --method verlet --substeps 1 --set verlet_damping=0.00005 --duration 8 --dt "  # lesson 13's d

# (document, its sentence with {} for the figure, command, its output with {} for the value, kind)
# kind: "rounded" (the value rounded to the document's digits is the document's) or "bound" (the
# value is at most the document's). Outputs are matched after the lesson check's or the run's
# line that names them, so each pattern names enough context to be unique.
FIGURES = [
    # The lessons table: `springlab lesson check` plays every lesson.
    ("docs/lessons.md", "(RK4 within {} m of both)", "lesson check", "within 0.0001 m: max |x - x_exact| = {} m", "bound"),
    ("docs/lessons.md", "(momentum and angular momentum kept to {});", "lesson check", "changed by {} of it", "bound"),
    ("docs/lessons.md", "(momentum and angular momentum kept to {});", "lesson check", "kg m^2/s by {}\n", "bound"),
    ("docs/lessons.md", "exp(-k_drag n t / M) (measured {},", "lesson check", "speed ratio {} (", "rounded"),
    ("docs/lessons.md", "(measured x{}, predicted x1.027778)", "lesson check", "euler: energy grows by x1.027778 a step: x{} a step", "rounded"),
    ("docs/lessons.md", "(stated limit {} s)", "lesson check", "stated stability limit h = 0.02 s: stated limit h = {} s", "rounded"),
    ("docs/lessons.md", "= 1.0125 a step (measured {})", "lesson check", "energy grows by x1.0125 a step: x{} a step", "rounded"),
    ("docs/lessons.md", "for modified Euler (measured {})", "lesson check", "modified-euler: energy grows by x1.013889 a step: x{} a step", "rounded"),
    ("docs/lessons.md", "for midpoint (measured {})", "lesson check", "midpoint: energy grows by x1.000193 a step: x{} a step", "rounded"),
    ("docs/lessons.md", "({} rejected, the step ranging", "lesson check", ": {} tries rejected", "rounded"),
    ("docs/lessons.md", "the step ranging {} to", "lesson check", "tries rejected, step from {} to", "rounded"),
    ("docs/lessons.md", "explode within {} s", "lesson check", "symplectic-euler: diverges by t = 1 s: diverged at t = {} s", "bound"),
    ("docs/lessons.md", "RK4 at h = 0.05 s within {} cm", "lesson check", "rk4: follows the exact solution within 0.02 m: max |x - x_exact| = {} m", "centimetres"),
    ("docs/lessons.md", "(error against force evaluations): orders {},", "lesson check", "most accurate for its cost: rk4: euler {} ", "rounded"),
    ("docs/lessons.md", "= 1280 drops ({} counted)", "lesson check", "1280 particles at t = 7 s: {} alive", "rounded"),
    ("docs/lessons.md", "(the arm straight towards it, to {} m)", "lesson check", "end {} m off the straight line", "rounded"),
    ("docs/lessons.md", "each iteration gaining under 1 % (x{} and", "lesson check", "local-global: nears the converged implicit-Euler step by x0.9999 or less an iteration: 0.849 of the step from 8 to 64 iterations to 0.83: x{} an iteration", "rounded"),
    ("docs/lessons.md", "and x{} an iteration)", "lesson check", "vbd: nears the converged implicit-Euler step by x0.9999 or less an iteration: 1 of the step from 8 to 64 iterations to 0.909: x{} an iteration", "rounded"),
    ("docs/lessons.md", "10 passes in one step act as k_s x {},", "lesson check", "k_s x0.02 or less: stretch 0.0215 m RMS against the spring model's 0.000133 m: k_s x{}\n", "rounded"),
    ("docs/lessons.md", "10 sub-steps of one pass as k_s x {} (", "lesson check", "0.1 or less: stretch 0.00273 m RMS against the spring model's 0.000133 m: k_s x{}\n", "rounded"),
    ("docs/methods.md", "(VBD: P off by {} of sum m|v|)", "lesson check", "vbd: momentum changes by more than 0.001 of sum m|v|: P changed by {} of", "rounded"),
    ("docs/lessons.md", "the same x{} a step at hω = 0.5", "lesson check", "heun: energy grows by x1.015625 a step: x{} a step", "rounded"),
    ("docs/lessons.md", "Heun with one wrong entry drops to {};", "lesson check", "heun 2.00 heun-wrong {} ;", "rounded"),
    ("docs/lessons.md", "keeps the undamped spring's energy to {} of its scale", "lesson check", "implicit-midpoint: energy stays within 1e-09 of its scale: within {} of", "rounded"),
    ("docs/lessons.md", "despite the drag and diverges at t = {} s,", "lesson check", "euler: diverges by t = 2.2 s: diverged at t = {} s", "rounded"),
    ("docs/lessons.md", "keep the falling rope's energy (to {} and", "lesson check", "symplectic-euler: energy stays within 1e-05 of its scale: within {} of", "rounded"),
    ("docs/lessons.md", "and {} of its scale); Verlet's", "lesson check", "verlet: energy stays within 2e-07 of its scale: within {} of", "rounded"),
    ("docs/lessons.md", "x{} a step at h = 1/1024 s", "lesson check", "step 4: Verlet's damping d\n    ok    energy decays by x0.99995 a step: x{} a step", "rounded"),
    ("docs/lessons.md", "and x{} at h = 1/2048 s", "lesson check", "step 5: Half the step, twice the damping\n    ok    energy decays by x0.99995 a step: x{} a step", "rounded"),
    ("docs/lessons.md", "falls in 8 s to {} J and", VERLET_D + "0.0009765625", "total {} J (initially 12.5 J)", "rounded"),
    ("docs/lessons.md", "and to {} J; on the spring", VERLET_D + "0.00048828125", "total {} J (initially 12.5 J)", "rounded"),
    ("docs/lessons.md", "orders {} (explicit Euler),", "lesson check", "most accurate for its cost: verlet: euler {} ", "rounded"),
    ("docs/lessons.md", "{} (semi-implicit) and", "lesson check", "verlet: euler 1.03 symplectic-euler {} verlet ", "rounded"),
    ("docs/lessons.md", "and {} (Verlet), as the checker", "lesson check", " verlet {} ;", "rounded"),
    ("docs/lessons.md", "their stated limit of {} s", "lesson check", "verlet: stated stability limit h = 0.2 s: stated limit h = {} s", "rounded"),
    # Homework 8's checker on the rope files the tests hold (tests/homework/).
    ("docs/homework.md", "matches springlab's row to {} of a step's", HOMEWORK + "ropes/correct.cpp", "c = 0.01 N s/m: each of 64 steps of a 16-mass rope falling from rest at h = 1/1024 s matches it to {} of the step's motion", "rounded"),
    ("docs/homework.md", "matches to {}, under its float floor", HOMEWORK + "students/float_everywhere.cpp", "c = 0.01 N s/m: each of 64 steps of a 16-mass rope falling from rest at h = 1/1024 s matches it to {} of the step's motion: float", "rounded"),
    ("docs/homework.md", "under its float floor of {};", HOMEWORK + "students/float_everywhere.cpp", "allows up to {} here)\n  ok    order 1", "rounded"),
    ("docs/homework.md", "gains x{} a step on the spring", HOMEWORK + "ropes/explicit.cpp", "energy grows: x{} a step", "rounded"),
    ("docs/homework.md", "1 + (ωh)² - (c/m)h = {} at", HOMEWORK + "ropes/explicit.cpp", "(c/m) h = {}), x", "rounded"),
    ("docs/homework.md", "loses x{} a step against 1 - d", HOMEWORK + "ropes/correct.cpp", "energy falls: x{} a step at h = 1/256 s (Verlet", "rounded"),
    ("docs/homework.md", "order is measured {}.", HOMEWORK + "ropes/no_damping.cpp", "order {} measured (Verlet", "rounded"),
    # What a large step costs the practitioners' methods: the chain at one step a frame.
    ("docs/methods.md", "XPBD's one pass leaves its springs acting as k_s x {} at rest", CHAIN + "xpbd", "act as k_s x {}\n", "rounded"),
    ("docs/methods.md", "at rest (VBD x {},", CHAIN + "vbd", "act as k_s x {}\n", "rounded"),
    ("docs/methods.md", "local-global x {}).", CHAIN + "local-global", "act as k_s x {}\n", "rounded"),
    ("docs/methods.md", "(XPBD's one pass on the chain below: {} J,", CHAIN + "xpbd", "energy in  {} J", "rounded"),
    ("docs/methods.md", "its springs at {} times their rest length)", CHAIN + "xpbd", "springs at {}x their rest length", "rounded"),
    ("docs/methods.md", "step a frame XPBD {} of 64,", "run jelly --dt 0.0333333 --substeps 1 --method xpbd", "cells      {} of 64 inverted", "rounded"),
    ("docs/methods.md", "of 64, VBD {}; implicit Euler none)", "run jelly --dt 0.0333333 --substeps 1 --method vbd", "cells      {} of 64 inverted", "rounded"),
    ("docs/methods.md", "({} on the chain at one step a frame: at 0.999", CHAIN + "local-global --rho 0.999", "spectral radius here, {} (", "rounded"),
    ("docs/methods.md", "at 0.999 it puts {} J in over 30 s)", CHAIN + "local-global --rho 0.999", "energy in  {} J", "rounded"),
    ("docs/numerics.md", "stretch as if they were `k_s x {}`", CHAIN + "xpbd", "act as k_s x {}\n", "rounded"),
    ("docs/numerics.md", "which prints {})", CHAIN + "xpbd", "act as k_s x {}\n", "rounded"),
    ("docs/numerics.md", "XPBD one pass x {};", CHAIN + "xpbd", "act as k_s x {}\n", "rounded"),
    ("docs/numerics.md", "VBD x {}; local-global", CHAIN + "vbd", "act as k_s x {}\n", "rounded"),
    ("docs/numerics.md", "local-global x {}.", CHAIN + "local-global", "act as k_s x {}\n", "rounded"),
]


def pattern(text):
    parts = text.split("{}")
    assert len(parts) == 2, text
    return re.compile(re.escape(parts[0]) + NUMBER + re.escape(parts[1]))


def shown(figure, value, kind):
    """Whether `value` (the program's) is `figure` (the document's) at the document's digits."""
    doc = Decimal(figure)
    if kind == "bound":
        return Decimal(value) <= doc
    if kind == "centimetres":
        value = str(Decimal(value) * 100)
    exponent = doc.as_tuple().exponent  # the last digit shown: 0.0086 -> -4, 1.2e-5 -> -6
    quantum = Decimal(1).scaleb(exponent)
    return Decimal(value).quantize(quantum) == doc.quantize(quantum)


outputs = {}


def output(command):
    if command not in outputs:
        r = subprocess.run([springlab] + command.split(), capture_output=True, text=True, cwd=root)
        if r.returncode != 0:
            sys.exit(f"figures_test: `springlab {command}` failed ({r.returncode}): {r.stderr}")
        outputs[command] = r.stdout + r.stderr  # (warnings are on stderr)
    return outputs[command]


failures = []
documents = {}
for doc, sentence, command, printed, kind in FIGURES:
    # (whitespace as one space: a sentence may wrap)
    text = documents.setdefault(doc, re.sub(r"\s+", " ", open(f"{root}/{doc}", encoding="utf-8").read()))
    found = pattern(sentence).findall(text)
    if len(found) != 1:
        failures.append(f"{doc}: '{sentence}' found {len(found)} times (once expected): the sentence changed?")
        continue
    got = pattern(printed).findall(output(command))
    if not got:
        failures.append(f"`springlab {command}` no longer prints '{printed}'")
        continue
    # Every place the output prints it must show the figure (a pattern matching twice is no excuse
    # to read only the first).
    for value in got:
        if not shown(found[0], value, kind):
            failures.append(f"{doc}: '{sentence.replace('{}', found[0])}', but `springlab {command}` prints "
                            f"{value} ({'not within it' if kind == 'bound' else 'another figure at those digits'})")
            break

# docs/methods.md's method table against the method table itself (`springlab list`).
page = open(f"{root}/docs/methods.md", encoding="utf-8").read()
listed = re.findall(r"^method  (\S+) +.*?: order (\d+), .*; keeps on a free body: (.+)$", output("list"), re.M)
methods = page.split("\n## The table\n")[1].split("\n## ")[0]
table = re.findall(r"^\| `([a-z0-9-]+)` \| (\d+) \| .* \| ([^|]+) \|$", methods, re.M)
if [(n, o, k.strip()) for n, o, k in table] != listed:
    failures.append("docs/methods.md's method table is not `springlab list`'s rows:\n  docs: " + str(table) +
                    "\n  list: " + str(listed))
count = {9: "nine", 10: "ten", 11: "eleven", 12: "twelve", 13: "thirteen", 14: "fourteen"}.get(len(listed))
for doc in ("docs/methods.md", "README.md"):  # (each states the count: both must follow the table)
    words = re.sub(r"\s+", " ", open(f"{root}/{doc}", encoding="utf-8").read()).lower()
    if f"the {count} built-in methods" not in words:
        failures.append(f"{doc} does not say 'the {count} built-in methods' ({len(listed)} rows)")

print(f"figures_test: {len(FIGURES)} figures and the method table checked")
if failures:
    print("\n".join(failures))
    sys.exit(1)
