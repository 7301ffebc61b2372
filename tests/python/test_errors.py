"""Bad input: ValueError naming the argument for arrays of the wrong dtype or shape, the library's
exception type and message otherwise."""

import pickle

import numpy as np
import pytest

import fairsurf


def test_hierarchy():
    for cls in (fairsurf.InvalidArgument, fairsurf.InvalidMeshError, fairsurf.IoError, fairsurf.NumericalError):
        assert issubclass(cls, fairsurf.Error)
    assert issubclass(fairsurf.ParseError, fairsurf.IoError)
    assert issubclass(fairsurf.RepairableMeshError, fairsurf.InvalidMeshError)


def with_nan(V):
    V = V.copy()
    V[5, 1] = np.nan
    return V


def with_index(F, index):
    F = F.copy()
    F[3, 2] = index
    return F


@pytest.mark.parametrize(
    "make, message",
    [
        (lambda V, F: (V.astype(np.float32), F), "V must have dtype float64, got float32"),
        (lambda V, F: (V[:, :2].copy(), F), "V must have shape (n, 3), got (810, 2)"),
        (lambda V, F: (V.ravel(), F), "V must have shape (n, 3), got (2430,)"),
        (lambda V, F: (V.tolist(), F), "V must be a NumPy array, got list"),
        (lambda V, F: (V, F.astype(np.float64)), "F must have dtype int32, int64, uint32 or uint64, got float64"),
        (lambda V, F: (V, F.astype(np.int16)), "F must have dtype int32, int64, uint32 or uint64, got int16"),
        (lambda V, F: (V, with_index(F.astype(np.uint64), 2**63 + 5)),
         "F: index 9223372036854775813 at face 3 does not fit a 32-bit int"),
        (lambda V, F: (V, F[:, :2].copy()), "F must have shape (n, 3), got (1602, 2)"),
        (lambda V, F: (V, with_index(F.astype(np.int64), 2**40)),
         "F: index 1099511627776 at face 3 does not fit a 32-bit int"),
    ],
)
def test_wrong_dtype_or_shape_raises_value_error(hand, make, message):
    V, F = make(*hand)
    for function in (fairsurf.info, fairsurf.curvature, fairsurf.fill_holes, fairsurf.smooth):
        with pytest.raises(ValueError) as error:
            function(V, F)
        assert str(error.value) == message


def test_unsigned_faces_are_accepted(hand):
    # PLY readers and VTK hand out uint32 faces; the result is the one int32 faces give.
    V, F = hand
    expected = fairsurf.info(V, F)
    for dtype in (np.uint32, np.uint64):
        assert fairsurf.info(V, F.astype(dtype)) == expected


def test_arrays_that_went_through_pickle_are_accepted(hand):
    # multiprocessing pickles arrays: their dtypes come back equal to float64 and int32/int64 but as
    # other objects, which a check of the dtype's identity refused ("got float64").
    V, F = hand
    expected = fairsurf.info(V, F)
    for faces in (F.astype(np.int32), F.astype(np.int64)):
        V2, F2 = pickle.loads(pickle.dumps((V, faces)))
        assert V2.dtype == np.float64 and V2.dtype is not np.dtype(np.float64)
        assert fairsurf.info(V2, F2) == expected


def test_nan_coordinates(hand):
    V, F = hand
    with pytest.raises(fairsurf.InvalidMeshError) as error:
        fairsurf.curvature(with_nan(V), F)
    assert str(error.value) == "fit_quadratics: a vertex coordinate is not finite"
    with pytest.raises(fairsurf.RepairableMeshError) as error:
        fairsurf.fill_holes(with_nan(V), F)
    assert str(error.value) == "fill_holes: mesh has 1 vertex with a NaN or infinite coordinate (first: 5)"
    assert fairsurf.info(with_nan(V), F)["nan_vertices"] == 1


def test_out_of_range_indices(hand, tmp_path):
    V, F = hand
    with pytest.raises(fairsurf.InvalidMeshError) as error:
        fairsurf.curvature(V, with_index(F, 810))
    assert str(error.value) == "build_topology: face 3 has vertex index 810 outside [0, 810)"
    with pytest.raises(fairsurf.InvalidMeshError) as error:
        fairsurf.fill_holes(V, with_index(F, -1))
    assert str(error.value) == "fill_holes: mesh has 1 face with an out-of-range vertex index (first: 3)"
    with pytest.raises(fairsurf.InvalidArgument) as error:
        fairsurf.write_mesh(tmp_path / "out.obj", V, with_index(F, 9999))
    assert str(error.value) == "write_mesh: face 3 has vertex index 9999 outside [0, 810)"
    assert not (tmp_path / "out.obj").exists()


def test_library_errors_carry_their_message(tmp_path):
    with pytest.raises(fairsurf.IoError) as error:
        fairsurf.read_mesh(tmp_path / "missing.obj")
    assert str(error.value) == f"read_raw: {tmp_path / 'missing.obj'}: cannot open (No such file or directory)"
    with pytest.raises(fairsurf.InvalidArgument) as error:
        fairsurf.scene("nope")
    assert str(error.value) == "make_scene: unknown scene 'nope' (scenes: fig3, fig4, fig7, fig8, sphere-cap)"


def test_bad_options(hand):
    V, F = hand
    with pytest.raises(fairsurf.InvalidArgument) as error:
        fairsurf.fill_holes(V, F, holes=[1])
    assert str(error.value).startswith("fill_holes: hole 1 is outside [0, 1)")
    with pytest.raises(fairsurf.InvalidArgument) as error:
        fairsurf.smooth(V, F, steps=3, time=0.1)
    assert str(error.value) == "smooth: give at most one of steps, time and steady"
    with pytest.raises(fairsurf.InvalidArgument) as error:
        fairsurf.smooth(V, F, steps=0)
    assert str(error.value) == "smooth: steps must be >= 1"
    for bad in ({"time": 0.0}, {"tau": -1e-3}):
        with pytest.raises(fairsurf.InvalidArgument) as error:
            fairsurf.smooth(V, F, **bad)
        assert str(error.value) == "smooth: time and tau must be positive"
    with pytest.raises(ValueError) as error:
        fairsurf.fair(V, F, region=np.ones(5, dtype=bool))
    assert str(error.value) == "region: a boolean mask must have one entry per vertex (810), got 5"


def test_a_failed_flow_raises_numerical_error_with_the_last_accepted_state(data_dir):
    # f = K is not parabolic on the torus: its flow fails after some accepted steps, as
    # `fairsurf smooth data/torus.obj --functions K --tau 0.9 --steps 30` does (exit 4, state written).
    V, F = fairsurf.read_mesh(data_dir / "torus.obj")
    with pytest.raises(fairsurf.NumericalError) as error:
        fairsurf.smooth(V, F, functions=["K"], tau=0.9, steps=30)
    message = str(error.value)
    assert "consecutive rejected steps" in message
    assert "f is not parabolic at" in message
    last = error.value.V
    assert last.shape == V.shape and last.dtype == np.float64
    assert np.all(np.isfinite(last))
    assert np.abs(last - V).max() > 0  # accepted steps moved the mesh before the failure
