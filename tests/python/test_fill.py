import json
import subprocess

import numpy as np

import fairsurf


def test_fill_closes_the_hole_like_the_cli(tmp_path, cli, data_dir, hand):
    out, log = tmp_path / "filled.ply", tmp_path / "fill.json"
    subprocess.run([str(cli), "fill", str(data_dir / "hand_lowres.obj"), "-o", str(out), "--log", str(log), "--quiet"],
                   check=True, capture_output=True)
    V_cli, F_cli = fairsurf.read_mesh(out)

    V, F = hand
    V2, F2, report = fairsurf.fill_holes(V, F)
    assert fairsurf.info(V2, F2)["boundary_loops"] == []
    assert report["filled"] == 1 and report["failed"] == 0
    assert np.array_equal(V2[: len(V)], V)  # the input's vertices never move
    assert np.array_equal(F2, F_cli)
    assert np.abs(V2 - V_cli).max() <= 1e-12
    cli_report = json.loads(log.read_text())
    assert report["holes"][0]["delivered"] == cli_report["holes"][0]["delivered"]
    assert report["holes"][0]["vertices_added"] == len(V2) - len(V)


def test_selected_holes_only(hand):
    V, F = hand
    V2, F2, report = fairsurf.fill_holes(V, F, holes=[0], continuity="G1", method="harmonic")
    assert report["holes"][0]["requested_continuity"] == "G1"
    assert report["holes"][0]["delivered"] == "C1 (linear)"
    assert fairsurf.info(V2, F2)["boundary_loops"] == []
