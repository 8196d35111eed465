#!/usr/bin/env python3
"""Re-encodes 8-bit RGBA PNGs (as tidepool writes them) as RGB with per-row filters and zlib 9.
The README pictures of dense particle fields shrink by about a third. Usage: shrink_png.py FILE..."""
import struct
import sys
import zlib


def chunks(data):
    i = 8
    while i < len(data):
        n = struct.unpack(">I", data[i:i + 4])[0]
        yield data[i + 4:i + 8], data[i + 8:i + 8 + n]
        i += 12 + n


def unfilter(raw, width, height, bpp):
    stride = width * bpp
    rows, prev, i = [], bytearray(stride), 0
    for _ in range(height):
        f, line = raw[i], bytearray(raw[i + 1:i + 1 + stride])
        i += 1 + stride
        for x in range(stride):
            a = line[x - bpp] if x >= bpp else 0
            b, c = prev[x], prev[x - bpp] if x >= bpp else 0
            if f == 1: line[x] = (line[x] + a) & 255
            elif f == 2: line[x] = (line[x] + b) & 255
            elif f == 3: line[x] = (line[x] + (a + b) // 2) & 255
            elif f == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[x] = (line[x] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(line)
        prev = line
    return rows


def best_filtered(rows, bpp):
    out, prev = bytearray(), bytearray(len(rows[0]))
    for line in rows:
        cands = []
        for f in (0, 1, 2, 4):
            enc = bytearray([f])
            for x in range(len(line)):
                a = line[x - bpp] if x >= bpp else 0
                b, c = prev[x], prev[x - bpp] if x >= bpp else 0
                if f == 0: pred = 0
                elif f == 1: pred = a
                elif f == 2: pred = b
                else:
                    p = a + b - c
                    pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                    pred = a if pa <= pb and pa <= pc else b if pb <= pc else c
                enc.append((line[x] - pred) & 255)
            cands.append((sum(v if v < 128 else 256 - v for v in enc[1:]), enc))
        out += min(cands, key=lambda t: t[0])[1]
        prev = line
    return bytes(out)


for path in sys.argv[1:]:
    data = open(path, "rb").read()
    idat = b"".join(d for t, d in chunks(data) if t == b"IDAT")
    w, h, depth, ctype = struct.unpack(">IIBB", next(d for t, d in chunks(data) if t == b"IHDR")[:10])
    assert depth == 8 and ctype == 6, "expects 8-bit RGBA"
    rgba = unfilter(zlib.decompress(idat), w, h, 4)
    rgb = [bytearray(b for x in range(w) for b in row[4 * x:4 * x + 3]) for row in rgba]
    def chunk(tag, body):
        return struct.pack(">I", len(body)) + tag + body + struct.pack(">I", zlib.crc32(tag + body))
    png = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0))
    png += chunk(b"IDAT", zlib.compress(best_filtered(rgb, 3), 9)) + chunk(b"IEND", b"")
    open(path, "wb").write(png)
