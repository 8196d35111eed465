#!/usr/bin/env python3
"""Generates assets/textures/tiles.png: the pool-floor tiles the ripples view refracts.

Our own asset, made with the standard library only (zlib + struct): 256x256 RGB, 4x4 glazed
tiles with grout lines, a slight per-tile tint and a soft bevel, so it repeats seamlessly.
"""
import random
import struct
import sys
import zlib

SIZE, TILES, GROUT = 256, 4, 3


def pixel(x, y, tints):
    t = SIZE // TILES
    tx, ty, lx, ly = x // t, y // t, x % t, y % t
    edge = min(lx, ly, t - 1 - lx, t - 1 - ly)
    if edge < GROUT:
        return (188, 186, 176)
    base = tints[ty % TILES][tx % TILES]
    bevel = min(1.0, (edge - GROUT) / 6.0)
    shade = 0.82 + 0.18 * bevel + (0.05 if lx < t // 2 and ly < t // 2 else 0.0) * bevel
    return tuple(max(0, min(255, int(c * shade))) for c in base)


def main(path):
    rnd = random.Random(7)
    tints = [[(int(210 + rnd.uniform(-12, 12)), int(228 + rnd.uniform(-10, 10)), int(236 + rnd.uniform(-8, 8)))
              for _ in range(TILES)] for _ in range(TILES)]
    raw = b"".join(b"\0" + bytes(c for x in range(SIZE) for c in pixel(x, y, tints)) for y in range(SIZE))

    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)

    png = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", SIZE, SIZE, 8, 2, 0, 0, 0))
    png += chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b"")
    with open(path, "wb") as f:
        f.write(png)


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "assets/textures/tiles.png")
