#!/usr/bin/env python3
"""springlab's icon for the web app manifest, drawn at build time (app/web/CMakeLists.txt): a
pinned anchor, a spring and its mass on the app's scene background, anti-aliased from distances
to the shapes (no imaging library: a PNG written with zlib). The picture keeps to the middle
60 %, so the square also serves as a maskable icon (a launcher's circle or rounded square).
Usage: make_icon.py SIZE OUT.png"""
import math
import os
import struct
import sys
import zlib

BACKGROUND = (0x1A, 0x1C, 0x21)  # the scene's background (app/draw/frame.hpp)
ANCHOR = (0x9A, 0xA0, 0xA8)
SPRING = (0x66, 0xB8, 0xFF)  # the theme's slider blue (app/ui/theme.cpp)
MASS = (0xE6, 0x9F, 0x00)  # Okabe and Ito's orange (app/draw/palette.hpp)


def segment_distance(px, py, ax, ay, bx, by):
    dx, dy = bx - ax, by - ay
    t = max(0.0, min(1.0, ((px - ax) * dx + (py - ay) * dy) / (dx * dx + dy * dy)))
    return math.hypot(px - ax - t * dx, py - ay - t * dy)


def draw(size):
    s = size / 100.0  # the picture in units of 1/100 of the side
    # The spring: a zigzag of 6 coils from the anchor down to the mass, with straight ends.
    top, bottom, half = 29.0, 63.0, 9.0
    points = [(50.0, 24.0), (50.0, top)]
    coils = 6
    for k in range(2 * coils):
        y = top + (bottom - top) * (k + 0.5) / (2 * coils)
        points.append((50.0 + (half if k % 2 == 0 else -half), y))
    points += [(50.0, bottom), (50.0, 66.0)]
    segments = [(a[0] * s, a[1] * s, b[0] * s, b[1] * s) for a, b in zip(points, points[1:])]
    spring_w = 2.2 * s
    anchor = (33.0 * s, 20.0 * s, 67.0 * s, 20.0 * s)
    anchor_w = 5.0 * s
    mass_c, mass_r = (50.0 * s, 72.0 * s), 9.0 * s
    rows = []
    for y in range(size):
        row = bytearray([0])  # filter: none
        py = y + 0.5
        for x in range(size):
            px = x + 0.5
            colour = BACKGROUND
            # Each shape's coverage of the pixel from its distance (a one-pixel ramp), painted in order.
            for shape_colour, coverage in (
                (ANCHOR, 0.5 + anchor_w / 2 - segment_distance(px, py, *anchor)),
                (SPRING, 0.5 + spring_w / 2 - min(segment_distance(px, py, *seg) for seg in segments)
                 if 40 * s - 2 < px < 60 * s + 2 and 22 * s < py < 68 * s else -1.0),
                (MASS, 0.5 + mass_r - math.hypot(px - mass_c[0], py - mass_c[1])),
            ):
                a = max(0.0, min(1.0, coverage))
                if a > 0.0:
                    colour = tuple(round(c * (1 - a) + n * a) for c, n in zip(colour, shape_colour))
            row += bytes(colour)
        rows.append(bytes(row))
    return b"".join(rows)


def png(size, pixels):
    def chunk(kind, data):
        body = kind + data
        return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body) & 0xFFFFFFFF)

    header = struct.pack(">IIBBBBB", size, size, 8, 2, 0, 0, 0)  # 8-bit RGB
    return b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", zlib.compress(pixels, 9)) + chunk(b"IEND", b"")


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    size = int(sys.argv[1])
    with open(sys.argv[2] + ".tmp", "wb") as f:
        f.write(png(size, draw(size)))
    os.replace(sys.argv[2] + ".tmp", sys.argv[2])


if __name__ == "__main__":
    main()
