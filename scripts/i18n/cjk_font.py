#!/usr/bin/env python3
"""The CJK font springlab draws its translations with: Noto Sans CJK SC (Debian's fonts-noto-cjk)
cut down to the characters the translations use, with fontTools' subsetter, so that the browser's
download grows by what is needed (about 0.5 MB for ~1000 characters), not the 16 MB of the whole.
The characters are those from U+2E80 on (CJK punctuation, ideographs, full-width forms) in every
msgstr of the catalogs given; everything below is drawn by DejaVu Sans, as in English. The app
builds its glyph ranges from the same rule (ui/theme.cpp), so it asks the font for nothing it lacks.

Usage: cjk_font.py --font NotoSansCJK-Regular.ttc --out springlab-cjk.otf CATALOG.po...
"""
import argparse
import re
import sys

from fontTools import subset
from fontTools.ttLib import TTCollection

FIRST_CJK = 0x2E80


def po_strings(path):
    """The msgstr texts of a PO file (simple parser: one or more quoted lines after msgstr)."""
    out, current = [], None
    for line in open(path, encoding="utf-8"):
        line = line.strip()
        if line.startswith("msgstr"):
            current = [line.split(" ", 1)[1]]
            out.append(current)
        elif line.startswith('"') and current is not None:
            current.append(line)
        else:
            current = None
    return ["".join(eval(part) for part in parts) for parts in out]  # PO strings are C literals


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--font", required=True)
    ap.add_argument("--name", default="Noto Sans CJK SC", help="the face to take from a collection")
    ap.add_argument("--out", required=True)
    ap.add_argument("catalogs", nargs="+")
    a = ap.parse_args()
    chars = sorted({ord(c) for path in a.catalogs for text in po_strings(path) for c in text if ord(c) >= FIRST_CJK})
    collection = TTCollection(a.font)
    faces = [f for f in collection.fonts if f["name"].getDebugName(4) == a.name]
    if not faces:
        sys.exit(f"cjk_font.py: {a.font} has no face named '{a.name}'")
    font = faces[0]
    options = subset.Options()
    options.layout_features = []  # ImGui draws glyph by glyph: no shaping tables
    options.name_IDs = ["*"]      # keep the licence and the names (OFL)
    options.notdef_outline = True
    options.hinting = False
    sub = subset.Subsetter(options)
    sub.populate(unicodes=chars)
    sub.subset(font)
    font.save(a.out)
    missing = [c for c in chars if c not in font.getBestCmap()]
    if missing:
        sys.exit("cjk_font.py: the font lacks " + "".join(map(chr, missing)))
    print(f"cjk_font.py: {len(chars)} characters -> {a.out}")


if __name__ == "__main__":
    main()
