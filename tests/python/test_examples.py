"""The scripts of examples/ run and print what docs/python.md says they print."""

import os
import pathlib
import subprocess
import sys

import numpy as np
import pytest

import fairsurf

EXAMPLES = pathlib.Path(__file__).resolve().parents[2] / "examples"


def run(script, *args):
    result = subprocess.run([sys.executable, str(EXAMPLES / script), *map(str, args)], capture_output=True,
                            text=True, env=dict(os.environ), check=True)
    return result.stdout


def test_fill_holes_example(tmp_path, data_dir):
    out = run("fill_holes.py", data_dir / "hand_lowres.obj", tmp_path)
    assert "hole 0: filled, G2" in out
    V, F = fairsurf.read_mesh(tmp_path / "filled.ply")
    assert fairsurf.info(V, F)["boundary_loops"] == []
    png = (tmp_path / "fill.png").read_bytes()
    assert png.startswith(b"\x89PNG\r\n\x1a\n")


def test_fill_holes_example_repairs_a_mesh_fill_refuses(tmp_path, hand):
    # The hand with its first face twice: fill refuses the duplicate, the example repairs and fills.
    V, F = hand
    fairsurf.write_mesh(tmp_path / "doubled.ply", V, np.vstack([F, F[:1]]))
    out = run("fill_holes.py", tmp_path / "doubled.ply", tmp_path)
    assert "refused: fill_holes: mesh has 3 non-manifold edges (first: 12-13), 1 duplicate face (first: 1602)" in out
    assert "repaired: duplicate_faces_removed 1\n" in out
    assert "hole 0: filled, G2" in out
    V2, F2 = fairsurf.read_mesh(tmp_path / "filled.ply")
    assert fairsurf.info(V2, F2)["boundary_loops"] == [] and len(F2) > len(F)


def test_smooth_with_progress_example(data_dir):
    out = run("smooth_with_progress.py", data_dir / "hand_lowres.obj")
    assert out.count("\nstep ") + out.startswith("step ") == 5
    last = out.strip().splitlines()[-1]
    assert last.startswith("interrupted after 5 steps")
    before, after = (float(x) for x in last.split("std of H ")[1].split(" -> "))
    assert after < before


def test_render_returns_the_image_it_writes(tmp_path, hand):
    V, F = hand
    image = fairsurf.render(V, F, size=(320, 240), path=tmp_path / "hand.png")
    assert image.shape == (240, 320, 3) and image.dtype == np.uint8
    assert (image != 255).any()  # something was drawn on the white background
    again = fairsurf.render(V, F, color=fairsurf.curvature(V, F)["H"], size=(320, 240))
    assert np.array_equal(image[:200], again[:200])  # same colours above the colour bar caption


def test_render_focus_frames_a_ball(hand):
    V, F = hand
    centre = V[F[0, 0]]
    radius = 0.05 * np.linalg.norm(V.max(axis=0) - V.min(axis=0))
    whole = fairsurf.render(V, F, color="none", size=(160, 120))
    close = fairsurf.render(V, F, color="none", size=(160, 120), focus=(*centre, radius))
    assert not np.array_equal(whole, close)
    assert (close[60, 80] != 255).any()  # the ball's centre, on the surface, is the image's middle
    with pytest.raises(fairsurf.InvalidArgument, match="no face has all three vertices inside the focus ball"):
        fairsurf.render(V, F, size=(160, 120), focus=(*(V.max(axis=0) + 10 * radius), radius))
