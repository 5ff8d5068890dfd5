#!/usr/bin/env python3
"""Writes the small textures of lab 4 (no third-party modules: PNG by hand with zlib).

bricks.png  128x128  a brick wall, for the flat object (wrap and filter modes show on it)
uvgrid.png  256x128  16x8 coloured cells with dark lines, hue by s and brightness by t, so
                     the seam, the poles and any stretching show on the sphere and torus
bumps.png   128x128  height map (grey = height) of 2x2 round bumps, for Blinn bump mapping on the torus
Run it from anywhere; it writes next to itself.
"""
import colorsys
import os
import struct
import zlib


def write_png(path, w, h, pixel):
    rows = b"".join(b"\x00" + bytes(c for x in range(w) for c in pixel(x, y)) for y in range(h))
    def chunk(tag, data):
        return struct.pack(">I", len(data)) + tag + data + struct.pack(">I", zlib.crc32(tag + data) & 0xFFFFFFFF)
    png = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0))
    png += chunk(b"IDAT", zlib.compress(rows, 9)) + chunk(b"IEND", b"")
    with open(path, "wb") as f:
        f.write(png)


def bricks(x, y):
    row = y // 16
    off = 16 if row % 2 else 0
    mortar = y % 16 < 2 or (x + off) % 32 < 2
    if mortar:
        return (200, 200, 190)
    shade = ((x + off) // 32 * 37 + row * 23) % 40  # each brick a slightly different red
    return (150 + shade, 60 + shade // 2, 45)


def uvgrid(x, y):
    cx, cy = x // 16, y // 16  # 16 columns (s), 8 rows (t, top row = north = t near 1)
    if x % 16 == 0 or y % 16 == 0:
        return (20, 20, 20)
    r, g, b = colorsys.hsv_to_rgb(cx / 16.0, 0.75, 0.45 + 0.07 * (7 - cy))
    if cx == 0 and 4 <= x % 16 <= 11 and 4 <= y % 16 <= 11:  # a white square marks s = 0
        return (255, 255, 255)
    return (int(r * 255), int(g * 255), int(b * 255))


def bumps(x, y):
    # Cell centres at (32, 32) + 64·k; height (1 - (d/26)²)² inside radius 26: smooth to
    # first order at the rim, so the central differences of the shader see no kink.
    dx = (x % 64) - 31.5
    dy = (y % 64) - 31.5
    q = (dx * dx + dy * dy) / (26.0 * 26.0)
    h = (1.0 - q) ** 2 if q < 1.0 else 0.0
    v = int(round(255 * h))
    return (v, v, v)


here = os.path.dirname(os.path.abspath(__file__))
write_png(os.path.join(here, "bricks.png"), 128, 128, bricks)
write_png(os.path.join(here, "uvgrid.png"), 256, 128, uvgrid)
write_png(os.path.join(here, "bumps.png"), 128, 128, bumps)
