#!/usr/bin/env python3
"""Writes the swarm's image-colouring presets into assets/textures/ (standard library only).

colors.png   16x16: hue across, white-to-full saturation down (like the seed's "Colors").
sunset.png   128x128: a sun over striped waves, so the start positions are recognisable.
Run from the repository root: python3 scripts/make_swarm_textures.py
"""
import colorsys
import math
import struct
import zlib
from pathlib import Path


def write_png(path, width, height, pixel):
    rows = b"".join(
        b"\x00" + b"".join(bytes(pixel(x, y)) for x in range(width)) for y in range(height))
    def chunk(tag, data):
        return struct.pack(">I", len(data)) + tag + data + struct.pack(">I", zlib.crc32(tag + data))
    png = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0))
    png += chunk(b"IDAT", zlib.compress(rows, 9)) + chunk(b"IEND", b"")
    Path(path).write_bytes(png)


def rgb(r, g, b):
    return [max(0, min(255, round(255 * c))) for c in (r, g, b)]


def colors(x, y):
    r, g, b = colorsys.hsv_to_rgb(x / 16.0, 0.25 + 0.75 * y / 15.0, 1.0)
    return rgb(r, g, b)


def sunset(x, y):
    u, v = (x + 0.5) / 128.0, (y + 0.5) / 128.0  # v = 0 at the top
    horizon = 0.58
    if v < horizon:  # sky: deep violet at the top to orange at the horizon, and the sun
        t = v / horizon
        sky = (0.15 + 0.85 * t, 0.05 + 0.45 * t * t, 0.35 - 0.2 * t)
        d = math.hypot(u - 0.5, v - 0.45)
        if d < 0.16:
            return rgb(1.0, 0.92 - 0.8 * d, 0.3)
        return rgb(*sky)
    wave = math.sin(2 * math.pi * (6 * u + 10 * (v - horizon) ** 0.7 * 3))
    depth = (v - horizon) / (1 - horizon)
    base = (0.0, 0.35 + 0.25 * (1 - depth), 0.55 + 0.3 * (1 - depth))
    if wave > 0.6:
        return rgb(0.85, 0.95, 1.0)
    return rgb(*base)


out = Path("assets/textures")
out.mkdir(parents=True, exist_ok=True)
write_png(out / "colors.png", 16, 16, colors)
write_png(out / "sunset.png", 128, 128, sunset)
