"""The GIL is released during long work, and repeated calls do not leak."""

import bisect
import threading
import time

import numpy as np

import fairsurf


def test_another_thread_runs_during_a_fill(data_dir):
    """Between two progress callbacks the main thread is in C++ (a flow step): a Python thread can
    only tick there if the binding released the GIL. No timing threshold is involved, but the steps
    must last long enough for the OS to schedule the other thread on a busy machine: blub_open's
    hole (about 300 new vertices) takes tens of milliseconds a step, the hand's a few."""
    V, F = fairsurf.read_mesh(data_dir / "blub_open.obj")
    ticks, callbacks, running = [], [], threading.Event()
    running.set()

    def count():
        while running.is_set():
            ticks.append(time.perf_counter())

    def progress(step):
        callbacks.append(time.perf_counter())  # entering Python
        callbacks.append(time.perf_counter())  # leaving it: the next step runs in C++

    worker = threading.Thread(target=count)
    worker.start()
    try:
        _, _, report = fairsurf.fill_holes(V, F, progress=progress)
    finally:
        running.clear()
        worker.join()
    assert report["filled"] == 1 and len(callbacks) >= 4
    steps = zip(callbacks[1::2], callbacks[2::2])  # (leaving callback k, entering callback k + 1)
    ticks_in_steps = sum(bisect.bisect_left(ticks, right) - bisect.bisect_right(ticks, left) for left, right in steps)
    assert ticks_in_steps > 0


def resident_bytes():
    with open("/proc/self/statm") as statm:
        return int(statm.read().split()[1]) * 4096


def test_repeated_small_calls_do_not_grow_memory(hand, data_dir, tmp_path):
    V, F = hand
    F64 = F.astype(np.int64)
    calls = [
        lambda: fairsurf.read_mesh(data_dir / "hand_lowres.obj")[0].shape == (810, 3),
        lambda: fairsurf.info(V, F64)["vertices"] == 810,
        lambda: fairsurf.curvature(V, F)["H"].shape == (810,),
        lambda: fairsurf.write_mesh(tmp_path / "hand.ply", V, F) is None,
    ]
    for k in range(100):  # warm-up: allocator pools, caches
        assert calls[k % 4]()
    before = resident_bytes()
    for k in range(1000):
        assert calls[k % 4]()
    grown = resident_bytes() - before
    # Leaking what one call allocates for its arrays (810 or 1602 rows: 13 to 45 kB) would add
    # more than 3 MB over the 250 calls of each kind.
    assert grown < 2 * 2**20, f"resident memory grew by {grown / 2**20:.2f} MiB over 1000 calls"
