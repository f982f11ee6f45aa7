"""An asymmetric contact under a moment: the edge-by-edge route against an exact solution.

The punch h(x) = x^2/(2R) + k x^3 (tests/calibration/helpers.py, CubicProfile: its pressure,
edges and rotation transcribed by hand from the bounded inversion of the half-plane equation)
is loaded along paths of P and M (about x = 0).  Its rotation changes along the path, so its
two edges have different laws, multipliers and slip zones, and (21) does not hold
(derivations/asymmetric_edge_multipliers.py, AS3-AS7).

The exact steady-state stick zone (eta = 0, both edges slipping the same way) is the contact of
the same punch at load P_K of (33) and at the *mean rotation* of the two states: the corrective
pressure of the Jaeger-Ciavarella superposition q_diff = mu (p1 + p2 - 2 p_K) must cancel the
slip gradient of p1 + p2 in the stick zone, which fixes its rotation there (AS7).  It is
computed here by Newton's method on the closed forms.
"""

from __future__ import annotations

import functools
import math

import numpy as np
import pytest

from asymslip import LoadCycle, slip_zone
from asymslip.calibration import calibrate
from asymslip.laws.calibrated import CalibratedLaw
from asymslip_gen.asymmetric_edges import (
    edge_moment_factor,
    edge_multiplier_balance,
    shear_edge_multiplier_asymmetric,
)
from asymslip_gen.corrective_slip import stick_boundary
from tests.calibration.helpers import CubicProfile, mesh, sampled_traces, stick_boundary_of_edge

PUNCH = CubicProfile(R=1.0, k=0.005, E_star=1.0)  # k R a = 0.06 at P = 100: p > 0 throughout
MU, LAM = 0.1, 0.2
PATHS = {"no moment": lambda P: 0.0, "moment growing with P": lambda P: 0.3 * (P - 100.0)}


class ExactEdges:
    """Both edges of the punch along a path, and their slopes by central differences."""

    def __init__(self, moment) -> None:
        self.moment = moment

    def contact(self, P: float) -> tuple[float, float]:
        return PUNCH.contact(P, self.moment(P))

    def position(self, P: float, side: str) -> float:
        m, h = self.contact(P)
        return m + h if side == "right" else -(m - h)

    def slope(self, P: float, side: str, step: float = 1e-3) -> float:
        return (self.position(P + step, side) - self.position(P - step, side)) / (2 * step)

    def width(self, P: float) -> float:
        return 2 * self.contact(P)[1]

    def multiplier(self, P: float, side: str) -> float:
        return PUNCH.multipliers(*self.contact(P))[0 if side == "right" else 1]

    def centre_moment_slope(self, P: float, step: float = 1e-3) -> float:
        """dM_c/dP = dM/dP - m dP/dP: the moment of the increments about the contact centre."""
        dM = (self.moment(P + step) - self.moment(P - step)) / (2 * step)
        return dM - self.contact(P)[0]


def exact_stick_edges(edges: ExactEdges, P1: float, P2: float) -> tuple[float, float]:
    """(right, left) edges of the contact at P_K and the mean rotation of the two states."""
    state1, state2 = edges.contact(P1), edges.contact(P2)
    rotation = 0.5 * (PUNCH.rotation(*state1) + PUNCH.rotation(*state2))
    P_K = 0.5 * (P1 + P2) - LAM * (P2 - P1) / (2 * MU)  # (33)
    m, h = PUNCH.contact_at_rotation(P_K, rotation, state1)
    return m + h, -(m - h)


def asymptotic_stick_edge(
    edges: ExactEdges, P1: float, P2: float, side: str, use_21: bool = False
) -> float:
    """(17) at one edge with the exact a, L_I and L_II from AS3 (or from (21) if asked).

    Both edges slip forward in the global sense (lam > mu): seen from the left edge that is
    backward slip, which is forward slip at (-lam_left, -eta) = (lam, 0).
    """
    multipliers = [edges.multiplier(P, side) for P in (P1, P2)]
    if use_21:
        shear = [LAM * L for L in multipliers]
    else:
        shear = [
            shear_edge_multiplier_asymmetric(LAM, 0.0, edges.width(P), edges.slope(P, side))
            for P in (P1, P2)
        ]
    a1, a2 = edges.position(P1, side), edges.position(P2, side)
    return float(stick_boundary(MU, a1, a2, *multipliers, *shear))


# --- the generated kernels against the closed forms ----------------------------------------
@pytest.mark.parametrize("path", list(PATHS))
def test_the_two_edges_multipliers_balance_whatever_the_moment_does(path):
    """(AS6): (pi sqrt w/4)(L_I,r a_r' + L_I,l a_l') = 1."""
    edges = ExactEdges(PATHS[path])
    for P in (80.0, 100.0, 130.0):
        balance = edge_multiplier_balance(
            edges.width(P),
            edges.multiplier(P, "right"),
            edges.slope(P, "right"),
            edges.multiplier(P, "left"),
            edges.slope(P, "left"),
        )
        assert abs(balance - 1) < 1e-7


@pytest.mark.parametrize("path", list(PATHS))
def test_the_moment_factor_is_one_plus_4_over_w_times_the_centre_moment_slope(path):
    """(AS4) from the closed-form L_I and a'(P), against dM_c/dP from the path itself."""
    edges = ExactEdges(PATHS[path])
    for P in (80.0, 100.0, 130.0):
        w, moment = edges.width(P), edges.centre_moment_slope(P)
        for side, sign in (("right", 1.0), ("left", -1.0)):  # mirrored: M_c changes sign
            factor = edge_moment_factor(w, edges.multiplier(P, side), edges.slope(P, side))
            assert abs(factor - (1 + sign * 4 * moment / w)) < 1e-7
            assert abs(factor - 1) > 0.03  # the rotation changes: (21) does not hold


def test_the_shear_multiplier_is_the_transcribed_formula():
    w, slope = np.array([20.0, 25.0]), np.array([0.05, 0.07])
    expected = 2 * (LAM + math.pi * 0.01 * w / 8) / (math.pi * np.sqrt(w) * slope)
    np.testing.assert_allclose(
        shear_edge_multiplier_asymmetric(LAM, 0.01, w, slope), expected, rtol=1e-15
    )


# --- the stick boundary against the exact solution ------------------------------------------
@pytest.mark.parametrize("path", list(PATHS))
def test_each_edge_s_own_L_II_gives_the_exact_stick_zone_to_second_order(path):
    """(17) with AS3 differs from the exact stick edge by O(dP^2): below (dP/P1)/4 of the slip
    zone (itself O(dP)) at every step, and a quarter per halving where the dP^2 term is not
    nearly zero (it nearly cancels at the right edge of the moment path)."""
    edges = ExactEdges(PATHS[path])
    for side in ("right", "left"):
        gaps = []
        for dP in (8.0, 4.0, 2.0):
            exact = exact_stick_edges(edges, 100.0, 100.0 + dP)[0 if side == "right" else 1]
            gaps.append(asymptotic_stick_edge(edges, 100.0, 100.0 + dP, side) - exact)
            width = edges.position(100.0, side) - exact
            assert abs(gaps[-1]) <= 0.25 * (dP / 100.0) * width, (side, dP)
        if path == "no moment":
            for coarse, fine in zip(gaps, gaps[1:], strict=False):
                assert 3.5 < coarse / fine < 4.5, (side, gaps)


@pytest.mark.parametrize("path", list(PATHS))
def test_21_misses_the_exact_stick_zone_at_first_order_on_a_rotating_contact(path):
    """(17) with (21) differs by O(dP): a half per halving, 5-50 % of the slip zone."""
    edges = ExactEdges(PATHS[path])
    for side in ("right", "left"):
        gaps, widths = [], []
        for dP in (8.0, 4.0, 2.0):
            exact = exact_stick_edges(edges, 100.0, 100.0 + dP)[0 if side == "right" else 1]
            gaps.append(asymptotic_stick_edge(edges, 100.0, 100.0 + dP, side, use_21=True) - exact)
            widths.append(edges.position(100.0, side) - exact)
        for coarse, fine in zip(gaps, gaps[1:], strict=False):
            assert 1.8 < coarse / fine < 2.2, (side, gaps)
        assert all(0.05 < abs(g) / w < 0.5 for g, w in zip(gaps, widths, strict=True)), side


# --- calibrated from traces ------------------------------------------------------------------
LOADS = (80.0, 90.0, 100.0, 105.0, 110.0, 120.0)


@functools.cache
def _calibrated(
    path: str, nodes: int = 200, noise: float = 0.0
) -> tuple[CalibratedLaw, ExactEdges]:
    edges = ExactEdges(PATHS[path])
    contacts = {P: edges.contact(P) for P in LOADS}
    rng = np.random.default_rng(nodes)
    x = mesh("uniform", contacts[100.0][1], nodes, rng) + contacts[100.0][0]

    def pressure(x, P):
        return PUNCH.pressure_of(*contacts[P], x)

    return CalibratedLaw(calibrate(sampled_traces(pressure, LOADS, x, noise, rng))), edges


@pytest.mark.parametrize("path", list(PATHS))
def test_calibrated_edges_and_multipliers_match_the_closed_form(path):
    law, edges = _calibrated(path)
    fits = law.calibration
    for side in ("right", "left"):
        for fit in fits.fits(side):
            m, h = edges.contact(fit.P)
            assert abs(fit.x_edge - (m + h if side == "right" else m - h)) <= fit.a_error
            assert abs(fit.L_I - edges.multiplier(fit.P, side)) <= fit.L_I_error


@pytest.mark.parametrize("path", list(PATHS))
def test_calibration_sees_the_moment_factor_and_balances_the_edges(path):
    law, edges = _calibrated(path)
    P = np.array([90.0, 110.0])
    for side in ("right", "left"):
        edge = law.for_edge(side)
        error = law.error_of(lambda fitted, side=side: fitted.for_edge(side).moment_factor(P))
        exact = [
            edge_moment_factor(
                edges.width(load), edges.multiplier(load, side), edges.slope(load, side)
            )
            for load in P
        ]
        assert np.all(np.abs(edge.moment_factor(P) - exact) <= error)
        assert np.all(np.abs(edge.moment_factor(P) - 1) > 3 * error)  # asymmetry resolved
    balance_error = law.error_of(lambda fitted: fitted.multiplier_balance(P))
    assert np.all(np.abs(law.multiplier_balance(P) - 1) <= balance_error)


@pytest.mark.parametrize(
    ("path", "nodes", "noise"),
    [
        ("no moment", 200, 0.0),
        ("moment growing with P", 200, 0.0),
        ("moment growing with P", 100, 0.005),
    ],
)
def test_two_different_slip_zones_agree_with_the_exact_ones_within_the_stated_errors(
    path, nodes, noise
):
    """b of each edge from the calibration, against the exact stick zone (Jaeger-Ciavarella).

    Allowed: the calibration's propagated error plus the method's own second-order gap
    (the asymptotic b from the exact a, L_I and AS3, minus the exact b).
    """
    law, edges = _calibrated(path, nodes, noise)
    P1, P2 = 100.0, 105.0
    exact = dict(zip(("right", "left"), exact_stick_edges(edges, P1, P2), strict=True))
    origin = law.origin
    b = {}
    for side in ("right", "left"):

        def own(fitted, side=side):
            return stick_boundary_of_edge(fitted.for_edge(side), P1, P2, LAM, 0.0, MU, side)

        b[side] = own(law)
        exact_b = exact[side] - origin if side == "right" else origin + exact[side]
        method_gap = abs(asymptotic_stick_edge(edges, P1, P2, side) - exact[side])
        assert abs(b[side] - exact_b) <= law.error_of(own) + method_gap, side
    widths = {side: law.for_edge(side).half_width(P1) - b[side] for side in b}
    assert abs(widths["left"] / widths["right"] - 1) > 0.3  # two different slip zones


def test_the_array_core_gives_each_calibrated_edge_its_own_slip_zone():
    law, edges = _calibrated("moment growing with P")
    P1, P2 = 100.0, 105.0
    result = slip_zone(law, LoadCycle(P1, 0.0, P2, LAM * (P2 - P1)), MU, edge="both")
    for side, b in (("right", result.b), ("left", result.left.b)):
        own = stick_boundary_of_edge(law.for_edge(side), P1, P2, LAM, 0.0, MU, side)
        assert abs(b - own) < 1e-9 * abs(own), side
