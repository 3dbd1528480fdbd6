#!/usr/bin/env python3
"""The English strings springlab's data shows, as a gettext template (POT) on standard output: the
lessons' titles, summaries, step titles, captions and prompts (assets/lessons/*.json), and the
scenes' descriptions (assets/scenes/*.json). The app passes each through tr() where it shows it.

Usage: data_strings.py ROOT
"""
import glob
import json
import os
import sys


def po_quote(text):
    return '"' + text.replace("\\", "\\\\").replace('"', '\\"').replace("\n", "\\n").replace("\t", "\\t") + '"'


def main(root):
    entries = {}  # text -> where

    def add(text, where):
        if isinstance(text, str) and text.strip():
            entries.setdefault(text, where)

    for path in sorted(glob.glob(os.path.join(root, "assets", "lessons", "*.json"))):
        name = os.path.relpath(path, root)
        lesson = json.load(open(path, encoding="utf-8"))
        add(lesson.get("title"), f"{name}:title")
        add(lesson.get("summary"), f"{name}:summary")
        for k, step in enumerate(lesson.get("steps", [])):
            for field in ("title", "caption", "try"):
                add(step.get(field), f"{name}:steps/{k}/{field}")
    for path in sorted(glob.glob(os.path.join(root, "assets", "scenes", "*.json"))):
        name = os.path.relpath(path, root)
        add(json.load(open(path, encoding="utf-8")).get("description"), f"{name}:description")
    out = ['msgid ""', 'msgstr ""', '"Content-Type: text/plain; charset=UTF-8\\n"', ""]
    for text, where in entries.items():
        out += [f"#: {where}", "msgid " + po_quote(text), 'msgstr ""', ""]
    sys.stdout.write("\n".join(out))


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else ".")
