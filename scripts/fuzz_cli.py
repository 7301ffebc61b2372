#!/usr/bin/env python3
"""Bounded mutation fuzzing of the fairsurf CLI (standard library only).

Mutates small meshes (bytes, numbers, lines), runs a random command on each mutant and fails if a
run ends by a signal (a crash: negative return code) or outlives its timeout (a hang). Failing
inputs are kept in the output directory with the command that failed, for tests/regressions/.

    python3 scripts/fuzz_cli.py build/bin/fairsurf --seconds 60 [--seed 1] [--out build/fuzz-cli]
"""
import argparse
import os
import random
import shutil
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SEED_FILES = ["hourglass_ico.obj", "cgal_degtri_sliding.off", "triple_vierbein.obj", "cube_soup.obj",
              "lagrange_prout.obj"]
SPECIAL = [b"nan", b"-nan", b"inf", b"-inf", b"0", b"-1", b"1e308", b"-1e308", b"1e-308", b"2147483647",
           b"-2147483648", b"4294967296", b"99999999999999999999", b"3", b"0.5"]


def commands(mesh, ext, work):
    out = lambda name: os.path.join(work, name)
    return [
        ["info", mesh], ["info", "--json", "--strict", mesh],
        ["curvature", mesh, "-o", out("c.ply")],
        ["smooth", mesh, "-o", out("s" + ext), "--steps", "2", "--quiet"],
        ["smooth", "--repair", mesh, "-o", out("s" + ext), "--steps", "2", "--quiet"],
        ["fill", mesh, "-o", out("f" + ext), "--max-steps", "3", "--quiet"],
        ["fill", "--repair", "--method", "harmonic", mesh, "-o", out("f" + ext), "--quiet"],
        ["fair", mesh, "-o", out("r" + ext), "--region-sphere", "0,0,0,0.5", "--max-steps", "2", "--quiet"],
        ["blend", "--repair", mesh, "-o", out("b" + ext), "--max-steps", "2", "--quiet"],
        ["render", mesh, "-o", out("r.png")],
        ["repair", mesh, "-o", out("p" + ext)], ["repair", "--json", mesh, "-o", out("p.ply")],
        ["convert", mesh, "-o", out("v.stl")],
    ]


def mutate(data, rng):
    data = bytearray(data)
    for _ in range(rng.randint(1, 4)):
        kind = rng.randrange(6)
        pos = rng.randrange(len(data) + 1)
        if kind == 0 and data:  # flip a byte
            data[min(pos, len(data) - 1)] ^= 1 << rng.randrange(8)
        elif kind == 1:  # a special number in place of a token
            start = pos
            while start < len(data) and data[start:start + 1].isspace():
                start += 1
            end = start
            while end < len(data) and not data[end:end + 1].isspace():
                end += 1
            data[start:end] = rng.choice(SPECIAL)
        elif kind == 2:  # delete a chunk
            del data[pos:pos + rng.randint(1, 64)]
        elif kind == 3:  # duplicate a chunk
            chunk = data[pos:pos + rng.randint(1, 256)]
            data[pos:pos] = chunk
        elif kind == 4:  # truncate
            del data[pos:]
        else:  # swap two lines
            lines = data.split(b"\n")
            if len(lines) > 2:
                i, j = rng.randrange(len(lines)), rng.randrange(len(lines))
                lines[i], lines[j] = lines[j], lines[i]
                data = bytearray(b"\n".join(lines))
    return bytes(data)


def make_seeds(cli, work):
    seeds = []
    for name in SEED_FILES:
        src = os.path.join(ROOT, "data", name)
        seeds.append(src)
    for ext, extra in [(".ply", ["--ascii"]), (".ply", []), (".stl", ["--ascii"]), (".stl", []), (".off", [])]:
        dst = os.path.join(work, "seed_%d%s" % (len(seeds), ext))
        subprocess.run([cli, "convert", seeds[0], "-o", dst] + extra, check=True,
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        seeds.append(dst)
    return [(os.path.splitext(s)[1], open(s, "rb").read()) for s in seeds]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("cli")
    parser.add_argument("--seconds", type=float, default=60)
    parser.add_argument("--seed", type=int, default=int(time.time()))
    parser.add_argument("--timeout", type=float, default=30)
    parser.add_argument("--out", default=os.path.join(ROOT, "build", "fuzz-cli"))
    args = parser.parse_args()
    rng = random.Random(args.seed)
    work = tempfile.mkdtemp(prefix="fairsurf_fuzz_cli_")
    failures = 0
    runs = 0
    try:
        seeds = make_seeds(args.cli, work)
        end = time.time() + args.seconds
        while time.time() < end:
            ext, data = rng.choice(seeds)
            mesh = os.path.join(work, "mutant" + ext)
            with open(mesh, "wb") as f:
                f.write(mutate(data, rng))
            command = [args.cli] + rng.choice(commands(mesh, ext, work))
            if command[1] not in ("info",):
                command.append("--force")
            runs += 1
            try:
                result = subprocess.run(command, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                                        timeout=args.timeout)
                problem = "signal %d" % -result.returncode if result.returncode < 0 else None
                detail = result.stderr.decode(errors="replace")[-2000:]
            except subprocess.TimeoutExpired:
                problem, detail = "timeout after %g s" % args.timeout, ""
            if problem:
                failures += 1
                os.makedirs(args.out, exist_ok=True)
                kept = os.path.join(args.out, "failure_%d%s" % (failures, ext))
                shutil.copyfile(mesh, kept)
                print("fuzz_cli: %s: %s (input kept as %s)\n%s" % (problem, " ".join(command[1:]), kept, detail))
    finally:
        shutil.rmtree(work, ignore_errors=True)
    print("fuzz_cli: %d runs in %g s (seed %d), %d failures" % (runs, args.seconds, args.seed, failures))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
