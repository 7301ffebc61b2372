"""fairsurf.repair: `fairsurf repair` on arrays, and the repair that lets fill_holes take a mesh it refuses."""

import json
import subprocess

import numpy as np
import pytest

import fairsurf


def test_a_pinched_vertex_is_split_and_each_vertex_names_its_origin(data_dir):
    # Two icospheres touching at one vertex: the vertex gets a copy for its second fan.
    V, F = fairsurf.read_mesh(data_dir / "hourglass_ico.obj")
    assert not fairsurf.info(V, F)["manifold"]
    V2, F2, report = fairsurf.repair(V, F)
    assert report["changed"] and report["vertices_split"] == 1
    assert len(V2) == len(V) + 1 and fairsurf.info(V2, F2)["manifold"]
    origin = report["vertex_origin"]
    assert origin.dtype == np.int32 and origin.shape == (len(V2),)
    assert np.array_equal(origin[: len(V)], np.arange(len(V)))  # the copy comes last
    assert np.array_equal(V2, V[origin])  # no vertex moved: each sits where its origin was
    assert report["remaining_findings"] == {"duplicate_vertex_positions": 1}  # the copy, on purpose
    V3, F3, again = fairsurf.repair(V2, F2)
    assert not again["changed"]
    assert np.array_equal(V3, V2) and np.array_equal(F3, F2)
    assert np.array_equal(again["vertex_origin"], np.arange(len(V2)))
    assert np.array_equal(report["vertex_destination"], np.arange(len(V)))  # the copy is extra


def test_the_report_and_the_result_are_the_commands(cli, tmp_path, data_dir):
    # An unwelded soup: the command's JSON and output against the call's dict and arrays.
    mesh, out = data_dir / "cube_soup.obj", tmp_path / "out.ply"
    printed = subprocess.run([str(cli), "repair", str(mesh), "-o", str(out), "--json"], check=True,
                             capture_output=True, text=True).stdout
    log = {k: v for k, v in json.loads(printed).items() if k not in ("file", "output")}
    V, F = fairsurf.read_mesh(mesh)
    V2, F2, report = fairsurf.repair(V, F)
    assert report.pop("vertex_origin").shape == (8,)
    destination = report.pop("vertex_destination")
    assert destination.shape == (24,) and np.array_equal(V2[destination], V)  # each copy to its corner
    assert report == log
    assert report["vertices_merged"] == 16 and report["remaining_findings"] == {}
    V_cli, F_cli = fairsurf.read_mesh(out)
    assert np.array_equal(V2, V_cli) and np.array_equal(F2, F_cli)


def test_operations_switch_off_and_bad_values_are_refused(data_dir):
    V, F = fairsurf.read_mesh(data_dir / "cube_soup.obj")
    V2, _, report = fairsurf.repair(V, F, merge_duplicate_vertices=False, stitch_borders=False)
    assert report["vertices_merged"] == 0 and len(V2) == 24
    for name in ("merge_tolerance", "stitch_tolerance", "needle_tolerance", "min_component_faces"):
        with pytest.raises(fairsurf.InvalidArgument) as error:
            fairsurf.repair(V, F, **{name: -1})
        assert str(error.value) == f"repair: {name} must be at least 0, not -1"


def test_loose_fins_are_removed_unless_kept_as_the_command_keeps_them(cli, tmp_path, data_dir):
    # The raw Stanford zipper output: its splits cut three two-face pieces and seven one-face pages
    # loose from the surface.
    mesh = data_dir / "stanford_bunny_zipper_res2.ply"
    V, F = fairsurf.read_mesh(mesh)
    _, F2, report = fairsurf.repair(V, F)
    assert report["fins_removed"] == 10 and report["fin_faces_removed"] == 13
    _, F3, kept = fairsurf.repair(V, F, remove_loose_fins=False)
    assert kept["fins_removed"] == 0 and len(F3) == len(F2) + 13
    printed = subprocess.run([str(cli), "repair", str(mesh), "-o", str(tmp_path / "out.ply"), "--json",
                              "--keep-fins"], check=True, capture_output=True, text=True).stdout
    assert json.loads(printed)["fin_faces_removed"] == 0


def test_fill_holes_takes_the_mesh_once_repaired_as_fill_repair_does(cli, tmp_path, data_dir):
    # Fins on non-manifold edges: fill_holes refuses the mesh; repaired with the border's pinches kept
    # (what `fairsurf fill --repair` does), it fills what the command fills, to the bit.
    mesh, out = data_dir / "triple_vierbein.obj", tmp_path / "out.ply"
    V, F = fairsurf.read_mesh(mesh)
    with pytest.raises(fairsurf.RepairableMeshError):
        fairsurf.fill_holes(V, F)
    V2, F2, _ = fairsurf.repair(V, F, keep_border_pinches=True)
    V3, F3, report = fairsurf.fill_holes(V2, F2)
    assert report["filled"] == 2 and report["failed"] == 1
    done = subprocess.run([str(cli), "fill", str(mesh), "--repair", "-o", str(out)], capture_output=True)
    assert done.returncode == 4  # the same hole fails; the output holds the two filled
    V_cli, F_cli = fairsurf.read_mesh(out)
    assert np.array_equal(F3, F_cli) and np.array_equal(V3, V_cli)


def test_keep_border_pinches_keeps_two_holes_touching_at_a_vertex_joined(cli, tmp_path, hand):
    # A second hole cut at the wrist's hole: the star of a vertex next to border vertex b, but not
    # next to b's border neighbours, so that the two loops meet at b alone.
    V, F = hand
    edges = np.sort(np.concatenate([F[:, [0, 1]], F[:, [1, 2]], F[:, [2, 0]]]), axis=1)
    unique, counts = np.unique(edges, axis=0, return_counts=True)
    border = unique[counts == 1]
    b = border.min()
    along = set(border[(border == b).any(axis=1)].ravel()) - {b}

    def neighbours(v):
        return set(F[(F == v).any(axis=1)].ravel()) - {v}

    w = min(v for v in neighbours(b) if v not in set(border.ravel()) and not neighbours(v) & along)
    F_pinched = F[~(F == w).any(axis=1)]
    assert sorted(fairsurf.info(V, F_pinched)["boundary_loops"]) == [5, 16]
    assert fairsurf.repair(V, F_pinched)[2]["vertices_split"] == 1  # the default splits b
    V2, F2, kept = fairsurf.repair(V, F_pinched, keep_border_pinches=True)
    assert kept["vertices_split"] == 0 and kept["unreferenced_vertices_removed"] == 1  # w
    V3, F3, report = fairsurf.fill_holes(V2, F2)
    assert report["filled"] == 2 and report["failed"] == 0 and fairsurf.info(V3, F3)["manifold"]
    fairsurf.write_mesh(tmp_path / "pinched.ply", V, F_pinched)
    subprocess.run([str(cli), "fill", str(tmp_path / "pinched.ply"), "--repair", "-o", str(tmp_path / "out.ply")],
                   check=True, capture_output=True)
    V_cli, F_cli = fairsurf.read_mesh(tmp_path / "out.ply")
    assert np.array_equal(F3, F_cli) and np.array_equal(V3, V_cli)
