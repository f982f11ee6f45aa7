"""The calibration as data: its JSON (``calibrate --json``), saving, loading and refusing.

The traces are the Hertz law's on a 120-node mesh (tests/calibration/helpers.py).
"""

from __future__ import annotations

import json

import numpy as np
import pytest

from asymslip import InputError
from asymslip.calibration import Calibration, Traces, calibrate
from tests.calibration.helpers import LAWS, mesh, sampled_traces

LOADS = (80.0, 95.0, 110.0, 125.0)
HERTZ = LAWS["hertz"]


@pytest.fixture(scope="module")
def calibration() -> Calibration:
    rng = np.random.default_rng(2)
    x = mesh("graded", float(HERTZ.half_width(100.0)), 120, rng)
    return calibrate(sampled_traces(HERTZ.pressure, LOADS, x, 0.0, rng))


def test_json_lists_both_edges_per_load_with_P_a_errors_and_window(calibration):
    data = calibration.to_dict()
    for side in ("right", "left"):
        assert [entry["P"] for entry in data[side]] == list(LOADS)
        for entry in data[side]:
            assert {"P", "a", "a_error", "L_I", "L_I_error", "window"} <= set(entry)
            assert set(entry["window"]) == {"x_from", "x_to", "nodes"}
            assert entry["window"]["nodes"] >= 4
            assert abs(entry["a"] - float(HERTZ.half_width(entry["P"]))) <= entry["a_error"] + abs(
                data["origin"]
            )
    json.dumps(data, allow_nan=False)  # plain JSON, no NaN


def test_the_default_origin_is_the_contact_centre_at_the_smallest_load(calibration):
    right, left = calibration.right[0], calibration.left[0]
    assert calibration.origin == 0.5 * (right.x_edge + left.x_edge)
    assert abs(calibration.origin) <= max(right.a_error, left.a_error)  # Hertz is centred at 0
    data = calibration.to_dict()
    assert data["right"][0]["a"] == data["left"][0]["a"]  # equal distances at that load


def test_an_origin_outside_a_contact_is_refused(calibration):
    rng = np.random.default_rng(2)
    x = mesh("graded", float(HERTZ.half_width(100.0)), 120, rng)
    traces = sampled_traces(HERTZ.pressure, LOADS, x, 0.0, rng)
    with pytest.raises(InputError, match="origin: x = 12 is not inside the contact at P = 80"):
        calibrate(traces, origin=12.0)


def test_save_and_load_give_back_the_same_calibration(calibration, tmp_path):
    path = tmp_path / "calibration.json"
    calibration.save(path)
    assert Calibration.load(path) == calibration  # every float round-trips exactly
    assert not list(tmp_path.glob(".*partial"))  # written atomically, nothing left beside


@pytest.mark.parametrize(
    ("edit", "words"),
    [
        (lambda text: text[: len(text) // 2], "not valid JSON"),
        (
            lambda text: text.replace('"asymslip-calibration"', '"something-else"'),
            "not a calibration",
        ),
        (lambda text: text.replace('"version": 1', '"version": 7'), "version 7 is not supported"),
        (lambda text: text.replace('"L_I": ', '"L_I": -', 1), "right[0]: 'L_I' must be > 0"),
        (
            lambda text: text.replace('"a_error": ', '"a_error": NaN, "x": ', 1),
            "NaN is not a number a calibration may hold",
        ),
        (
            lambda text: text.replace('"nodes": ', '"nodes": 0.5, "n": ', 1),
            "'window.nodes' must be a positive integer",
        ),
        (
            lambda text: text.replace('"x_edge": ', '"x_edge": "12", "was": ', 1),
            "'x_edge' must be a finite number",
        ),
        (lambda text: text.replace('"P": 95.0', '"P": 70.0'), "the loads P must increase"),
        (
            lambda text: text.replace('"error_kind": "estimate"', '"error_kind": "maybe"', 1),
            "right[0]: 'error_kind' must be \"estimate\" or \"bound\" (got 'maybe')",
        ),
        (
            lambda text: text.replace('"x_edge": ', '"x_edge": 1e3, "ignored": ', 1),
            "is not the distance of 'x_edge'",
        ),
    ],
)
def test_a_malformed_calibration_file_is_refused_in_one_line(calibration, tmp_path, edit, words):
    path = tmp_path / "calibration.json"
    calibration.save(path)
    path.write_text(edit(path.read_text()))
    with pytest.raises(InputError) as caught:
        Calibration.load(path)
    message = str(caught.value)
    assert words in message and "\n" not in message and message.startswith("calibration: ")


def test_every_fit_says_whether_its_errors_are_estimates_or_bounds(calibration):
    """Hertz on 120 graded nodes: the windows show the expansion's order, so estimates."""
    data = calibration.to_dict()
    assert {entry["error_kind"] for side in ("right", "left") for entry in data[side]} == {
        "estimate"
    }


def test_a_file_written_before_the_error_kind_loads_with_estimates(calibration, tmp_path):
    """Files written before fits told estimates from bounds reported them as estimates."""
    data = calibration.to_dict()
    for side in ("right", "left"):
        for entry in data[side]:
            del entry["error_kind"]
    path = tmp_path / "old.json"
    path.write_text(json.dumps(data))
    loaded = Calibration.load(path)
    assert all(fit.error_kind == "estimate" for fit in loaded.right + loaded.left)


def test_a_missing_file_is_refused_naming_it(tmp_path):
    with pytest.raises(InputError, match="cannot read .*absent.json"):
        Calibration.load(tmp_path / "absent.json")


def test_one_edge_only_is_taken_as_symmetric_about_zero(tmp_path):
    x = np.linspace(0.0, 1.6 * float(HERTZ.half_width(125.0)), 100)
    P = np.repeat(LOADS, x.size)
    p = np.concatenate([HERTZ.pressure(x, load) for load in LOADS])
    traces = Traces.from_arrays(P, np.tile(x, len(LOADS)), p, side=["right"] * P.size)
    result = calibrate(traces)
    assert result.origin == 0.0 and result.symmetric_about_origin and not result.left
    assert any("taken as symmetric about x = 0" in warning for warning in result.warnings)
    with pytest.raises(InputError, match="the origin must be 0"):
        calibrate(traces, origin=0.5)
