#!/usr/bin/env python3
"""Figures for scripts/gallery.sh and scripts/demo.sh, read from fairsurf's outputs and meshes.

  row LABEL [--log L.json] [--curv C.json] [--mesh M] [--ref R] [--numbers FILE]
      one Markdown table row: accepted (rejected) steps, time reached and stop reason, energy
      before -> after (from `smooth --log`), H's 5/50/95% quantiles (from `curvature --json`),
      volume relative to R (closed meshes), mean distance to the centroid, and the largest / rms
      vertex deviation from R (same vertex order) over R's bounding-box diagonal. Every number
      printed is also appended to FILE, so that `check` can test them.
  header                 the matching table header
  range C.json [--around-median]
      the colour range a,b: [-q, q] with q = max(|p5|, |p95|) of H, or median -/+ |median|
  sphere INPUT FILLED [--numbers FILE]
      how far the vertices FILLED adds after INPUT's lie from the unit sphere: max and mean of
      | |v| - 1 |, and the lowest z they reach
  stop L.json            the log's stop reason
  time L.json            the time the run reached
  check FILE             exit 1 unless FILE holds at least one number and every one is finite
"""
import argparse
import json
import math
import sys

HEADER = ("| mesh | steps (rejected) | t reached (stop) | energy before → after | H p5 / p50 / p95 "
          "| volume / clean | mean distance to centroid | deviation max / rms (of diagonal) |\n"
          "|---|---|---|---|---|---|---|---|")


def read_mesh(path):
    """Positions and triangles of an OBJ/OFF/ASCII-or-binary-free PLY file (ASCII only)."""
    with open(path, "rb") as f:
        text = f.read().decode("latin-1")
    lines = [l.split("#")[0].split() for l in text.splitlines()]
    lines = [l for l in lines if l]
    if path.endswith(".obj"):
        verts = [tuple(map(float, l[1:4])) for l in lines if l[0] == "v"]
        faces = []
        for l in lines:
            if l[0] == "f":
                idx = [int(p.split("/")[0]) - 1 for p in l[1:]]
                faces += [(idx[0], idx[k], idx[k + 1]) for k in range(1, len(idx) - 1)]
        return verts, faces
    if path.endswith(".off"):
        start = 1 if len(lines[0]) == 1 else 0
        head = lines[start] if start else lines[0][1:]
        nv, nf = int(head[0]), int(head[1])
        body = lines[start + 1:]
        verts = [tuple(map(float, l[:3])) for l in body[:nv]]
        faces = [tuple(map(int, l[1:4])) for l in body[nv:nv + nf]]
        return verts, faces
    raise SystemExit(f"gallery_measure: {path}: only .obj and .off are measured")


def shape(path):
    verts, faces = read_mesh(path)
    n = len(verts)
    centroid = [sum(v[k] for v in verts) / n for k in range(3)]
    edges = {}
    volume = 0.0
    for a, b, c in faces:
        p, q, r = verts[a], verts[b], verts[c]
        volume += (p[0] * (q[1] * r[2] - q[2] * r[1]) - p[1] * (q[0] * r[2] - q[2] * r[0])
                   + p[2] * (q[0] * r[1] - q[1] * r[0])) / 6.0
        for e in ((a, b), (b, c), (c, a)):
            key = (min(e), max(e))
            edges[key] = edges.get(key, 0) + 1
    closed = all(count == 2 for count in edges.values())
    radius = sum(math.dist(v, centroid) for v in verts) / n
    lo = [min(v[k] for v in verts) for k in range(3)]
    hi = [max(v[k] for v in verts) for k in range(3)]
    return {"verts": verts, "volume": volume if closed else None, "radius": radius,
            "diagonal": math.dist(lo, hi)}


def fmt(x, numbers):
    numbers.append(x)
    return "%.3g" % x


def row(args):
    numbers, cells = [], [args.label]
    log = json.load(open(args.log)) if args.log else None
    if log:
        cells.append("%d (%d)" % (log["accepted_steps"], log["rejected_steps"]))
        cells.append("%s (%s)" % (fmt(log["time"], numbers), log["stop_reason"]))
        cells.append("%s → %s" % (fmt(log["initial_energy"], numbers), fmt(log["final_energy"], numbers)))
    else:
        cells += ["–", "–", "–"]
    if args.curv:
        h = json.load(open(args.curv))["statistics"]["H"]
        cells.append(" / ".join(fmt(h[k], numbers) for k in ("p5", "p50", "p95")))
    else:
        cells.append("–")
    mesh = shape(args.mesh) if args.mesh else None
    ref = shape(args.ref) if args.ref else None
    if mesh and ref and mesh["volume"] is not None and ref["volume"]:
        cells.append(fmt(mesh["volume"] / ref["volume"], numbers))
    else:
        cells.append("–")
    cells.append(fmt(mesh["radius"], numbers) if mesh else "–")
    if mesh and ref and len(mesh["verts"]) == len(ref["verts"]):
        d = [math.dist(p, q) / ref["diagonal"] for p, q in zip(mesh["verts"], ref["verts"])]
        rms = math.sqrt(sum(x * x for x in d) / len(d))
        cells.append("%s / %s" % (fmt(max(d), numbers), fmt(rms, numbers)))
    else:
        cells.append("–")
    print("| " + " | ".join(cells) + " |")
    if args.numbers:
        with open(args.numbers, "a") as f:
            f.writelines("%r\n" % x for x in numbers)


def colour_range(args):
    h = json.load(open(args.curv))["statistics"]["H"]
    if args.around_median:
        m = h["p50"]
        print("%.4g,%.4g" % (m - abs(m), m + abs(m)))
    else:
        q = max(abs(h["p5"]), abs(h["p95"]))
        print("%.4g,%.4g" % (-q, q))


def sphere(args):
    numbers = []
    n = len(read_mesh(args.input)[0])
    added = read_mesh(args.filled)[0][n:]
    if not added:
        sys.exit(f"gallery_measure: {args.filled} adds no vertex to {args.input}")
    off = [abs(math.hypot(*v) - 1.0) for v in added]
    print("%d new vertices, | |v| - 1 | max %s, mean %s; lowest z %s" % (
        len(added), fmt(max(off), numbers), fmt(sum(off) / len(off), numbers),
        fmt(min(v[2] for v in added), numbers)))
    if args.numbers:
        with open(args.numbers, "a") as f:
            f.writelines("%r\n" % x for x in numbers)


def check(args):
    values = [float(l) for l in open(args.file) if l.strip()]
    bad = [v for v in values if not math.isfinite(v)]
    if not values or bad:
        sys.exit(f"gallery_measure: {len(values)} numbers, {len(bad)} not finite")
    print(f"gallery_measure: {len(values)} numbers, all finite")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    sub = parser.add_subparsers(dest="command", required=True)
    p = sub.add_parser("row")
    p.add_argument("label")
    for opt in ("--log", "--curv", "--mesh", "--ref", "--numbers"):
        p.add_argument(opt)
    sub.add_parser("header")
    p = sub.add_parser("range")
    p.add_argument("curv")
    p.add_argument("--around-median", action="store_true")
    p = sub.add_parser("sphere")
    p.add_argument("input")
    p.add_argument("filled")
    p.add_argument("--numbers")
    for name in ("stop", "time"):
        sub.add_parser(name).add_argument("log")
    sub.add_parser("check").add_argument("file")
    args = parser.parse_args()
    if args.command == "row":
        row(args)
    elif args.command == "header":
        print(HEADER)
    elif args.command == "range":
        colour_range(args)
    elif args.command == "sphere":
        sphere(args)
    elif args.command == "stop":
        print(json.load(open(args.log))["stop_reason"])
    elif args.command == "time":
        print(repr(json.load(open(args.log))["time"]))
    else:
        check(args)


if __name__ == "__main__":
    main()
