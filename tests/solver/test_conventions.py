"""The solver's outputs keep the project's conventions: slip has the sign of q2 - q1.

The convention (fixed for every command): the slip is the change of u_x(indenter) -
u_x(lower body) from state 1 to state 2, and q the traction the indenter exerts on the lower
body; Coulomb's law then makes the slip in a slip zone point along q2 - q1 (the sliding body
drags the other one along its own slip).  Checked on the files a user reads (slip.csv and
tractions.csv) for cycles that slip forward and backward, with and without bulk tension, at
both edges.
"""

from __future__ import annotations

import io
import json

import numpy as np
import pytest

from asymslip import HertzLaw, LoadCycle
from asymslip.solver import solve
from asymslip.solver.conventions import CONVENTIONS
from asymslip.solver.outputs import csv_texts

LAW = HertzLaw(R=1.0, E_star=1.0)
CYCLES = {
    "forward (Fig. 5)": LoadCycle(100.0, 0.0, 105.0, 1.0),
    "backward": LoadCycle(100.0, 1.0, 105.0, 0.0),
    "forward with tension": LoadCycle(100.0, 0.0, 105.0, 1.0, 0.0, 0.05),
}


def columns(text: str) -> dict[str, np.ndarray]:
    """A CSV file's columns by header name (its comment lines skipped; blank cells NaN)."""
    body = "\n".join(line for line in text.splitlines() if not line.startswith("#"))
    table = np.genfromtxt(io.StringIO(body), delimiter=",", names=True)
    return {name: table[name] for name in table.dtype.names}


@pytest.fixture(scope="module", params=list(CYCLES))
def files(request: pytest.FixtureRequest) -> tuple[str, dict[str, np.ndarray]]:
    result = solve(LAW, CYCLES[request.param], 0.1, elements=800, steps=8)
    assert result.steady
    texts = csv_texts(result)
    data = columns(texts["tractions.csv"]) | columns(texts["slip.csv"])
    return request.param, data


def test_slip_in_a_slip_zone_has_the_sign_of_q2_minus_q1(files):
    name, data = files
    # A slip zone at state 2: elements in contact at both states that slip at state 2.
    zone = (data["state_2"] != 0) & np.isfinite(data["state_1"]) & np.isfinite(data["state_2"])
    moved = zone & (np.abs(data["slip_2"]) > 1e-9 * np.abs(data["slip_2"]).max())
    assert moved.sum() >= 10, f"{name}: too few slipping elements to check"
    q_change = data["q_2"] - data["q_1"]
    assert np.all(np.sign(data["slip_2"][moved]) == np.sign(q_change[moved]))
    # Both edges are checked: slipping elements on both sides of the centre.
    assert np.any(data["x"][moved] > 0) and np.any(data["x"][moved] < 0)


def test_the_forward_cycle_slips_along_plus_x_and_the_backward_one_along_minus_x():
    # The direction itself, not only its agreement with q: with Q rising from state 1 to
    # state 2 (the indenter pushed along +x) its slip zones slide along +x over the lower
    # body, at both edges; with Q falling, along -x.
    signs = {}
    for name in ("forward (Fig. 5)", "backward"):
        result = solve(LAW, CYCLES[name], 0.1, elements=400, steps=4)
        slip = result.states[1].slip
        signs[name] = set(np.sign(slip[np.abs(slip) > 1e-9 * np.abs(slip).max()]).tolist())
    assert signs == {"forward (Fig. 5)": {1.0}, "backward": {-1.0}}


def test_every_output_states_the_conventions_in_the_same_words():
    result = solve(LAW, CYCLES["forward (Fig. 5)"], 0.1, elements=200, steps=2)
    words = list(CONVENTIONS.values())
    for text in csv_texts(result).values():
        header = "\n".join(line for line in text.splitlines() if line.startswith("#"))
        assert all(sentence in header for sentence in words)
    data = json.loads(json.dumps(result.to_dict()))
    assert data["conventions"] == dict(CONVENTIONS)
    assert "indenter on the lower body" in CONVENTIONS["q"]
    assert "u_x(indenter) - u_x(lower body)" in CONVENTIONS["slip"]
