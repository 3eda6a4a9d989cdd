#!/usr/bin/env python3
"""Writes the inputs of docs/density.md's pictures into a directory:

  gradient.png  a smooth radial gradient (dark centre, light rim)
  face.png      a face drawn procedurally from smooth shapes (a photo-like
                grayscale image for stippling, made here so nothing is shipped)
  mask.png      a ring and a bar, dark where samples go
  region.geojson  a polygon with a hole and a second polygon
  fixed.csv     points to keep: a circle and a diagonal of points 0.025 apart

Usage: scripts/density_inputs.py OUTDIR. Standard library only (PNG by zlib).
"""
import math
import os
import struct
import sys
import zlib


def write_png(path, width, height, grey):
    """grey(x, y) in [0, 1] (0 black) for pixel centres; 8-bit grayscale PNG."""
    rows = bytearray()
    for y in range(height):
        rows.append(0)  # filter: none
        for x in range(width):
            g = min(1.0, max(0.0, grey(x + 0.5, y + 0.5)))
            rows.append(int(round(g * 255)))

    def chunk(kind, data):
        body = kind + data
        return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body) & 0xFFFFFFFF)

    header = struct.pack(">IIBBBBB", width, height, 8, 0, 0, 0, 0)
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", zlib.compress(bytes(rows), 9)) +
                chunk(b"IEND", b""))


def smoothstep(e0, e1, x):
    t = min(1.0, max(0.0, (x - e0) / (e1 - e0)))
    return t * t * (3 - 2 * t)


def gradient(x, y, size=256):
    d = math.hypot(x / size - 0.5, y / size - 0.5) / 0.7071
    return d


def face(x, y, size=256):
    u, v = x / size - 0.5, y / size - 0.5  # v grows downward
    tone = 0.97 - 0.2 * smoothstep(0.0, 0.7, math.hypot(u, v + 0.1))  # a lit background
    head = math.hypot(u / 0.33, (v + 0.02) / 0.42)
    if head < 1.0:
        # A lit sphere: light from the upper left.
        nz = math.sqrt(max(0.0, 1 - head * head))
        light = 0.25 + 0.6 * max(0.0, (-0.5 * u / 0.33 - 0.5 * (v + 0.02) / 0.42 + 0.7 * nz))
        tone = min(tone, 0.15 + 0.8 * light) * smoothstep(1.0, 0.95, head) + tone * (1 - smoothstep(1.0, 0.95, head))
    # Hair: a dark cap over the top of the head.
    hair = math.hypot(u / 0.36, (v + 0.12) / 0.38)
    if hair < 1.0 and v < -0.18 + 0.08 * math.cos(u * 9):
        tone = min(tone, 0.12 + 0.1 * smoothstep(0.6, 1.0, hair))
    for ex in (-0.12, 0.12):  # eyes: dark pupils in light whites, brows above
        e = math.hypot((u - ex) / 0.065, (v + 0.04) / 0.035)
        if e < 1.0:
            tone = 0.95 - 0.85 * smoothstep(0.55, 0.35, math.hypot((u - ex) / 0.03, (v + 0.04) / 0.03))
        brow = math.hypot((u - ex) / 0.075, (v + 0.11) / 0.014)
        tone = min(tone, 0.1 + 0.9 * smoothstep(0.6, 1.0, brow))
    nose = math.hypot((u + 0.02) / 0.03, (v - 0.1) / 0.02)
    tone = min(tone, 0.3 + 0.7 * smoothstep(0.5, 1.0, nose))
    mouth = abs(v - 0.2 + 1.6 * u * u) / 0.012
    if abs(u) < 0.12:
        tone = min(tone, 0.15 + 0.85 * smoothstep(0.5, 1.5, mouth))
    return tone


def mask(x, y, size=256):
    u, v = x / size - 0.5, y / size - 0.5
    ring = 0.2 < math.hypot(u + 0.1, v) < 0.35
    bar = 0.2 < u < 0.42 and abs(v) < 0.4
    return 0.0 if (ring or bar) else 1.0


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else "."
    os.makedirs(out, exist_ok=True)
    write_png(os.path.join(out, "gradient.png"), 256, 256, gradient)
    write_png(os.path.join(out, "face.png"), 256, 256, face)
    write_png(os.path.join(out, "mask.png"), 256, 256, mask)
    with open(os.path.join(out, "region.geojson"), "w") as f:
        f.write('{"type": "MultiPolygon", "coordinates": [\n'
                '  [[[0.05, 0.05], [0.6, 0.1], [0.55, 0.9], [0.1, 0.95], [0.05, 0.05]],\n'
                '   [[0.2, 0.3], [0.4, 0.3], [0.35, 0.7], [0.2, 0.65], [0.2, 0.3]]],\n'
                '  [[[0.7, 0.2], [0.95, 0.5], [0.7, 0.8], [0.7, 0.2]]]]}\n')
    with open(os.path.join(out, "fixed.csv"), "w") as f:
        # A circle and a diagonal of points 0.025 apart: rows no random set
        # draws, so the picture shows which points were fixed.
        f.write("x,y\n")
        for i in range(75):
            a = 2 * math.pi * i / 75
            f.write("%.6f,%.6f\n" % (0.55 + 0.3 * math.cos(a), 0.55 + 0.3 * math.sin(a)))
        for i in range(12):
            f.write("%.6f,%.6f\n" % (0.05 + 0.0177 * i, 0.05 + 0.0177 * i))


if __name__ == "__main__":
    main()
