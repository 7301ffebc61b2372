import numpy as np
import pytest

import fairsurf


@pytest.mark.parametrize("extension", [".obj", ".off", ".ply"])
@pytest.mark.parametrize("binary", [True, False])
def test_round_trip_is_exact(tmp_path, hand, extension, binary):
    V, F = hand
    path = tmp_path / ("mesh" + extension)
    fairsurf.write_mesh(path, V, F, binary=binary)
    V2, F2 = fairsurf.read_mesh(path)
    assert V2.dtype == np.float64 and F2.dtype == np.int32
    assert np.array_equal(V2, V)
    assert np.array_equal(F2, F)


def test_int64_and_non_contiguous_inputs_give_the_same_file(tmp_path, hand):
    V, F = hand
    fairsurf.write_mesh(tmp_path / "a.ply", V, F)
    V_fortran = np.asfortranarray(V)
    assert not V_fortran.flags.c_contiguous
    fairsurf.write_mesh(tmp_path / "b.ply", V_fortran, F.astype(np.int64))
    assert (tmp_path / "a.ply").read_bytes() == (tmp_path / "b.ply").read_bytes()


def test_outputs_own_their_memory(hand):
    V, F = hand
    assert V.flags.c_contiguous and V.flags.writeable and V.shape == (810, 3)
    assert F.flags.c_contiguous and F.shape[1] == 3


def test_info_mirrors_the_cli(hand):
    V, F = hand
    report = fairsurf.info(V, F)
    assert report["vertices"] == 810
    assert report["boundary_loops"] == [16]
    assert report["lone_triangles"] == 0
    assert report["manifold"] and report["orientable"] and report["valid"]
    assert report["genus"] == 0


def test_scene_is_the_cli_scene(tmp_path, cli):
    import subprocess

    subprocess.run([str(cli), "scene", "fig4", "-o", str(tmp_path / "fig4.ply")], check=True, capture_output=True)
    V_cli, F_cli = fairsurf.read_mesh(tmp_path / "fig4.ply")
    V, F = fairsurf.scene("fig4")
    assert np.array_equal(V, V_cli) and np.array_equal(F, F_cli)
