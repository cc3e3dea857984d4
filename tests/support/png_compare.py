#!/usr/bin/env python3
"""png_compare.py A B [THRESHOLD]: compares two 8-bit RGB PNGs (as voxc writes them) pixel by pixel.
Prints "max M, differing D of N" where M is the largest channel difference and D counts the pixels
with a channel differing by more than THRESHOLD (default 0); "sizes differ" when they do."""
import struct
import sys
import zlib


def pixels(path):
    data, at, idat = open(path, "rb").read(), 8, b""
    while at < len(data):
        length, kind = struct.unpack(">I4s", data[at:at + 8])
        if kind == b"IHDR":
            width, height = struct.unpack(">II", data[at + 8:at + 16])
        if kind == b"IDAT":
            idat += data[at + 8:at + 8 + length]
        at += 12 + length
    raw, stride, out = zlib.decompress(idat), width * 3, bytearray()
    previous = bytearray(stride)
    for y in range(height):
        kind, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):  # PNG row filters: none, sub, up, average, Paeth
            a = line[i - 3] if i >= 3 else 0
            b, c = previous[i], previous[i - 3] if i >= 3 else 0
            if kind == 1: line[i] = (line[i] + a) & 255
            elif kind == 2: line[i] = (line[i] + b) & 255
            elif kind == 3: line[i] = (line[i] + (a + b) // 2) & 255
            elif kind == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        out += line
        previous = line
    return (width, height), out


(size_a, a), (size_b, b) = pixels(sys.argv[1]), pixels(sys.argv[2])
threshold = int(sys.argv[3]) if len(sys.argv) > 3 else 0
if size_a != size_b:
    print("sizes differ")
    sys.exit(0)
differences = [max(abs(a[i + k] - b[i + k]) for k in range(3)) for i in range(0, len(a), 3)]
print("max %d, differing %d of %d" % (max(differences), sum(d > threshold for d in differences), len(differences)))
