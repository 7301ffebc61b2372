import json
import pathlib
import subprocess

import numpy as np
import pytest

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
    assert report["holes"][0]["patch_shared_with"] == cli_report["holes"][0]["patch_shared_with"] == -1
    assert report["holes"][0]["pinched_by"] == cli_report["holes"][0]["pinched_by"] == -1
    assert report["holes"][0]["around_a_face"] is cli_report["holes"][0]["around_a_face"] is False
    assert report["holes"][0]["hanging_piece_at"] == cli_report["holes"][0]["hanging_piece_at"] == -1
    assert report["holes"][0]["lone_triangle"] == cli_report["holes"][0]["lone_triangle"] == -1


def test_a_loop_round_a_lone_triangle_is_skipped_and_says_so():
    V = np.array([[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]])
    F = np.array([[0, 1, 2]])
    V2, F2, report = fairsurf.fill_holes(V, F)
    hole = report["holes"][0]
    assert hole["status"] == "skipped" and hole["around_a_face"] is True and hole["pinched_by"] == -1
    assert np.array_equal(F2, F)


def test_selected_holes_only(hand):
    V, F = hand
    V2, F2, report = fairsurf.fill_holes(V, F, holes=[0], continuity="G1", method="harmonic")
    assert report["holes"][0]["requested_continuity"] == "G1"
    assert report["holes"][0]["delivered"] == "C1 (linear)"
    assert fairsurf.info(V2, F2)["boundary_loops"] == []


def cut_ball(V, F, centre, radius):
    """V, F without the faces whose three vertices lie within `radius` of `centre`, unused vertices dropped."""
    inside = np.linalg.norm(V - centre, axis=1) <= radius
    kept = F[~inside[F].all(axis=1)]
    used = np.zeros(len(V), dtype=bool)
    used[kept.ravel()] = True
    index = np.cumsum(used) - 1
    return V[used], index[kept]


def test_a_hole_given_the_solve_before_its_membrane_reports_its_flows_untried(data_dir):
    # blub's tail fin (tests/applications/test_fill_real.cpp, RealHoleTailFin): one ∆³ solve from the
    # patch before its membrane re-predicts the held-out rings over twice as well as the re-evaluated
    # solution the flows start from, so the flows are not tried and their errors are NaN, not None.
    V, F = fairsurf.read_mesh(data_dir / "blub.obj")
    edges = np.unique(np.sort(np.concatenate([F[:, [0, 1]], F[:, [1, 2]], F[:, [2, 0]]]), axis=1), axis=0)
    h = np.linalg.norm(V[edges[:, 0]] - V[edges[:, 1]], axis=1).mean()
    V, F = cut_ball(V, F, np.array([0.00697216, -0.181279, -1.03702]), 4 * h)
    _, _, report = fairsurf.fill_holes(V, F)
    hole = report["holes"][0]
    assert hole["refined_start"] and hole["delivered"] == "C2 (linear)"
    assert 2 * hole["held_out_refined_linear_error"] < hole["held_out_linear_error"]
    assert np.isnan(hole["held_out_flow_error"]) and np.isnan(hole["held_out_two_ring_flow_error"])
    assert "the flow was not tried" in hole["note"]


def test_keep_flow_delivers_g2_where_the_held_out_rings_chose_the_floor(data_dir):
    # The bunny scan's five holes: by default the linear floor re-predicts the held-out rings better
    # on each (C2 (linear)); keep_flow=True keeps the settled flow on all five, as `fill --keep-flow`.
    V, F = fairsurf.read_mesh(data_dir / "stanford_bunny_zipper.obj")
    _, _, default = fairsurf.fill_holes(V, F)
    V2, F2, kept = fairsurf.fill_holes(V, F, keep_flow=True)
    assert not default["keep_flow"] and kept["keep_flow"]
    assert [h["delivered"] for h in default["holes"]] == ["C2 (linear)"] * 5
    assert [h["delivered"] for h in kept["holes"]] == ["G2"] * 5
    # The held-out rings only chose between the flow's 1-ring and 2-ring boundary fits.
    assert not any(h["checks_chose_linear"] for h in kept["holes"])
    # The scan reads smooth at the scale of its edges (held_out_max_roughness 0.05): so the held-out
    # rings could weigh the floor by default; with keep_flow they do not, and the roughness is not read.
    assert all(0 < h["held_out_roughness"] < 0.05 for h in default["holes"])
    assert all(np.isnan(h["held_out_roughness"]) for h in kept["holes"])
    assert not any(h["flow_folded_back"] for h in kept["holes"])
    assert all(np.isfinite(h["held_out_two_ring_flow_error"]) for h in kept["holes"])
    assert fairsurf.info(V2, F2)["boundary_loops"] == []
    with pytest.raises(fairsurf.InvalidArgument, match="keep_flow"):
        fairsurf.fill_holes(V, F, keep_flow=True, method="harmonic")


def test_a_joint_group_left_unfaired_reports_which_hole_was_filled_alone():
    # tests/data/demosthenes_joint_holes_unfaired.ply (RealHoleJointGroup in test_fill_real.cpp): only
    # the unfaired refined triangulation closes the 146-edge hole; the 43-edge hole beside it, filled
    # jointly with it before, is filled alone and faired.
    V, F = fairsurf.read_mesh(pathlib.Path(__file__).resolve().parents[1] / "data" / "demosthenes_joint_holes_unfaired.ply")
    _, _, report = fairsurf.fill_holes(V, F, method="harmonic")
    large, small = report["holes"]
    assert large["unfaired"] and large["delivered"] == "C0 (linear)"
    assert not small["unfaired"] and small["delivered"] == "C2 (linear)"
    assert "closed only as its refined triangulation, unfaired; filled alone" in small["note"]
