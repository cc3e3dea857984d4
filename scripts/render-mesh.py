#!/usr/bin/env python3
"""Renders a binary PLY written by `voxc run` to a PNG (standard library only). `voxc render`
draws the docs pictures now (scripts/render-docs-images.sh); this script is kept for the three
made from a changed file or an edited mesh (cut open, turned inside out: docs/examples.md names them). Vertex colours (materials) are used when present. Usage: render-mesh.py MESH.ply OUT.png [--size 480]
[--yaw 35] [--pitch 30]."""
import argparse
import math
import struct
import zlib


PLY_TYPES = {"float": "f", "uchar": "B", "int": "i", "uint": "I"}


def read_ply(path):
    """Positions, triangles and per-vertex colours (None when the file has no red/green/blue)."""
    with open(path, "rb") as f:
        header = b""
        while not header.endswith(b"end_header\n"):
            header += f.readline()
        lines = header.decode().splitlines()
        vertices = int(next(l for l in lines if l.startswith("element vertex")).split()[-1])
        faces = int(next(l for l in lines if l.startswith("element face")).split()[-1])
        start = next(i for i, l in enumerate(lines) if l.startswith("element vertex")) + 1
        names, fmt = [], "<"
        for line in lines[start:]:
            if not line.startswith("property "):
                break
            _, kind, name = line.split()
            names.append(name)
            fmt += PLY_TYPES[kind]
        stride = struct.calcsize(fmt)
        data = f.read(vertices * stride)
        records = [struct.unpack_from(fmt, data, i * stride) for i in range(vertices)]
        positions = [tuple(r[names.index(k)] for k in "xyz") for r in records]
        colours = None
        if "red" in names:
            colours = [tuple(r[names.index(k)] for k in ("red", "green", "blue")) for r in records]
        face_start = next(i for i, l in enumerate(lines) if l.startswith("element face")) + 1
        face_extra = sum(1 for l in lines[face_start:] if l.startswith("property uchar"))
        triangles = []
        for _ in range(faces):
            count = f.read(1)[0]
            triangles.append(struct.unpack("<%di" % count, f.read(4 * count)))
            f.read(face_extra)  # the face's material id
    return positions, triangles, colours


def write_png(path, width, height, rgb_rows):
    raw = b"".join(b"\x00" + bytes(row) for row in rgb_rows)

    def chunk(kind, body):
        return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body) & 0xFFFFFFFF)

    png = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0))
    png += chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b"")
    with open(path, "wb") as f:
        f.write(png)


def render(positions, triangles, colours, size, yaw, pitch):
    lo = [min(p[i] for p in positions) for i in range(3)]
    hi = [max(p[i] for p in positions) for i in range(3)]
    centre = [(lo[i] + hi[i]) / 2 for i in range(3)]
    radius = max(hi[i] - lo[i] for i in range(3)) * 0.9
    cy, sy, cp, sp = math.cos(math.radians(yaw)), math.sin(math.radians(yaw)), math.cos(math.radians(pitch)), math.sin(math.radians(pitch))

    def view(p):  # orthographic: yaw about y, then pitch about x; +z towards the viewer
        x, y, z = (p[i] - centre[i] for i in range(3))
        x, z = cy * x + sy * z, -sy * x + cy * z
        y, z = cp * y - sp * z, sp * y + cp * z
        return (x, y, z)

    viewed = [view(p) for p in positions]
    projected = [((x / radius + 1) * size / 2, (1 - y / radius) * size / 2, z) for x, y, z in viewed]
    depth = [[-1e30] * size for _ in range(size)]
    image = [[[235, 240, 245] * 1 for _ in range(size)] for _ in range(size)]
    light = (0.4, 0.8, 0.45)
    for tri in triangles:
        # lighting in view space (y up, +z towards the viewer); triangles wind counter-clockwise seen from air
        va, vb, vc = (viewed[i] for i in tri)
        e1 = [vb[k] - va[k] for k in range(3)]
        e2 = [vc[k] - va[k] for k in range(3)]
        n = (e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0])
        length = math.sqrt(sum(k * k for k in n)) or 1.0
        shade = max(0.0, (n[0] * light[0] + n[1] * light[1] + n[2] * light[2]) / length)
        if n[2] < 0:
            shade = 0.1  # back face
        a, b, c = (projected[i] for i in tri)
        ux, uy, uz = b[0] - a[0], b[1] - a[1], b[2] - a[2]
        vx, vy, vz = c[0] - a[0], c[1] - a[1], c[2] - a[2]
        area = ux * vy - uy * vx
        if abs(area) < 1e-12:
            continue
        if colours:  # the material's colour, lit
            base = [sum(colours[i][k] for i in tri) / 3.0 for k in range(3)]
            colour = [min(255, int(channel * (0.3 + 0.8 * shade))) for channel in base]
        else:
            colour = [int(60 + 150 * shade), int(55 + 140 * shade), int(50 + 120 * shade)]
        x0, x1 = max(int(min(a[0], b[0], c[0])), 0), min(int(max(a[0], b[0], c[0])) + 1, size - 1)
        y0, y1 = max(int(min(a[1], b[1], c[1])), 0), min(int(max(a[1], b[1], c[1])) + 1, size - 1)
        for py in range(y0, y1 + 1):
            for px in range(x0, x1 + 1):
                qx, qy = px + 0.5 - a[0], py + 0.5 - a[1]
                s = (qx * vy - qy * vx) / area
                t = (ux * qy - uy * qx) / area
                if s < 0 or t < 0 or s + t > 1:
                    continue
                z = a[2] + s * uz + t * vz
                if z > depth[py][px]:
                    depth[py][px] = z
                    image[py][px] = colour
    return [[channel for pixel in row for channel in pixel] for row in image]


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("mesh")
    parser.add_argument("png")
    parser.add_argument("--size", type=int, default=480)
    parser.add_argument("--yaw", type=float, default=35)
    parser.add_argument("--pitch", type=float, default=30)
    args = parser.parse_args()
    positions, triangles, colours = read_ply(args.mesh)
    write_png(args.png, args.size, args.size, render(positions, triangles, colours, args.size, args.yaw, args.pitch))


if __name__ == "__main__":
    main()
