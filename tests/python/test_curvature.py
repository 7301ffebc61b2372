import numpy as np

import fairsurf


def test_mean_curvature_of_a_sphere_is_minus_one_over_r(data_dir):
    V, F = fairsurf.read_mesh(data_dir / "sphere_16k.off")
    V = V - V.mean(axis=0)
    R = np.linalg.norm(V, axis=1).mean()
    c = fairsurf.curvature(V * 2.0, F)  # scaled to radius 2R: H must follow the radius
    assert c["well_posed"].all()
    assert np.abs(c["H"] * 2.0 * R + 1.0).max() < 1e-2
    assert np.abs(c["K"] * (2.0 * R) ** 2 - 1.0).max() < 2e-2
    assert np.all(c["k1"] >= c["k2"])
    # Outward normals: n·x > 0 everywhere.
    assert np.all(np.einsum("ij,ij->i", c["normal"], V) > 0)
    assert c["H"].shape == (V.shape[0],) and c["H"].dtype == np.float64


def test_flipping_the_orientation_flips_h(data_dir):
    V, F = fairsurf.read_mesh(data_dir / "sphere_16k.off")
    H = fairsurf.curvature(V, F)["H"]
    H_flipped = fairsurf.curvature(V, F[:, ::-1])["H"]
    assert np.allclose(H_flipped, -H, rtol=0, atol=1e-12)
