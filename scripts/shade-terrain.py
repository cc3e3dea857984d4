#!/usr/bin/env python3
"""Draws a terrain map from `voxc terrain` as a shaded-relief picture seen from above (standard
library only): hill shading lit from the west over a height tint, so channels, fans and
smoothed slopes show. Usage:

  voxc terrain examples/valley.vox valley --height h.npy --difference d.npy
  python3 scripts/shade-terrain.py h.npy eroded.png --max-height 40 --cell 0.5
  python3 scripts/shade-terrain.py h.npy uneroded.png --max-height 40 --cell 0.5 --subtract d.npy
  python3 scripts/shade-terrain.py h.npy change.png --max-height 40 --cell 0.5 --change d.npy

--subtract draws the height before erosion (H - S_h); --change tints the shading red where the
water cut the ground (S_h < 0) and blue where it deposited (S_h > 0), full colour at --change-scale
(units of max_height). --cell is a map cell's size in voxels, so slopes are true to the voxels;
--scale repeats every cell that many pixels (nearest)."""
import argparse
import ast
import math
import struct
import zlib


def read_map(path):
    """A (side, 1, side) float32 .npy map as rows: rows[y][x] = cell (x, y)."""
    with open(path, "rb") as f:
        data = f.read()
    if data[:6] != b"\x93NUMPY":
        raise SystemExit(f"{path}: not a .npy file")
    header_length = struct.unpack("<H", data[8:10])[0] if data[6] == 1 else struct.unpack("<I", data[8:12])[0]
    start = (10 if data[6] == 1 else 12) + header_length
    header = ast.literal_eval(data[start - header_length:start].decode("latin1"))
    if header["descr"] != "<f4" or len(header["shape"]) != 3 or header["shape"][1] != 1:
        raise SystemExit(f"{path}: expected a float32 map of shape (side, 1, side), got {header}")
    width, _, height = header["shape"]
    values = struct.unpack(f"<{width * height}f", data[start:start + 4 * width * height])
    # arr[x, 0, y] = cell (x, y): x varies slowest in C order, fastest in Fortran order.
    if header["fortran_order"]:
        return [list(values[y * width:(y + 1) * width]) for y in range(height)]
    return [[values[x * height + y] for x in range(width)] for y in range(height)]


def tint(t):
    """Height tint from low (green) through brown to high (pale grey), t in [0, 1]."""
    stops = [(0.0, (70, 110, 60)), (0.35, (130, 140, 80)), (0.65, (150, 120, 90)), (1.0, (225, 220, 215))]
    t = min(max(t, 0.0), 1.0)
    for (t0, c0), (t1, c1) in zip(stops, stops[1:]):
        if t <= t1:
            f = (t - t0) / (t1 - t0)
            return tuple(a + (b - a) * f for a, b in zip(c0, c1))
    return stops[-1][1]


def write_png(path, rows):
    raw = b"".join(b"\x00" + bytes(row) for row in rows)
    def chunk(kind, body):
        return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body))
    png = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", len(rows[0]) // 3, len(rows), 8, 2, 0, 0, 0))
    png += chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b"")
    with open(path, "wb") as f:
        f.write(png)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("height")
    parser.add_argument("out")
    parser.add_argument("--max-height", type=float, default=1.0, help="voxels per unit of the map (the block's max_height)")
    parser.add_argument("--cell", type=float, default=1.0, help="a cell's size in voxels")
    parser.add_argument("--subtract", help="a --difference map to subtract: the height before erosion")
    parser.add_argument("--change", help="a --difference map to tint: red where cut, blue where deposited")
    parser.add_argument("--change-scale", type=float, default=0.05)
    parser.add_argument("--low", type=float, help="height of the lowest tint (units of the map; default its minimum)")
    parser.add_argument("--high", type=float, help="height of the highest tint (default its maximum)")
    parser.add_argument("--scale", type=int, default=1)
    args = parser.parse_args()

    height = read_map(args.height)
    side_y, side_x = len(height), len(height[0])
    if args.subtract:
        difference = read_map(args.subtract)
        height = [[h - d for h, d in zip(hr, dr)] for hr, dr in zip(height, difference)]
    change = read_map(args.change) if args.change else None
    low = args.low if args.low is not None else min(map(min, height))
    high = args.high if args.high is not None else max(map(max, height))
    # From the west, a little north, 37 degrees up: slopes that run down along y (gullies on the
    # valley sides) show one lit and one dark wall.
    light = tuple(c / math.sqrt(0.8 * 0.8 + 0.3 * 0.3 + 0.6 * 0.6) for c in (-0.8, -0.3, 0.6))

    def at(x, y):
        return height[min(max(y, 0), side_y - 1)][min(max(x, 0), side_x - 1)] * args.max_height

    rows = []
    for y in range(side_y):
        row = []
        for x in range(side_x):
            gx = (at(x + 1, y) - at(x - 1, y)) / (2 * args.cell)
            gy = (at(x, y + 1) - at(x, y - 1)) / (2 * args.cell)
            norm = math.sqrt(gx * gx + gy * gy + 1)
            shade = max(0.0, (-gx * light[0] - gy * light[1] + light[2]) / norm)
            colour = tint((height[y][x] - low) / max(high - low, 1e-12))
            if change:
                c = max(-1.0, min(1.0, change[y][x] / args.change_scale))
                target = (200, 40, 30) if c < 0 else (40, 90, 220)
                colour = tuple(a + (b - a) * abs(c) for a, b in zip(colour, target))
            pixel = [int(min(255, max(0, v * (0.25 + 0.9 * shade)))) for v in colour]
            row.extend(pixel * args.scale)
        rows.extend([row] * args.scale)
    write_png(args.out, rows)


if __name__ == "__main__":
    main()
