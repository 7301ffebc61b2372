"""Report dicts have the CLI's JSON log fields, minus those naming files, the command or --repair."""

import json
import subprocess

import numpy as np
import pytest

import fairsurf

NOT_IN_DICTS = {"command", "input", "inputs", "output", "repair"}


def keys(tree, prefix=""):
    """Every key path of nested dicts (lists: their first element)."""
    found = set()
    if isinstance(tree, list):
        return keys(tree[0], prefix) if tree and isinstance(tree[0], (dict, list)) else found
    if isinstance(tree, dict):
        for key, value in tree.items():
            found.add(prefix + key)
            found |= keys(value, prefix + key + ".")
    return found


def cli_log(cli, tmp_path, *args):
    log = tmp_path / "log.json"
    subprocess.run([str(cli), *map(str, args), "-o", str(tmp_path / "out.ply"), "--log", str(log), "--quiet"],
                   check=True, capture_output=True)
    tree = json.loads(log.read_text())
    return {k: v for k, v in tree.items() if k not in NOT_IN_DICTS}


def test_fill_report_fields(cli, tmp_path, data_dir, hand):
    _, _, report = fairsurf.fill_holes(*hand)
    assert keys(report) == keys(cli_log(cli, tmp_path, "fill", data_dir / "hand_lowres.obj"))


def test_smooth_report_fields(cli, tmp_path, data_dir, hand):
    _, report = fairsurf.smooth(*hand, steps=2)
    log = cli_log(cli, tmp_path, "smooth", data_dir / "hand_lowres.obj", "--steps", 2)
    assert keys(report) == keys(log)
    # The time-stepped flow has no Gauss–Newton model: nothing is promised to any trial, accepted or
    # rejected (None here, null in the log).
    assert sum(s["accepted"] for s in report["steps"]) == 2
    assert len(log["steps"]) == len(report["steps"])
    assert all(s["predicted_decrease"] is None for s in report["steps"])
    assert all(s["predicted_decrease"] is None for s in log["steps"])


def test_fair_report_fields(cli, tmp_path):
    subprocess.run([str(cli), "scene", "sphere-cap", "-o", str(tmp_path / "cap.ply"), "--edge-length", "0.3"],
                   check=True, capture_output=True)
    V, F = fairsurf.read_mesh(tmp_path / "cap.ply")
    cap = V[:, 2] == 0.5  # the scene flattens its free cap onto z = 0.5 (and a few vertices lie on it)
    (tmp_path / "cap.txt").write_text(" ".join(map(str, cap.nonzero()[0])))
    V_faired, report = fairsurf.fair(V, F, region=cap)
    log = cli_log(cli, tmp_path, "fair", tmp_path / "cap.ply", "--region", tmp_path / "cap.txt")
    assert keys(report) == keys(log)
    assert report["free_vertices"] == log["free_vertices"] == cap.sum()
    V_cli, _ = fairsurf.read_mesh(tmp_path / "out.ply")
    assert np.abs(V_faired - V_cli).max() <= 1e-12
    # The energy descent's model never promises a rise, and the log carries the same promises.
    promised = [s["predicted_decrease"] for s in report["steps"]]
    assert promised and all(p >= 0 for p in promised)
    assert promised == [s["predicted_decrease"] for s in log["steps"]]


def test_fair_report_of_a_region_in_parts(cli, tmp_path, data_dir):
    # Two balls on blub far apart: each part faired on its own, reported under "parts" (the CLI's
    # log the same), the whole labelled by its weakest part.
    V, F = fairsurf.read_mesh(data_dir / "blub.obj")
    region = np.zeros(len(V), dtype=bool)
    for centre in (1987, 6569):
        region |= np.linalg.norm(V - V[centre], axis=1) <= 0.148137
    (tmp_path / "parts.txt").write_text(" ".join(map(str, region.nonzero()[0])))
    _, report = fairsurf.fair(V, F, region=region)
    log = cli_log(cli, tmp_path, "fair", data_dir / "blub.obj", "--region", tmp_path / "parts.txt")
    assert keys(report) == keys(log)
    assert [p["delivered"] for p in report["parts"]] == [p["delivered"] for p in log["parts"]]
    assert sorted(p["delivered"] for p in report["parts"]) == ["C2 (linear)", "G2"]
    assert sum(p["free_vertices"] for p in report["parts"]) == report["free_vertices"] == region.sum()
    assert report["delivered"] == "C2 (linear)"


def test_blend_report_fields_and_result(cli, tmp_path):
    subprocess.run([str(cli), "scene", "fig4", "-o", str(tmp_path / "fig4.ply"), "--edge-length", "0.25"],
                   check=True, capture_output=True)
    V, F = fairsurf.read_mesh(tmp_path / "fig4.ply")
    V2, F2, report = fairsurf.blend(V, F, max_steps=5)
    log = cli_log(cli, tmp_path, "blend", tmp_path / "fig4.ply", "--max-steps", 5)
    assert keys(report) == keys(log)
    assert fairsurf.info(V2, F2)["boundary_loops"] == []  # two caps joined into a closed surface
    V_cli, F_cli = fairsurf.read_mesh(tmp_path / "out.ply")
    assert np.array_equal(F2, F_cli) and np.abs(V2 - V_cli).max() <= 1e-12


def test_blend_all_pairs_is_blend_all(cli, tmp_path, data_dir):
    # The blobby's three pieces: two blends, as `fairsurf blend --all` makes them and logs them.
    path = data_dir / "cgal_blobby_3cc.off"
    V, F = fairsurf.read_mesh(path)
    V2, F2, report = fairsurf.blend(V, F, all_pairs=True)
    log = cli_log(cli, tmp_path, "blend", path, "--all")
    assert keys(report) == keys(log)
    assert [b["loops_found"] for b in report["blends"]] == [4, 2]
    assert report["unjoined"] == [] and report["loops_left"] == 0
    assert fairsurf.info(V2, F2)["boundary_loops"] == []
    V_cli, F_cli = fairsurf.read_mesh(tmp_path / "out.ply")
    assert np.array_equal(F2, F_cli) and np.abs(V2 - V_cli).max() <= 1e-12
    with pytest.raises(fairsurf.InvalidArgument):
        fairsurf.blend(V, F, loops=(0, 3), all_pairs=True)


def test_blend_all_pairs_leaves_a_pair_it_cannot_join_open(tmp_path):
    # Two copies of the fig4 caps side by side, a thin closed octahedron (a disk) in the gap of the
    # first: its pair cannot be joined, the other pair is, and the report says which stayed open.
    V, F = fairsurf.scene("fig4")[:2]
    disk = np.array([[1.5, 0, 0], [-1.5, 0, 0], [0, 1.5, 0], [0, -1.5, 0], [0, 0, 0.02], [0, 0, -0.02]])
    disk_faces = np.array([[0, 2, 4], [2, 1, 4], [1, 3, 4], [3, 0, 4], [2, 0, 5], [1, 2, 5], [3, 1, 5], [0, 3, 5]])
    shifted = V + np.array([5.0, 0, 0])
    V2 = np.vstack([V, disk, shifted])
    F2 = np.vstack([F, disk_faces + len(V), F + len(V) + len(disk)])
    V3, F3, report = fairsurf.blend(V2, F2, all_pairs=True, max_steps=20)
    assert len(report["blends"]) == 1 and report["loops_left"] == 2
    (unjoined,) = report["unjoined"]
    assert "crosses the mesh" in unjoined["why"] and not unjoined["repairable"]
    assert (unjoined["loop_a"], unjoined["loop_b"]) == (0, 1)  # the first copy's loops
    assert unjoined["length_a"] == unjoined["length_b"] == 54
    assert fairsurf.info(V3, F3)["boundary_loops"] == [54, 54]
    assert np.array_equal(V3[: len(V2)], V2)


def test_info_fields_and_values(cli, data_dir):
    path = data_dir / "lagrange_prout.obj"  # findings of most kinds, with examples
    out = subprocess.run([str(cli), "info", str(path), "--json"], check=True, capture_output=True, text=True).stdout
    cli_info = json.loads(out)
    for read_only in ("file", "polygons_triangulated", "triangles_added", "read_notes", "texture_coordinates",
                      "textured_triangles", "normals", "normal_triangles", "polygons"):
        del cli_info[read_only]
    report = fairsurf.info(*fairsurf.read_mesh(path))
    assert keys(report) == keys(cli_info)
    as_json = json.loads(json.dumps(report))  # tuples become lists, as in the CLI's JSON
    assert as_json == cli_info
