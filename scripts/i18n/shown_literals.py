#!/usr/bin/env python3
"""The English strings the app shows, found in its code: every string literal passed to a call that
puts text on screen (ImGui's widgets, springlab's text and chart helpers) or assigned to a chart's
title or label. Each must reach the screen through tr() (springlab/text.hpp), so that it is
translated; a literal that does not is reported with its file and line.

Usage: shown_literals.py [--fix] FILE...
  (no option)  report the literals not wrapped in tr() or N_(); exit 1 if there is any
  --fix        wrap them in tr() in place (a one-off; read the diff)
Skipped: literals with no two letters in a row ("%s", "%.3f", "s"), ImGui IDs ("##open"), JSON
(a literal with an escaped quote), and lines marked "// not shown" or "// symbols" (dt, k_s: the same
in every language); a "// not shown" comment on a line of its own marks the whole statement below it
(one that clang-format spreads over several lines).
"""
import re
import sys

# Calls whose string arguments are shown. (Begin is not here: a window's name is its identity too,
# and is written as tr("Title") + "###id" by hand.)
CALLS = r"(?:ImGui::(?:Button|SmallButton|Checkbox|BeginCombo|Selectable|CollapsingHeader|SliderInt|SliderFloat|" \
        r"InputInt|InputTextWithHint|Text|TextDisabled|TextColored|TextUnformatted|TextWrapped|SetTooltip|" \
        r"MenuItem|BeginMenu|BulletText|RadioButton|CalcTextSize)|text_wrapped|text_wrapped_disabled|slider|fmt|" \
        r"draw_note|label_text|std::snprintf|series)"
CALL_RE = re.compile(r"(?<![\w:])" + CALLS + r"\s*\(")
ASSIGN_RE = re.compile(r"(?:\breturn\b|(?:std::string|const char\*)\s+\w+\s*=|[\w.\]]\s*\+?=(?!=))\s*")
LETTERS = re.compile(r"[A-Za-z]{2,}")


def literal_end(text, i):
    """The index after the string literal starting at text[i] == '"'."""
    j = i + 1
    while text[j] != '"':
        j += 2 if text[j] == "\\" else 1
    return j + 1


def group_end(text, i):
    """Adjacent literals ("a" "b") are one string: the index after the last."""
    end = literal_end(text, i)
    while True:
        k = end
        while k < len(text) and text[k] in " \t\r\n":
            k += 1
        if k < len(text) and text[k] == '"':
            end = literal_end(text, k)
        else:
            return end


def call_span(text, open_paren):
    """The index of the ')' closing the call opened at text[open_paren]."""
    depth, i = 0, open_paren
    while i < len(text):
        c = text[i]
        if c == '"':
            i = literal_end(text, i)
            continue
        if c == "'":
            i = text.index("'", i + 2 if text[i + 1] == "\\" else i + 1) + 1
            continue
        if c == "(":
            depth += 1
        elif c == ")":
            depth -= 1
            if depth == 0:
                return i
        i += 1
    return len(text)


def wrapped(text, start):
    before = text[:start].rstrip()
    return before.endswith("tr(") or before.endswith("N_(")


def shown(text, start, end):
    body = text[start:end]
    if '"##' in body[:3] or body.startswith('"##'):
        return False
    if '\\"' in body or body in ('"true"', '"false"'):  # JSON or markup the page reads, not text
        return False
    return bool(LETTERS.search(re.sub(r"%[-+ #0-9.*]*(?:ll|l)?[a-zA-Z]", "", body)))


def code_mask(text):
    """True at each index that is code: not in a string or character literal, nor a comment."""
    mask = [True] * len(text)
    i = 0
    while i < len(text):
        c = text[i]
        if text.startswith("//", i):
            end = text.find("\n", i)
            end = len(text) if end < 0 else end
        elif text.startswith("/*", i):
            end = text.find("*/", i) + 2
        elif c == '"':
            end = literal_end(text, i)
        elif c == "'" and not text[i - 1].isalnum():
            end = text.index("'", i + 2 if text[i + 1] == "\\" else i + 1) + 1
        else:
            i += 1
            continue
        for k in range(i, end):
            mask[k] = False
        i = end
    return mask


def candidates(text):
    spans = []
    mask = code_mask(text)
    for m in CALL_RE.finditer(text):
        if not mask[m.start()]:
            continue
        open_paren = m.end() - 1
        close = call_span(text, open_paren)
        spans.append((open_paren + 1, close))
    for m in ASSIGN_RE.finditer(text):
        if not mask[m.start()]:
            continue
        end = m.end()
        while end < len(text) and (text[end] != ";" or not mask[end]):
            end += 1
        spans.append((m.end(), end))
    # Statements below a "// not shown" line of their own: from that line to the statement's ';'.
    statements = []
    for m in re.finditer(r"^[ \t]*// not shown[^\n]*\n", text, re.M):
        end = m.end()
        while end < len(text) and (text[end] != ";" or not mask[end]):
            end += 1
        statements.append((m.end(), end))
    found = set()
    for a, b in spans:
        i = a
        while i < b:
            if text[i] == '"' and text[i - 1] != "'" and text[i - 1] != "\\":
                end = group_end(text, i)
                # A string literal's prefix (u8"", R"") or an #include: not shown text.
                line_end = text.find("\n", i)
                line = text[text.rfind("\n", 0, i):line_end]
                marked = "// not shown" in line or "// symbols" in line
                marked = marked or any(s <= i < e for s, e in statements)
                if not text[i - 1].isalnum() and not marked and shown(text, i, end) and not wrapped(text, i):
                    found.add((i, end))
                i = end
            else:
                i += 1
    return sorted(found)


def main(argv):
    fix = "--fix" in argv
    files = [a for a in argv if a != "--fix"]
    bad = 0
    for path in files:
        text = open(path, encoding="utf-8").read()
        found = candidates(text)
        if fix:
            for start, end in reversed(found):
                text = text[:start] + "tr(" + text[start:end] + ")" + text[end:]
            open(path, "w", encoding="utf-8").write(text)
        else:
            for start, end in found:
                line = text.count("\n", 0, start) + 1
                print(f"{path}:{line}: shown but not translated: {text[start:end][:70]}")
                bad += 1
    if bad:
        print(f"{bad} shown string(s) do not go through tr() (springlab/text.hpp)", file=sys.stderr)
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
