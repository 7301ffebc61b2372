"""The Python bindings' overhead: `fairsurf.fill_holes` on a ~10k-vertex mesh and `fairsurf.curvature`
on a ~100k-vertex mesh, against the same library calls from C++ (bench_python_reference.cpp), in
process CPU time with one OpenMP thread: on a shared machine other load blurs wall times by ±50%,
while a single-threaded call's CPU time is its own work. glibc's allocator is pinned too (see PINNED).

Rounds alternate the C++ and the Python calls, so that both see the same load on the machine; in each
round each side runs each call WARM times (in one process) and keeps its fastest, so that neither pays
for a cold start. The script prints the median and the fastest of the rounds. For the fill it also
prints the overhead within each Python call: its wall time minus the library's own `seconds` (wall
time) for the same call. Target: under 5%.

    PYTHONPATH=build/python /usr/bin/python3 bench/bench_python.py build/bin/bench_python_reference [ROUNDS]
"""

import json
import os
import pathlib
import statistics
import subprocess
import sys
import time

# One OpenMP thread, and glibc keeping freed memory instead of unmapping large blocks: otherwise a
# call re-faults its ~100 MB of fresh pages at random (a 50 ms curvature then takes 150-300 ms of
# CPU, on either side). Both must hold from the start, so the script re-executes itself with them;
# the C++ side inherits them.
PINNED = {"OMP_NUM_THREADS": "1", "MALLOC_MMAP_THRESHOLD_": str(2**30), "MALLOC_TRIM_THRESHOLD_": str(2**30)}
if any(os.environ.get(key) != value for key, value in PINNED.items()):
    os.execve(sys.executable, [sys.executable, *sys.argv], {**os.environ, **PINNED})

import fairsurf  # noqa: E402  (after the environment is pinned)

DATA = pathlib.Path(__file__).resolve().parents[1] / "data"
FILL_MESH = DATA / "airplane_holes.obj"  # 8,519 vertices, 27 holes of 12 to 28 edges, all filled
CYLINDER_EDGE = 0.0125  # fig7's cylinder: 97k vertices


WARM = 3


def seconds_of(call):
    """The least CPU time of WARM calls."""
    best = float("inf")
    for _ in range(WARM):
        start = time.process_time()
        call()
        best = min(best, time.process_time() - start)
    return best


def fill_overhead_within(V, F):
    """(wall time − the library's own wall time) / the library's, of one fill_holes call."""
    start = time.perf_counter()
    _, _, report = fairsurf.fill_holes(V, F)
    return (time.perf_counter() - start - report["seconds"]) / report["seconds"]


def main():
    reference, rounds = sys.argv[1], int(sys.argv[2]) if len(sys.argv) > 2 else 7
    V, F = fairsurf.read_mesh(FILL_MESH)
    Vc, Fc = fairsurf.scene("fig7", edge_length=CYLINDER_EDGE)
    times = {"fill": ([], []), "curvature": ([], [])}  # (C++, Python) seconds per round
    within = []  # Python fill's wall time minus the library's time for the same call
    for _ in range(rounds):
        cpp = json.loads(subprocess.run([reference, str(FILL_MESH), str(CYLINDER_EDGE), str(WARM)], check=True,
                                        capture_output=True, text=True).stdout)
        fill_seconds = seconds_of(lambda: fairsurf.fill_holes(V, F))
        curvature_seconds = seconds_of(lambda: fairsurf.curvature(Vc, Fc))
        for call, seconds in (("fill", fill_seconds), ("curvature", curvature_seconds)):
            times[call][0].append(cpp[call][1])  # the fastest of WARM
            times[call][1].append(seconds)
        within.append(fill_overhead_within(V, F))
    for call, vertices in (("fill", len(V)), ("curvature", len(Vc))):
        for statistic, pick in (("median", statistics.median), ("fastest", min)):
            c, p = pick(times[call][0]), pick(times[call][1])
            print(f"{call:9s} {vertices:6d} vertices, {statistic:7s} of {rounds}: C++ {c * 1e3:8.2f} ms, "
                  f"Python {p * 1e3:8.2f} ms CPU, overhead {100 * (p - c) / c:+.1f}%")
    print(f"fill: Python wall time over the library's own wall time for the same call: "
          f"median {100 * statistics.median(within):+.2f}%, largest {100 * max(within):+.2f}%")


if __name__ == "__main__":
    main()
