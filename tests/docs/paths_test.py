#!/usr/bin/env python3
"""Every path, test, function, command and section the documents give exists in the tree, and so
does every path the sources' comments give, so that a renamed file, test, function or heading
cannot leave a document or a comment pointing at nothing. Usage: paths_test.py ROOT [--no-floors];
paths_test.py --self-test (runs itself on tests/docs/fixtures/paths/, a tree with one planted
defect of each kind, and expects it to fail naming each by file:line).

Read: README.md, CONTRIBUTING.md, docs/*.md and assets/*/README.md. Checked:
- a repository path: a word that begins with one of the tree's top-level folders (`core/src/...`,
  `app/ui/panels.cpp`, `tests/...`, `scripts/test.sh`, `assets/...`), from the root; `*` is a glob;
- a file name given with a folder (`ui/panels.cpp`, `springlab/text.hpp`): the end of some file's
  path in the tree;
- a Markdown link's target (relative to the document, as GitHub reads it) and its `#anchor` (a
  heading of the target, as GitHub makes anchors);
- a test named `Suite.Name` (a CTest name or a GoogleTest one, `Suite.*` for a suite,
  `Prefix/Suite.Name` for a parameterised one): a `TEST`, `TEST_F` or `TEST_P` in tests/ or
  an `add_test(NAME ...)` in a CMakeLists.txt;
- a function in code format: `draw_panels()`, `sim.step()`, `Session::step()`, and a qualified
  call or name (`Simulation::advance(due)`, `springlab.load_scene(name)`, `ui::draw_panels`): the
  function is an identifier of some source in core/, app/, python/, tests/, bench/, examples/ or
  shaders/ (a word-boundary match); for `A::b`, the sources say `A::b` or a file that declares `A`
  (class, struct, namespace, enum, using) names `b`. (An unqualified name with arguments, `R(z)`,
  `log(h)`, is taken for mathematics and left alone.)
- a command: `springlab WORD ...` in code format or a line of a code block: WORD is a subcommand
  of app/ (CLI11's `app.add_subcommand("WORD"`), the next word one of its own where it has some
  (`springlab lesson check`), and every `--flag` on it a flag some command defines;
- a section: a document followed by a heading in quotes (docs/numerics.md, "Divergence";
  [python.md](python.md), "Tests"; docs/architecture.md's "A scene kind"): a heading of that
  document, or a paragraph's bold lead (`**A scene kind**`), or a heading's words before its colon.
The sources' comments (`//` and `/* */` in C++, JavaScript and GLSL; `#` in Python, shell, CMake
and text; Python's docstrings) in core/, app/, python/, tests/, scripts/, bench/, examples/,
shaders/, cmake/, .ci/ and the top-level CMake and Python files: their paths and files with a folder
as above (relative to the file for `../`; under tests/, a path of one of tests/*/fixtures/*/, the
trees the house checks run on, counts too), their sections, and their `springlab WORD` commands.
And no file of the tree names the notes outside it that a clone does not have (the workspace's
DESIGN, PLATFORM, STYLE and NUMERICS .md files, or its ../ shared/ folder).
Left alone: build outputs (build*/, docs/api/), system and home paths (/usr, /tmp, ~), system
headers (`<backends/imgui_impl_glfw.h>`), URLs, names to choose (`assets/scenes/NAME.json`), the
few files a user makes, named in USERS_FILES below, and tests/*/fixtures/ (planted defects, each
checked by its own check's --self-test). Python's standard library only."""
import fnmatch
import os
import re
import subprocess
import sys

FIXTURE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "fixtures", "paths")


def self_test():
    """Runs this check on the fixture; exit 0 when it failed naming each planted defect."""
    p = subprocess.run([sys.executable, __file__, FIXTURE, "--no-floors"], capture_output=True, text=True)
    out = p.stdout + p.stderr
    print(f"$ paths_test.py tests/docs/fixtures/paths --no-floors  -> exit {p.returncode}")
    print(out, end="")
    problems = [] if p.returncode else ["the planted defects passed"]
    for want in ("README.md:5: `no_such_function()` names no identifier of the sources",
                 "README.md:6: `Widget::vanish()`: the sources have no Widget::vanish, and no file that declares "
                 "Widget names vanish",
                 "README.md:7: `springlab fly` is no subcommand (springlab has: run)",
                 "README.md:8: `springlab run --warp`: no command has the flag --warp",
                 'README.md:9: docs/guide.md has no heading or bold lead "No such section"',
                 "README.md:10: names DESIGN" + ".md, which is outside the project (a clone has no such file)",
                 "app/widget.cpp:3: app/made_up.cpp is not in the tree",
                 "app/widget.cpp:4: `springlab walk` is no subcommand (springlab has: run)",
                 "app/widget.cpp:5: names .." + "/shared/, which is outside the project (a clone has no such "
                 "file)"):
        if want not in out:
            problems.append(f"not said: {want}")
    # The true statements beside the planted ones must not be named.
    for line in ("README.md:4", "app/widget.cpp:1", "app/widget.cpp:2", "CONTRIBUTING.md", "docs/guide.md"):
        if line + ":" in out:
            problems.append(f"{line}, which is true, was named")
    for problem in problems:
        print(f"self-test: {problem}", file=sys.stderr)
    print("self-test: " + ("FAILED" if problems else "the check fails on each planted defect, by file:line"))
    sys.exit(1 if problems else 0)


args = sys.argv[1:]
if args == ["--self-test"]:
    self_test()
floors = "--no-floors" not in args
args = [a for a in args if a != "--no-floors"]
root = os.path.abspath(args[0] if args else ".")

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


# The fixtures the house checks run on: trees of the project's shape holding planted defects. Their
# files are read by nothing below; a comment under tests/ may give a path inside one.
FIXTURE_ROOTS = sorted(f for f in folders if re.fullmatch(r"tests/[^/]+/fixtures/[^/]+", f))


def in_fixture(path):
    return re.match(r"tests/[^/]+/fixtures/", path) is not None


_texts = {}


def read(path):
    if path not in _texts:
        _texts[path] = open(os.path.join(root, path), encoding="utf-8", errors="replace").read()
    return _texts[path]


# The sources: what a function named in the documents must be found in.
SOURCE_FOLDERS = ("core/", "app/", "python/", "tests/", "bench/", "examples/", "shaders/")
SOURCE_EXTENSIONS = (".cpp", ".hpp", ".h", ".c", ".cc", ".inl", ".py", ".js", ".cjs", ".mjs", ".html",
                     ".glsl", ".vert", ".frag", ".cmake")
sources = sorted(p for p in files if p.startswith(SOURCE_FOLDERS) and not in_fixture(p)
                 and (p.endswith(SOURCE_EXTENSIONS) or os.path.basename(p) == "CMakeLists.txt"))
all_sources = "\n".join(read(p) for p in sources)  # searched for a name only when a document gives it


def in_sources(word):
    """A word of the sources, at word boundaries."""
    at = all_sources.find(word)
    while at >= 0:
        around = all_sources[at - 1:at] + all_sources[at + len(word):at + len(word) + 1]
        if not any(c.isalnum() or c == "_" for c in around):
            return True
        at = all_sources.find(word, at + 1)
    return False


def declares(path, name):
    return re.search(rf"\b(?:class|struct|union|namespace|enum(?:\s+class)?)\s+{name}\b|\busing\s+{name}\s*=",
                     read(path)) is not None


IDENT = r"~?[A-Za-z_]\w*"
CODE_NAME = re.compile(rf"({IDENT}(?:(?:::|\.|->){IDENT})*)(\(\)|\(|$)")


def code_name_problem(name):
    """Why a function or qualified name of the documents is not in the sources, or None."""
    parts = name.replace("~", "").split("::")
    last = re.split(r"\.|->", parts[-1])  # obj.method, module.function: the last is the function
    for a, b in zip(parts, parts[1:]):
        b = re.split(r"\.|->", b)[0]
        if not in_sources(f"{a}::{b}") and not in_sources(f"{a}::~{b}") and \
                not any(declares(f, a) and re.search(rf"\b{b}\b", read(f)) for f in sources if a in read(f)):
            return f"the sources have no {a}::{b}, and no file that declares {a} names {b}"
    if not in_sources(last[-1]):
        return f"names no identifier of the sources ({', '.join(f.rstrip('/') for f in SOURCE_FOLDERS)})"
    return None


# The command line: the subcommands app/ gives CLI11, their own subcommands and every flag.
commands, subcommands, flags = set(), {}, {"--help", "-h", "--version"}
for p in sorted(files):
    if p.startswith("app/") and p.endswith(".cpp") and not in_fixture(p):
        text = read(p)
        if "add_subcommand" not in text and "add_option" not in text and "add_flag" not in text:
            continue
        commands.update(re.findall(r"\bapp\.add_subcommand\(\s*\"([\w-]+)\"", text))
        parent = dict(re.findall(r"CLI::App\*\s*(\w+)\s*=\s*app\.add_subcommand\(\s*\"([\w-]+)\"", text))
        for var, name in re.findall(r"\b(\w+)->add_subcommand\(\s*\"([\w-]+)\"", text):
            if var in parent:
                subcommands.setdefault(parent[var], set()).add(name)
        for spec in re.findall(r"\"((?:-\w,\s*)?--?[A-Za-z][\w-]*(?:,\s*--?[A-Za-z][\w-]*)*)\"", text):
            flags.update(f.strip() for f in spec.split(","))
# A browser check's title may begin with springlab's name (`springlab in words`): not a command.
check_titles = [t for p in files if p.startswith("tests/web/") and p.endswith(".cjs")
                for t in re.findall(r"\bcheck\(\s*\"([^\"]+)\"", read(p))]
COMMAND = re.compile(r"\s*(?:\$\s+)?(?:[\w./-]*/)?springlab\s+(.*)")
LOWER_WORD = re.compile(r"[a-z][a-z0-9-]*")


def command_problems(span):
    """What is wrong with `springlab WORD ...` (a span of code or a line of a code block)."""
    m = COMMAND.fullmatch(span)
    if not m or any(t.startswith(span.strip()) for t in check_titles):
        return []
    rest = re.sub(r"\s#\s.*", "", m.group(1))  # a shell comment after the command
    words, problems = rest.split(), []
    if words and LOWER_WORD.fullmatch(words[0]):
        if words[0] not in commands:
            return [f"`springlab {words[0]}` is no subcommand (springlab has: {', '.join(sorted(commands))})"]
        own = subcommands.get(words[0])
        if own and len(words) > 1 and LOWER_WORD.fullmatch(words[1]) and words[1] not in own:
            problems.append(f"`springlab {words[0]} {words[1]}`: {words[0]} has no subcommand {words[1]} "
                            f"(it has: {', '.join(sorted(own))})")
    for flag in re.findall(r"(?<![\w-])(--?[A-Za-z][\w-]*)", rest):
        if flag not in flags:
            problems.append(f"`springlab {' '.join(words[:1])} {flag}`: no command has the flag {flag}")
    return problems


# Sections: a document and a heading in quotes after it.
SECTION_LINK = re.compile(r"\[[^\]]*\]\(([^)\s#]+\.md)\)(?:,|'s)?\s\(?\"([^\"\n]{2,80})\"")
SECTION_PATH = re.compile(r"(?<![\w./-])((?:\.\.?/)*[\w][\w./-]*\.md)(?:,|'s)?\s\(?\"([^\"\n]{2,80})\"")
_headings = {}


def headings(path):
    """A document's headings, its paragraphs' bold leads (`**A scene kind**`) and the words of a
    heading before its colon, as they read (code and emphasis marks dropped)."""
    if path not in _headings:
        found, in_code = set(), False
        for line in read(path).splitlines():
            if line.startswith("```"):
                in_code = not in_code
            m = re.match(r"#{1,6} +(.*?) *#* *$", line) or re.match(r"\*\*([^*]+?)\.?\*\*", line)
            if m and not in_code:
                text = re.sub(r"[`*]", "", re.sub(r"\{#[\w-]+\}", "", m.group(1))).strip()
                found.update({text, text.split(":")[0].strip()})
        _headings[path] = found
    return _headings[path]


def resolve_document(name, folder):
    """The document a section reference names: from the root, from the file's folder, or the one
    file of the tree whose path ends so."""
    for path in (os.path.normpath(os.path.join(folder, name)), name):
        if path in files:
            return path
    endings = [p for p in files if p.endswith("/" + name) and not in_fixture(p)]
    return endings[0] if len(endings) == 1 else None


def section_problems(text, folder, links_relative):
    problems = []
    for regex in (SECTION_LINK, SECTION_PATH):
        for name, heading in regex.findall(text):
            checked["sections"] += 1
            path = os.path.normpath(os.path.join(folder, name)) if regex is SECTION_LINK and links_relative \
                else resolve_document(name, folder)
            if path is None or path not in files:
                problems.append(f"{name}, whose section \"{heading}\" is named, is no document of the tree")
            elif heading.replace("`", "") not in headings(path):
                problems.append(f"{path} has no heading or bold lead \"{heading}\"")
    return problems


def path_problems(text, folder, fixture_fallback=False):
    """The repository paths and files with a folder in a text that are not in the tree."""
    problems = []
    text = re.sub(r"<[\w./+-]+>", " ", URL.sub(" ", text))  # system headers, `<backends/imgui_impl_glfw.h>`
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
            if not (exists(path) or exists(path + ".*")  # a unit named by its files' stem
                    or fixture_fallback and any(exists(f"{f}/{path}") for f in FIXTURE_ROOTS)):
                problems.append(f"{word} is not in the tree")
        elif EXTENSION.search(word) and re.match(r"[A-Za-z_]", first):
            checked["files with a folder"] += 1
            if not exists_as_ending(word):
                problems.append(f"{word} is no file's path or the end of one")
    return problems


documents = ["README.md", "CONTRIBUTING.md"]
documents += sorted("docs/" + n for n in os.listdir(os.path.join(root, "docs")) if n.endswith(".md"))
documents += sorted(f"assets/{d}/README.md" for d in sorted(os.listdir(os.path.join(root, "assets")))
                    if os.path.isfile(os.path.join(root, "assets", d, "README.md"))) \
    if os.path.isdir(os.path.join(root, "assets")) else []

LINK = re.compile(r"\]\(([^)\s]+)\)")
URL = re.compile(r"\b[a-z][a-z0-9+.-]*://\S+|\bwww\.\S+|\b[\w.-]+\.(?:com|org|io|net)/\S*")
WORD = re.compile(r"[A-Za-z0-9_.*~$+/-]*/[A-Za-z0-9_.*~$+/-]*")
TEST = re.compile(r"(?<![\w./-])([A-Z][A-Za-z0-9]*(?:/[A-Z][A-Za-z0-9]*)?\.(?:[A-Z][A-Za-z0-9_]*\*?|\*))(?![\w(*])")
EXTENSION = re.compile(r"\.(?:[A-Za-z][A-Za-z0-9]{0,7}|\*)$")

failures = []
checked = {"paths": 0, "files with a folder": 0, "links": 0, "anchors": 0, "tests": 0, "functions": 0,
           "commands": 0, "sections": 0}
for doc in documents:
    folder = os.path.dirname(doc)
    in_code = False
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
        # Sections named in quotes after a document.
        failures += [f"{where}: {p}" for p in section_problems(line, folder, links_relative=True)]
        text = URL.sub(" ", LINK.sub("] ", line))
        # Paths and file names with a folder.
        failures += [f"{where}: {p}" for p in path_problems(text, folder)]
        # Test names.
        for name in TEST.findall(text):
            if name in NOT_TESTS:
                continue
            checked["tests"] += 1
            if not test_exists(name):
                failures.append(f"{where}: the test {name} is not in tests/ (no TEST, TEST_P, TEST_F or add_test)")
        # Functions and commands in code format; a code block's lines as commands.
        if line.startswith("```"):
            in_code = not in_code
            continue
        spans = [line.rstrip("\n")] if in_code else re.findall(r"`([^`\n]+)`", line)
        for span in spans:
            m = None if in_code else CODE_NAME.match(span)
            if m and (m.group(2) == "()" or (m.group(2) == "(" and re.search(r"::|\.|->", m.group(1)))
                      or (m.group(2) == "" and "::" in m.group(1))):
                checked["functions"] += 1
                problem = code_name_problem(m.group(1))
                if problem:
                    failures.append(f"{where}: `{span if len(span) < 60 else m.group(1) + '(...)'}`"
                                    f"{':' if problem.startswith('the') else ''} {problem}")
            if COMMAND.fullmatch(span):
                checked["commands"] += 1
                failures += [f"{where}: {p}" for p in command_problems(span)]

# The sources' comments.
C_LIKE = (".cpp", ".hpp", ".h", ".c", ".cc", ".inl", ".js", ".cjs", ".mjs", ".glsl", ".vert", ".frag")
HASH = (".sh", ".cmake", ".txt", ".toml", ".cfg", ".yml", ".yaml", ".supp")
C_TOKENS = re.compile(r'R"([^(\s]{0,16})\(.*?\)\1"|"(?:\\.|[^"\\\n])*"|`(?:\\.|[^`\\])*`'
                      r"|//[^\n]*|/\*.*?\*/|'(?:\\.|[^'\\\n])*'", re.S)
COMMENT_FOLDERS = ("core/", "app/", "python/", "tests/", "scripts/", "bench/", "examples/", "shaders/",
                   "cmake/", ".ci/")


def comments(path, text):
    """(line, comment text) for each comment of a source: `//` and `/* */` in C++, JavaScript and
    GLSL (strings skipped); `#` in shell, CMake, text and Python, and Python's docstrings."""
    found = []
    if path.endswith(C_LIKE):
        for m in C_TOKENS.finditer(text):
            if m.group(0).startswith(("//", "/*")):
                found.append((text.count("\n", 0, m.start()) + 1, m.group(0)))
    elif path.endswith(".py"):
        lines = text.split("\n")
        for m in re.finditer(r'^[ \t]*[rbu]?("""|\'\'\')(.*?)\1', text, re.M | re.S):  # docstrings
            found.append((text.count("\n", 0, m.start()) + 1, m.group(2)))
        for k, line in enumerate(lines, 1):
            m = re.search(r"(?:^|\s)#(?!!)(.*)", line)
            if m and line.count('"', 0, m.start()) % 2 == 0 and line.count("'", 0, m.start()) % 2 == 0:
                found.append((k, m.group(1)))
    elif path.endswith(HASH) or os.path.basename(path) == "CMakeLists.txt" or \
            "." not in os.path.basename(path) and text.startswith("#!"):
        for k, line in enumerate(text.split("\n"), 1):
            m = re.search(r"(?:^|\s)#(?![!{])(.*)", line)
            if m:
                found.append((k, m.group(1)))
    return found


commented = sorted(p for p in files if (p.startswith(COMMENT_FOLDERS)
                                       or "/" not in p and p.endswith((".py", ".txt", ".toml", ".cmake")))
                   and not in_fixture(p))
comments_read = 0
for p in commented:
    if os.path.getsize(os.path.join(root, p)) > 1_000_000:
        continue
    text = read(p)
    if "\0" in text[:4096]:
        continue
    folder = os.path.dirname(p)
    for first_line, comment in comments(p, text):
        comments_read += 1
        if "/" not in comment and ".md" not in comment and "springlab " not in comment:
            continue  # nothing to check: no path, no section, no command
        for k, line in enumerate(comment.split("\n")):
            if "/" not in line and ".md" not in line and "springlab " not in line:
                continue
            where = f"{p}:{first_line + k}"
            in_tests = p.startswith("tests/")
            failures += [f"{where}: {x}" for x in path_problems(line, folder, fixture_fallback=in_tests)]
            failures += [f"{where}: {x}" for x in section_problems(line, folder, links_relative=False)]
            for span in re.findall(r"`([^`\n]+)`", line):
                if COMMAND.fullmatch(span):
                    checked["commands"] += 1
                    failures += [f"{where}: {x}" for x in command_problems(span)]

# Nothing names the notes outside the project: a clone has none of them.
# (Written in pieces, so that this file does not name them itself.)
NOTES = (b"DESIGN", b"PLATFORM", b"STYLE", b"NUMERICS")
FOREIGN = re.compile(rb"(?<![\w-])(?:" + b"|".join(n + rb"\.md" for n in NOTES) + rb")|\.\./" + b"shared/")
for p in sorted(files):
    if in_fixture(p) or os.path.getsize(os.path.join(root, p)) > 5_000_000:
        continue
    data = open(os.path.join(root, p), "rb").read()
    if b"../" + b"shared/" not in data and not any(n in data for n in NOTES):
        continue
    for m in FOREIGN.finditer(data):
        number = data.count(b"\n", 0, m.start()) + 1
        failures.append(f"{p}:{number}: names {m.group(0).decode()}, which is outside the project "
                        "(a clone has no such file)")

total = sum(checked.values())
print(f"paths_test: {len(documents)} documents and {comments_read} comments of {len(commented)} files read, "
      f"{total} names checked (" + ", ".join(f"{v} {k}" for k, v in checked.items()) + f"); "
      f"{len(sources)} sources, {len(commands)} subcommands, {len(flags)} flags")
FLOORS = {"paths and files with a folder": (checked["paths"] + checked["files with a folder"], 500),
          "test names": (checked["tests"], 20), "functions": (checked["functions"], 60),
          "commands": (checked["commands"], 60), "sections": (checked["sections"], 25),
          "subcommands": (len(commands), 8), "comments": (comments_read, 5000)}
for what, (found, least) in FLOORS.items():
    if floors and found < least:
        failures.append(f"only {found} {what} found (at least {least} expected): the test has stopped reading them")
if failures:
    print("\n".join(failures))
    sys.exit(1)
