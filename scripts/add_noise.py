#!/usr/bin/env python3
"""Adds reproducible normal noise to a triangle mesh (OBJ or OFF in, OBJ out) for the gallery and demo.

Each vertex moves along its area-weighted normal by u * AMPLITUDE * (mean edge length), u uniform in
[-1, 1] from Python's Mersenne Twister seeded with SEED, so the same arguments give the same bytes on
every run and platform. Only positions and triangles are kept (texture coordinates are dropped).

usage: add_noise.py IN OUT.obj [--amplitude 0.3] [--seed 1]
"""
import argparse
import math
import random


def read_mesh(path):
    with open(path) as f:
        text = f.read()
    if path.lower().endswith(".off"):
        tokens = [line.split("#")[0].split() for line in text.splitlines()]
        tokens = [t for t in tokens if t]
        head = tokens[0][1:] if len(tokens[0]) > 1 else tokens[1]
        start = 1 if len(tokens[0]) > 1 else 2
        nv, nf = int(head[0]), int(head[1])
        verts = [tuple(float(x) for x in t[:3]) for t in tokens[start:start + nv]]
        faces = [tuple(int(x) for x in t[1:4]) for t in tokens[start + nv:start + nv + nf]]
        return verts, faces
    verts, faces = [], []
    for line in text.splitlines():
        parts = line.split()
        if not parts:
            continue
        if parts[0] == "v":
            verts.append(tuple(float(x) for x in parts[1:4]))
        elif parts[0] == "f":
            idx = [int(p.split("/")[0]) for p in parts[1:]]
            idx = [i - 1 if i > 0 else len(verts) + i for i in idx]
            faces.extend((idx[0], idx[k], idx[k + 1]) for k in range(1, len(idx) - 1))
    return verts, faces


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("input")
    parser.add_argument("output")
    parser.add_argument("--amplitude", type=float, default=0.3, help="noise in mean edge lengths")
    parser.add_argument("--seed", type=int, default=1)
    args = parser.parse_args()

    verts, faces = read_mesh(args.input)
    normals = [[0.0, 0.0, 0.0] for _ in verts]
    edge_sum, edge_count = 0.0, 0
    for tri in faces:
        p = [verts[i] for i in tri]
        n = cross(sub(p[1], p[0]), sub(p[2], p[0]))  # length = twice the area: area weighting
        for i in tri:
            for k in range(3):
                normals[i][k] += n[k]
        for k in range(3):
            edge_sum += math.dist(p[k], p[(k + 1) % 3])
            edge_count += 1
    step = args.amplitude * edge_sum / edge_count

    rng = random.Random(args.seed)
    with open(args.output, "w") as out:
        for v, n in zip(verts, normals):
            length = math.sqrt(sum(c * c for c in n)) or 1.0
            u = rng.uniform(-1.0, 1.0) * step / length
            out.write("v %.9g %.9g %.9g\n" % tuple(v[k] + u * n[k] for k in range(3)))
        for tri in faces:
            out.write("f %d %d %d\n" % tuple(i + 1 for i in tri))


if __name__ == "__main__":
    main()
