#!/usr/bin/env python3
"""Checks that a PNG written by shapecorr decodes with zlib (whose Adler-32 check verifies the
content) to the size its header announces: python3 check_png.py FILE.png"""
import struct
import sys
import zlib

data = open(sys.argv[1], "rb").read()
assert data[:8] == b"\x89PNG\r\n\x1a\n", "not a PNG signature"
i, idat, width, height = 8, b"", 0, 0
while i < len(data):
    n = struct.unpack(">I", data[i:i + 4])[0]
    kind, body = data[i + 4:i + 8], data[i + 8:i + 8 + n]
    crc = struct.unpack(">I", data[i + 8 + n:i + 12 + n])[0]
    assert zlib.crc32(kind + body) & 0xFFFFFFFF == crc, f"bad CRC in {kind}"
    if kind == b"IHDR":
        width, height = struct.unpack(">II", body[:8])
        assert body[8:10] == b"\x08\x02", "expected 8-bit RGB"
    elif kind == b"IDAT":
        idat += body
    i += 12 + n
raw = zlib.decompress(idat)
assert len(raw) == height * (1 + 3 * width), f"{len(raw)} bytes for {width}x{height}"
assert all(raw[y * (1 + 3 * width)] == 0 for y in range(height)), "unexpected filter byte"
print(f"{sys.argv[1]}: {width}x{height}, {len(data)} bytes (raw {len(raw)})")
