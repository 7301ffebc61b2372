"""Denoise a mesh with noise added along its normals by the sixth-order flow, print each accepted
step, stop after five.

    PYTHONPATH=build/python /usr/bin/python3 examples/smooth_with_progress.py data/hand_lowres.obj
"""

import sys

import numpy as np

import fairsurf

V, F = fairsurf.read_mesh(sys.argv[1])
rng = np.random.default_rng(1)
h = fairsurf.info(V, F)["mean_edge_length"]
normals = fairsurf.curvature(V, F)["normal"]
noisy = V + normals * rng.uniform(-0.1 * h, 0.1 * h, size=(len(V), 1))

accepted = 0


def progress(step):
    """Called after every trial step; returning False stops the run (last accepted state kept)."""
    global accepted
    accepted += step["accepted"]
    if step["accepted"]:
        print(f"step {step['step']}: t {step['time']:.3g}, E {step['energy']:.4g}")
    return accepted < 5


smoothed, report = fairsurf.smooth(noisy, F, steps=20, progress=progress)
H_noisy, H_smooth = (fairsurf.curvature(x, F)["H"] for x in (noisy, smoothed))
print(f"{report['stop_reason']} after {report['accepted_steps']} steps; "
      f"std of H {H_noisy.std():.3g} -> {H_smooth.std():.3g}")
