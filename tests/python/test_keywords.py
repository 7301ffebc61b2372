"""Keyword names are the option fields' (docs/python.md): `functions` sets FlowOptions::functions and
`fixed_vertices` SmoothOptions::fixed_vertices; their former names `f` and `fixed`, the CLI flags'
before they were renamed after the fields, stay as aliases."""

import numpy as np
import pytest

import fairsurf


def test_functions_and_its_alias_f_set_the_same_functions(hand):
    V, F = hand
    V_named, named = fairsurf.smooth(V, F, functions=["H", "K"], steps=1)
    V_alias, alias = fairsurf.smooth(V, F, f=["H", "K"], steps=1)
    V_default, default = fairsurf.smooth(V, F, steps=1)
    assert named["functions"] == alias["functions"] == ["H", "K"]
    assert default["functions"] == ["H"]
    assert np.array_equal(V_named, V_alias)
    assert not np.array_equal(V_named, V_default)  # the functions reached the flow


def test_fill_holes_takes_functions(hand):
    V, F = hand
    _, _, report = fairsurf.fill_holes(V, F, functions=["absHpH:0.5"], max_steps=2)
    assert report["functions"] == ["absHpH:0.5"]


def test_fixed_vertices_and_its_alias_fixed_hold_the_same_vertices(hand):
    V, F = hand
    held = [100, 200, 300]
    V_named, _ = fairsurf.smooth(V, F, fixed_vertices=held, steps=1)
    V_alias, _ = fairsurf.smooth(V, F, fixed=held, steps=1)
    V_free, _ = fairsurf.smooth(V, F, steps=1)
    assert np.array_equal(V_named, V_alias)
    assert np.array_equal(V_named[held], V[held])
    assert not np.array_equal(V_free[held], V[held])


@pytest.mark.parametrize("call", ["smooth", "fill_holes", "fair", "blend"])
def test_a_field_and_its_alias_together_are_refused(hand, call):
    V, F = hand
    extra = {"region": [0]} if call == "fair" else {}
    with pytest.raises(TypeError) as error:
        getattr(fairsurf, call)(V, F, functions=["H"], f=["K"], **extra)
    assert str(error.value) == f"{call}() got both functions and its alias f; give one"


def test_fixed_vertices_and_fixed_together_are_refused(hand):
    V, F = hand
    with pytest.raises(TypeError) as error:
        fairsurf.smooth(V, F, fixed_vertices=[1], fixed=[2])
    assert str(error.value) == "smooth() got both fixed_vertices and its alias fixed; give one"


def test_fair_start_takes_the_cli_values_and_its_former_one(tmp_path):
    V, F = fairsurf.scene("sphere-cap", edge_length=0.3)
    cap = V[:, 2] == 0.5  # the scene flattens its free cap onto z = 0.5
    V_flat, _ = fairsurf.fair(V, F, region=cap, start="flat", max_steps=2)
    V_input, _ = fairsurf.fair(V, F, region=cap, start="input", max_steps=2)
    V_harmonic, _ = fairsurf.fair(V, F, region=cap, start="harmonic", max_steps=2)
    assert np.array_equal(V_flat, V_input)
    assert not np.array_equal(V_flat, V_harmonic)
    with pytest.raises(fairsurf.InvalidArgument) as error:
        fairsurf.fair(V, F, region=cap, start="membrane")
    assert str(error.value) == "fair: start must be 'harmonic' or 'flat' (alias 'input'), got 'membrane'"


@pytest.mark.parametrize("call", ["fill_holes", "fair", "blend"])
def test_keep_flow_is_reported_and_needs_the_flow(hand, call):
    # `keep_flow` is --keep-flow (keep_settled_flow): the report says it was given, and the harmonic
    # method, which runs no flow to keep, refuses it.
    V, F = fairsurf.scene("fig8") if call == "blend" else hand
    extra = {"region": np.arange(5)} if call == "fair" else {}
    report = getattr(fairsurf, call)(V, F, keep_flow=True, max_steps=3, **extra)[-1]
    assert report["keep_flow"] is True
    with pytest.raises(fairsurf.InvalidArgument, match="keep_flow keeps the flow's result; method 'harmonic'"):
        getattr(fairsurf, call)(V, F, keep_flow=True, method="harmonic", **extra)


def test_other_functions_are_weighed_on_the_held_out_rings(data_dir):
    # As `fair --other-functions H --other-functions K/kappa`: on a region of data/torus.obj the
    # held-out rings choose the flow with the Gaussian curvature term (by default they choose ∆³).
    V, F = fairsurf.read_mesh(data_dir / "torus.obj")
    region = np.flatnonzero(np.linalg.norm(V - [1.0, 0.0, 0.0], axis=1) < 0.45)
    _, default = fairsurf.fair(V, F, region)
    _, chosen = fairsurf.fair(V, F, region, other_functions=["H", "K/kappa"])
    assert default["other_functions"] == [] and not default["other_functions_chosen"]
    assert chosen["other_functions"] == ["H", "K/kappa"] and chosen["other_functions_chosen"]
    assert chosen["held_out_other_flow_error"] < chosen["held_out_flow_error"]
    assert "with f = {H, K/kappa} the flow re-predicts" in chosen["note"]
    # fill_holes: on the bunny scan's largest hole (hole 4) the flow with them is delivered, G2.
    Vb, Fb = fairsurf.read_mesh(data_dir / "stanford_bunny_zipper.obj")
    _, _, filled = fairsurf.fill_holes(Vb, Fb, other_functions=["H", "K/kappa"])
    hole = filled["holes"][4]
    assert hole["delivered"] == "G2" and hole["other_functions_chosen"]
    assert hole["held_out_other_flow_error"] < hole["held_out_flow_error"]
    assert not any(h["other_functions_chosen"] for h in filled["holes"][:4])
    with pytest.raises(fairsurf.InvalidArgument, match="only start 'harmonic' has"):
        fairsurf.fair(V, F, region, start="flat", other_functions=["K/kappa"])
    with pytest.raises(fairsurf.InvalidArgument, match="method 'harmonic' runs no flow"):
        fairsurf.fill_holes(V, F, method="harmonic", other_functions=["K/kappa"])
