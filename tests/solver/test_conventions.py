"""The solver's outputs keep the project's conventions: slip opposite in sign to q2 - q1.

The convention (the paper's (38), fixed for every command): q is the shear traction the lower
body exerts on the indenter (Q = int q dx, the shear force on the indenter), and the slip is
delta = the change from state 1 to state 2 of u_x(indenter) - u_x(lower body).  Coulomb's law
for the indenter: where it slips, the friction it receives opposes its motion relative to the
lower body, and that friction is the traction q.  Over a loading step of a slip zone the
indenter's traction goes from q1 towards q2 (by the step's change of mu p on an element
already slipping, or from inside the friction bound to +-mu p on one that starts to slip),
and the slip zone carries q2 = -mu p sign(d delta): where q2 - q1 > 0 the slip decreases,
delta < 0, and the other way round.  So in a slip zone delta has the sign opposite to q2 - q1.

The slip is checked against the elastic displacements of the two bodies computed here from the
solver's own tractions with the Flamant kernel (``derivations/solver_influence.py``: a surface
traction t along +x on a half-plane gives du_x/dx = -(1/(pi E*)) int t(xi)/(x - xi) dxi, E*
the plane-strain contact modulus of the pair, whichever side the body lies): the indenter
carries q, the lower body -q, so the change of u_x(indenter) - u_x(lower body) is
-(2/(pi E*)) int (q2 - q1) ln|x - xi| dxi plus a rigid shift, which the permanent stick zone
(no slip) fixes.  Then on the files a user reads (slip.csv and tractions.csv) for cycles that
slip forward and backward, with and without bulk tension, at both edges.
"""

from __future__ import annotations

import io
import json

import numpy as np
import pytest

from asymslip import HertzLaw, LoadCycle
from asymslip.solver import SolverResult, solve
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
def solved(request: pytest.FixtureRequest) -> tuple[str, SolverResult]:
    result = solve(LAW, CYCLES[request.param], 0.1, elements=800, steps=8)
    assert result.steady
    return request.param, result


def relative_displacement_change(result: SolverResult) -> np.ndarray:
    """Change of u_x(indenter) - u_x(lower body) from state 1 to 2 at the element centres.

    Flamant's kernel integrated over each element of uniform traction (independent of the
    solver's Toeplitz products), plus the uniform surface strain (1 - nu^2) sigma/E =
    sigma/(2 E*) of a bulk tension sigma (the lower body's minus the indenter's): the lower
    body's surface stretches by d sigma x/(2 E*) relative to the indenter's.  The rigid shift is
    fixed by the permanent stick zone, which does not slip.
    """
    x, h = result.x, result.element_size
    change = result.states[1].shear - result.states[0].shear  # on the indenter; lower body: -it

    def primitive(u: np.ndarray) -> np.ndarray:  # an antiderivative of ln|u|
        return u * np.log(np.abs(u)) - u

    offsets = x[:, None] - x[None, :]  # never +-h/2: the logarithm's ends are never 0
    logs = primitive(offsets + h / 2) - primitive(offsets - h / 2)  # int ln|x_i - xi| over j
    # u_x(indenter) from q and u_x(lower body) from -q, each -(1/(pi E*)) int t ln|x - xi|:
    delta = -(2 / (np.pi * result.E_star)) * (logs @ change)
    delta -= (result.states[1].sigma - result.states[0].sigma) * x / (2 * result.E_star)
    return delta - np.mean(delta[result.permanent_stick])


def slip_zone(result: SolverResult) -> np.ndarray:
    """Elements in contact at both states that slip at state 2 and moved."""
    one, two = result.states[0], result.states[1]
    zone = one.contact & two.contact & (two.slip_sign != 0)
    return zone & (np.abs(two.slip) > 1e-6 * np.abs(two.slip).max())


def test_the_slip_is_the_change_of_the_bodies_relative_displacement(solved):
    name, result = solved
    expected = relative_displacement_change(result)
    moved = slip_zone(result)
    assert moved.sum() >= 8, f"{name}: too few slipping elements to check"
    # The stick zone does not move relative to the shift fixed on it: the kernel is consistent.
    assert np.max(np.abs(expected[result.permanent_stick])) < 1e-8 * np.max(np.abs(expected))
    # The reported slip is that displacement, in sign and size (measured: within 6e-10 of its
    # peak; the same kernel, summed by FFT in the solver and step by step).
    scale = np.max(np.abs(expected[moved]))
    assert np.max(np.abs(result.states[1].slip[moved] - expected[moved])) < 1e-7 * scale
    assert np.all(np.sign(result.states[1].slip[moved]) == np.sign(expected[moved]))


def test_slip_in_a_slip_zone_has_the_sign_opposite_to_q2_minus_q1(solved):
    name, result = solved
    data = columns(csv_texts(result)["tractions.csv"]) | columns(csv_texts(result)["slip.csv"])
    # A slip zone at state 2: elements in contact at both states that slip at state 2.
    zone = (data["state_2"] != 0) & np.isfinite(data["state_1"]) & np.isfinite(data["state_2"])
    moved = zone & (np.abs(data["slip_2"]) > 1e-6 * np.abs(data["slip_2"]).max())
    assert moved.sum() >= 8, f"{name}: too few slipping elements to check"
    q_change = data["q_2"] - data["q_1"]
    assert np.all(np.sign(data["slip_2"][moved]) == -np.sign(q_change[moved]))
    # Friction opposes the slip at state 2: q_2 = -mu p_2 sign(slip_2) there.
    assert np.all(np.sign(data["q_2"][moved]) == -np.sign(data["slip_2"][moved]))
    # Both edges are checked: slipping elements on both sides of the centre.
    assert np.any(data["x"][moved] > 0) and np.any(data["x"][moved] < 0)


def test_the_forward_cycle_slips_along_minus_x_and_the_backward_one_along_plus_x():
    # The direction itself, not only its agreement with q: with Q rising from state 1 to
    # state 2 (the lower body pushing the indenter harder along +x, the pad holder holding it
    # back) the indenter's slip zones slide along -x over the lower body, at both edges; with
    # Q falling, along +x.
    signs = {}
    for name in ("forward (Fig. 5)", "backward"):
        result = solve(LAW, CYCLES[name], 0.1, elements=400, steps=4)
        slip = result.states[1].slip
        signs[name] = set(np.sign(slip[np.abs(slip) > 1e-9 * np.abs(slip).max()]).tolist())
    assert signs == {"forward (Fig. 5)": {-1.0}, "backward": {1.0}}


def test_every_output_states_the_conventions_in_the_same_words():
    result = solve(LAW, CYCLES["forward (Fig. 5)"], 0.1, elements=200, steps=2)
    words = list(CONVENTIONS.values())
    for text in csv_texts(result).values():
        header = "\n".join(line for line in text.splitlines() if line.startswith("#"))
        assert all(sentence in header for sentence in words)
    data = json.loads(json.dumps(result.to_dict()))
    assert data["conventions"] == dict(CONVENTIONS)
    assert "on the indenter by the lower body" in CONVENTIONS["q"]
    assert "u_x(indenter) - u_x(lower body)" in CONVENTIONS["slip"]
    assert "opposite to q2 - q1" in CONVENTIONS["slip"]
