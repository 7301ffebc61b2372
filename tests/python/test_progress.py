import numpy as np
import pytest

import fairsurf


def test_returning_false_stops_and_keeps_the_last_accepted_state(hand):
    V, F = hand
    seen = []

    def stop_after_three_accepted(step):
        seen.append(step)
        return sum(s["accepted"] for s in seen) < 3

    V_stopped, report = fairsurf.smooth(V, F, steps=20, progress=stop_after_three_accepted)
    assert report["stop_reason"] == "interrupted"
    assert report["accepted_steps"] == 3
    assert seen == report["steps"]  # the callback got every step's report, as the report lists them
    V_three, reference = fairsurf.smooth(V, F, steps=3)
    assert reference["stop_reason"] == "max steps"
    assert np.array_equal(V_stopped, V_three)


def test_none_or_true_lets_the_run_finish(hand):
    V, F = hand
    _, report = fairsurf.smooth(V, F, steps=2, progress=lambda step: None)
    assert report["stop_reason"] == "max steps" and report["accepted_steps"] == 2


def test_stopping_a_fill_keeps_its_linear_floor(hand):
    V, F = hand
    calls = []
    V2, F2, report = fairsurf.fill_holes(V, F, progress=lambda step: calls.append(step) or False)
    assert len(calls) == 1 and calls[0]["holes"] == (0,)
    hole = report["holes"][0]
    assert hole["status"] == "filled" and hole["delivered"] == "C2 (linear)" and hole["steps"] == 0
    assert fairsurf.info(V2, F2)["boundary_loops"] == []


def test_an_exception_in_the_callback_stops_the_run_and_propagates(hand):
    V, F = hand
    calls = []

    def fail(step):
        calls.append(step)
        raise KeyError("from the callback")

    with pytest.raises(KeyError, match="from the callback"):
        fairsurf.smooth(V, F, steps=20, progress=fail)
    assert len(calls) == 1


def test_progress_must_be_callable(hand):
    with pytest.raises(TypeError, match="progress must be callable or None"):
        fairsurf.smooth(*hand, steps=1, progress=3)
