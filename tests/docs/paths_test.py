#!/usr/bin/env python3
"""Every path and test name the documents give exists in the tree, so that a renamed file or test
cannot leave a document pointing at nothing. Usage: paths_test.py ROOT.

Read: README.md, CONTRIBUTING.md, docs/*.md and assets/*/README.md. Checked:
- a repository path: a word that begins with one of the tree's top-level folders (`core/src/...`,
  `app/ui/panels.cpp`, `tests/...`, `scripts/test.sh`, `assets/...`), from the root; `*` is a glob;
- a file name given with a folder (`ui/panels.cpp`, `springlab/text.hpp`): the end of some file's
  path in the tree;
- a Markdown link's target (relative to the document, as GitHub reads it) and its `#anchor` (a
  heading of the target, as GitHub makes anchors);
- a test named `Suite.Name` (a CTest name or a GoogleTest one, `Suite.*` for a suite,
  `Prefix/Suite.Name` for a parameterised one): a `TEST`, `TEST_F` or `TEST_P` in tests/ or
  an `add_test(NAME ...)` in a CMakeLists.txt.
Left alone: build outputs (build*/, docs/api/), system and home paths (/usr, /tmp, ~), system
headers (`<backends/imgui_impl_glfw.h>`), URLs, names to choose (`assets/scenes/NAME.json`) and the
few files a user makes, named in USERS_FILES below. Python's standard library only."""
import fnmatch
import os
import re
import sys

root = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else ".")

# Files a document names that are the user's own, not the project's: made by a command it shows.
USERS_FILES = {
    "hw8/rope.cpp",          # `springlab homework kit hw8` writes it
    "hw8/README.md",
}
# A path with a word in capitals standing for a name (`assets/scenes/NAME.json`, `PREFIX/lib/...`)
# names a file to make, and `"room/file.hpp"` is the form of an include.
STAND_IN = re.compile(r"(?:^|[/_.-])(?:NAME|TAG|NN|FILE|DIR|PREFIX|SCENE|ROOM|KIND)(?:$|[/_.-])")
TEMPLATES = {"room/file.hpp"}
# Words of the form Suite.Name that are not tests.
NOT_TESTS = {"Boost.Multiprecision"}
# Folders that hold what a build or a command makes, never files of the tree.
GENERATED = ("build", "build-web", "build-wasm", "build-sanitize", "build-pip", "docs/api", "out")

# The tree: every file and folder, build outputs and .git left out.
files, folders = set(), set()
for here, dirs, names in os.walk(root):
    rel = os.path.relpath(here, root)
    if rel == ".":
        dirs[:] = [d for d in dirs if not d.startswith(("build", ".git", ".pytest_cache"))]
        rel = ""
    dirs[:] = [d for d in dirs if d not in ("node_modules", "__pycache__")]
    for d in dirs:
        folders.add(os.path.join(rel, d))
    for n in names:
        files.add(os.path.join(rel, n))
top_level = {p.split("/")[0] for p in files | folders if "/" in p}  # folders at the top: app, core, ...
everything = files | folders


def exists(path):
    path = path.rstrip("/")
    if any(c in path for c in "*?["):
        return any(fnmatch.fnmatchcase(p, path) for p in everything)
    return path in everything or path + ".in" in files  # (a file CMake configures from NAME.in)


def exists_as_ending(path):
    """A file name with a folder (`ui/panels.cpp`): the end of some file's path."""
    if any(c in path for c in "*?["):
        return any(fnmatch.fnmatchcase(p, path) or fnmatch.fnmatchcase(p, "*/" + path) for p in files)
    return any(p in (path, path + ".in") or p.endswith(("/" + path, "/" + path + ".in")) for p in files)


# Test names: GoogleTest's macros in tests/ (and python/, bench/ if any), CTest's add_test.
gtest = set()
for p in files:
    if p.endswith((".cpp", ".hpp")) and p.startswith(("tests/", "python/", "bench/")):
        text = open(os.path.join(root, p), encoding="utf-8", errors="replace").read()
        fixtures = {}
        for prefix, suite in re.findall(r"INSTANTIATE_TEST_SUITE_P\(\s*(\w+)\s*,\s*(\w+)", text):
            fixtures.setdefault(suite, []).append(prefix)
        for macro, suite, name in re.findall(r"\b(TEST|TEST_F|TEST_P|TYPED_TEST)\(\s*(\w+)\s*,\s*(\w+)\s*\)", text):
            gtest.add(f"{suite}.{name}")
            for prefix in fixtures.get(suite, []):
                gtest.add(f"{prefix}/{suite}.{name}")
ctest_literal, ctest_patterns = set(), []
for p in files:
    if os.path.basename(p) == "CMakeLists.txt" or p.endswith(".cmake"):
        text = open(os.path.join(root, p), encoding="utf-8", errors="replace").read()
        for name in re.findall(r"add_test\(\s*NAME\s+(\S+)", text):
            if "${" in name:  # Python.${name}: the value must be a word of the same file
                regex = re.sub(r"\\\$\\\{\w+\\\}", r"(\\w+)", re.escape(name))
                ctest_patterns.append((re.compile(regex + "$"), set(re.findall(r"\w+", text))))
            else:
                ctest_literal.add(name)
test_names = gtest | ctest_literal


def test_exists(name):
    if name.endswith("*"):  # Suite.* or a prefix
        return any(t.startswith(name[:-1]) for t in test_names) or \
            any(m.match(name[:-1] + "x") for m, _ in ctest_patterns)
    if name in test_names:
        return True
    # A parameterised test's name may be a prefix (Prefix/Suite.Name/param), or carry the parameter.
    if any(t.startswith(name + "/") or name.startswith(t + "/") for t in test_names):
        return True
    for regex, words in ctest_patterns:
        m = regex.match(name)
        if m and all(g in words for g in m.groups()):
            return True
    return False


# GitHub's anchors: a heading lowercased, punctuation other than - and _ dropped, spaces as -.
def anchors(path):
    found, seen = set(), {}
    in_code = False
    for line in open(path, encoding="utf-8"):
        if line.startswith("```"):
            in_code = not in_code
        m = re.match(r"#{1,6} +(.*?) *#* *$", line)
        if m and not in_code:
            text = re.sub(r"\{#[\w-]+\}", "", m.group(1))
            text = re.sub(r"[`*]", "", text)
            slug = re.sub(r"[^\w\- ]", "", text.strip().lower()).replace(" ", "-")
            n = seen.get(slug, 0)
            seen[slug] = n + 1
            found.add(slug if n == 0 else f"{slug}-{n}")
    return found


documents = ["README.md", "CONTRIBUTING.md"]
documents += sorted("docs/" + n for n in os.listdir(os.path.join(root, "docs")) if n.endswith(".md"))
documents += sorted(f"assets/{d}/README.md" for d in os.listdir(os.path.join(root, "assets"))
                    if os.path.isfile(os.path.join(root, "assets", d, "README.md")))

LINK = re.compile(r"\]\(([^)\s]+)\)")
URL = re.compile(r"\b[a-z][a-z0-9+.-]*://\S+|\bwww\.\S+|\b[\w.-]+\.(?:com|org|io|net)/\S*")
WORD = re.compile(r"[A-Za-z0-9_.*~$+/-]*/[A-Za-z0-9_.*~$+/-]*")
TEST = re.compile(r"(?<![\w./-])([A-Z][A-Za-z0-9]*(?:/[A-Z][A-Za-z0-9]*)?\.(?:[A-Z][A-Za-z0-9_]*\*?|\*))(?![\w(*])")
EXTENSION = re.compile(r"\.(?:[A-Za-z][A-Za-z0-9]{0,7}|\*)$")

failures, checked = [], {"paths": 0, "files with a folder": 0, "links": 0, "anchors": 0, "tests": 0}
for doc in documents:
    folder = os.path.dirname(doc)
    for number, line in enumerate(open(os.path.join(root, doc), encoding="utf-8"), 1):
        where = f"{doc}:{number}"
        # Links, relative to the document.
        for target in LINK.findall(line):
            if URL.match(target) or target.startswith("mailto:"):
                continue
            path, _, anchor = target.partition("#")
            full = os.path.normpath(os.path.join(folder, path)) if path else doc
            checked["links"] += 1
            if path and not exists(full):
                failures.append(f"{where}: the link to {target} leads to no file ({full})")
                continue
            if anchor and full.endswith(".md"):
                checked["anchors"] += 1
                if anchor not in anchors(os.path.join(root, full)):
                    failures.append(f"{where}: the link to {target}: {full} has no heading #{anchor}")
        text = URL.sub(" ", LINK.sub("] ", line))
        text = re.sub(r"<[\w./+-]+>", " ", text)  # a system header, `<backends/imgui_impl_glfw.h>`
        # Paths and file names with a folder.
        for word in WORD.findall(text):
            word = re.sub(r"^\./", "", word.rstrip(".,;:") if not word.endswith(".*") else word)
            if "/" not in word or word.startswith(("/", "~", "$")) or word in USERS_FILES | TEMPLATES \
                    or STAND_IN.search(word) or TEST.fullmatch(word):
                continue
            if word.startswith(GENERATED) and (word.split("/")[0] in GENERATED or word.startswith("docs/api")):
                continue
            first = word.split("/")[0]
            if first in top_level or first == "..":
                checked["paths"] += 1
                path = os.path.normpath(os.path.join(folder, word)) if first == ".." else word
                if not exists(path):
                    failures.append(f"{where}: {word} is not in the tree")
            elif EXTENSION.search(word) and re.match(r"[A-Za-z_]", first):
                checked["files with a folder"] += 1
                if not exists_as_ending(word):
                    failures.append(f"{where}: {word} is no file's path or the end of one")
        # Test names.
        for name in TEST.findall(text):
            if name in NOT_TESTS:
                continue
            checked["tests"] += 1
            if not test_exists(name):
                failures.append(f"{where}: the test {name} is not in tests/ (no TEST, TEST_P, TEST_F or add_test)")

total = sum(checked.values())
print(f"paths_test: {len(documents)} documents, {total} names checked (" +
      ", ".join(f"{v} {k}" for k, v in checked.items()) + ")")
if checked["paths"] + checked["files with a folder"] < 300:
    failures.append(f"only {checked['paths'] + checked['files with a folder']} paths found: "
                    "the documents hold hundreds, so the test has stopped reading them")
if checked["tests"] < 20:
    failures.append(f"only {checked['tests']} test names found: the test has stopped reading them")
if failures:
    print("\n".join(failures))
    sys.exit(1)
