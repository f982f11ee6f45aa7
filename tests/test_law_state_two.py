"""State 2 of a cycle is the law's own a(P2), for every law and every load change (issue 17).

A cycle asks its law once for a1, a2 and a2 - a1 (:meth:`ContactLaw.cycle_state`).  The growth
a2 - a1 is computed without cancellation; a2 must still be the half-width that carries P2.  The
rounded flat after a large load growth broke that: the cancellation-free difference integrated
P' by a Gauss rule outside its range (an interval far wider than the distance to the branch
point at a = c), leaving uninitialised memory in a2 (a2 = 29.156 where a(P2) = 26.133, and
valid cycles refused as "dP/da = 0").

Every expected value here is an mpmath root of the law's P(a) = P, written out below from the
laws' formulas (the README's table of laws), at 30 digits; for the table law, the fitted cubic
in log a against log P evaluated in mpmath from its coefficients.
"""

from __future__ import annotations

import types

import mpmath as mp
import numpy as np
import pytest

from asymslip import FlatRoundedLaw, HertzLaw, LoadCycle, PowerLaw, TableLaw, slip_zone
from asymslip.laws.module_law import ModuleLaw
from asymslip.slip_zones import evaluate

mp.mp.dps = 30
EPS = 2.0**-52


def random_cycles(rng: np.random.Generator, count: int) -> tuple[np.ndarray, np.ndarray]:
    """Loads P1 over ten decades; half the cycles grow the load by 1e-12 to 1, half by a factor
    1 to 1e4."""
    P1 = 10 ** rng.uniform(-5, 5, count)
    small = rng.random(count) < 0.5
    ratio = np.where(small, 1 + 10 ** rng.uniform(-12, 0, count), 10 ** rng.uniform(0, 4, count))
    P2 = P1 * ratio
    keep = P2 > P1
    return P1[keep], P2[keep]


def within(value: float, exact: mp.mpf, ulps: float) -> bool:
    return abs(mp.mpf(value) - exact) <= ulps * np.spacing(abs(float(exact)))


# --- the laws, and their a(P) in mpmath -------------------------------------------------------
def flat_rounded_load(a: mp.mpf, c: float, R: float, E: float) -> mp.mpf:
    """P(a) = E* (a^2 psi - c sqrt(a^2 - c^2))/(2R), psi = arccos(c/a) (README)."""
    c = mp.mpf(c)
    return E * (a * a * mp.acos(c / a) - c * mp.sqrt(a * a - c * c)) / (2 * R)


def flat_rounded_root(P: float, c: float, R: float, E: float) -> mp.mpf:
    hertz = mp.sqrt(4 * mp.mpf(P) * R / (mp.pi * E))  # c <= a <= c + a_Hertz
    return mp.findroot(
        lambda a: flat_rounded_load(a, c, R, E) - mp.mpf(P),
        (mp.mpf(c) * (1 + mp.mpf(10) ** -25), mp.mpf(c) + hertz),
        solver="anderson",
    )


def check_state_two(
    law, P1: np.ndarray, P2: np.ndarray, root, *, flat: float = 0.0
) -> tuple[float, float]:
    """Every cycle's a2 within 8 units in the last place of the root of P(a) = P2, and a2 - a1
    within 4e-15 of the exact difference (plus, for a contact barely wider than a flat of
    half-width ``flat``, the conditioning of a1 as a double: two units in the last place of a1
    amplified by (a2 - a1)/(a1 - c)).  Returns the largest errors (ulps of a2, relative da)."""
    state = law.cycle_state(P1, P2 - P1)
    worst_a2 = worst_da = 0.0
    for i in range(len(P1)):
        A1, A2 = root(float(P1[i])), root(float(P2[i]))
        exact = A2 - A1
        a2, da = float(state.a2[i]), float(state.da[i])
        error_a2 = float(abs(mp.mpf(a2) - A2) / np.spacing(float(A2)))
        error_da = float(abs(mp.mpf(da) - exact))
        allowed = 4e-15 * exact + 2 * np.spacing(float(A1)) * min(1, exact / (A1 - flat))
        assert error_a2 <= 8, (P1[i], P2[i], a2, A2)
        assert error_da <= allowed, (P1[i], P2[i], da, exact)
        worst_a2, worst_da = max(worst_a2, error_a2), max(worst_da, float(error_da / exact))
    return worst_a2, worst_da


def test_hertz_a2_is_its_half_width_at_P2_for_any_load_change():
    rng = np.random.default_rng(11)
    R, E = 0.7, 3.1
    P1, P2 = random_cycles(rng, 300)
    check_state_two(HertzLaw(R, E), P1, P2, lambda P: mp.sqrt(4 * mp.mpf(P) * R / (mp.pi * E)))


@pytest.mark.parametrize("n", [1.0, 1.5, 3.0, 7.5])
def test_power_law_a2_is_its_half_width_at_P2_for_any_load_change(n):
    rng = np.random.default_rng(12)
    A, E = 0.3, 3.1
    K = mp.sqrt(mp.pi) * mp.gamma(mp.mpf(n + 1) / 2) / mp.gamma(mp.mpf(n) / 2)  # P = K E* A a^n
    P1, P2 = random_cycles(rng, 200)
    check_state_two(
        PowerLaw(A, n, E), P1, P2, lambda P: (mp.mpf(P) / (K * E * A)) ** (1 / mp.mpf(n))
    )


def test_rounded_flat_a2_is_its_half_width_at_P2_for_any_load_change_and_any_contact():
    """Random flats and corners; contacts from 1e-6 c to 10 c wider than the flat; load
    growth from 1e-12 to a factor 1e3."""
    rng = np.random.default_rng(13)
    worst = 0.0
    for _ in range(60):
        c, R, E = 10 ** rng.uniform(-3, 2), 10 ** rng.uniform(-3, 2), 10 ** rng.uniform(-1, 4)
        law = FlatRoundedLaw(c, R, E)
        a1 = c * (1 + 10 ** rng.uniform(-6, 1, 6))
        P1 = np.array([float(flat_rounded_load(mp.mpf(a), c, R, E)) for a in a1])
        ratio = np.where(
            rng.random(6) < 0.5, 1 + 10 ** rng.uniform(-12, 0, 6), 10 ** rng.uniform(0, 3, 6)
        )
        P2 = P1 * ratio
        keep = P2 > P1
        worst_a2, _ = check_state_two(
            law, P1[keep], P2[keep], lambda P, c=c, R=R, E=E: flat_rounded_root(P, c, R, E), flat=c
        )
        worst = max(worst, worst_a2)
    assert worst <= 8


def test_the_issue_s_rounded_flat_cycle_has_a2_equal_to_a_of_P2():
    """The cycle of issue 17: a2 was 29.156 where the law's own a(P2) is 26.133."""
    c, R, E = 20.81825223219882, 0.021005411292975198, 478.24222024718534
    law = FlatRoundedLaw(c, R, E)
    state = law.cycle_state(135273.6, 1302743.7 - 135273.6)
    exact = flat_rounded_root(1302743.7, c, R, E)
    assert within(float(state.a2), exact, 2)
    assert float(state.a2) == pytest.approx(26.133103502122665, rel=1e-15)
    assert within(float(state.da), exact - flat_rounded_root(135273.6, c, R, E), 4)


def test_a_valid_rounded_flat_cycle_once_refused_as_dP_da_zero_is_answered():
    """Of the same family (a contact 0.4 % wider than its flat, the load grown 160-fold): the
    garbage a2 had dP/da = 0 and the cycle was refused; its a2 is now the law's a(P2)."""
    c, R, E = 0.21612777813552073, 0.1978908365550703, 5.890923242594566
    P1, P2, Q2 = 0.0009553338111847162, 0.1552479890720037, 0.06175235468413299
    result = slip_zone(FlatRoundedLaw(c, R, E), LoadCycle(P1, 0.0, P2, Q2), 0.5)
    assert within(float(result.a2), flat_rounded_root(P2, c, R, E), 8)
    assert 0 < result.b <= result.a2


def test_none_of_30000_random_large_growths_of_the_rounded_flat_is_wrong_or_refused():
    """The issue's census: 300 random flats, a contact 1e-4 c to c wider than the flat, the
    load grown 3 to 1000-fold, mu = 0.5, |Q2| < 0.9 mu P2.  Before the fix 2,578 of the 30,000
    a2 were more than 4 units in the last place from the law's own a(P2) and 554 cycles were
    refused (357 as a non-finite half-width, 193 as dP/da = 0, 4 with b outside the contact);
    now every a2 is a(P2) (the law's bracketed root, an independent solve) and none is
    refused."""
    rng = np.random.default_rng(1)
    refused = wrong = 0
    for _ in range(300):
        c, R, E = 10 ** rng.uniform(-2, 2), 10 ** rng.uniform(-3, 1), 10 ** rng.uniform(0, 3)
        law = FlatRoundedLaw(c, R, E)
        count = 100
        P1 = law.load(c * (1 + 10 ** rng.uniform(-4, 0, count)))
        P2 = P1 * 10 ** rng.uniform(np.log10(3), 3, count)
        Q2 = 0.5 * P2 * rng.uniform(-0.9, 0.9, count)
        zeros = np.zeros(count)
        cycles = LoadCycle.unchecked(P1, zeros, P2, Q2, zeros, zeros)
        result = evaluate(law, cycles, np.full(count, 0.5))
        refused += int((~result.verdict.valid).sum())
        a2 = np.asarray(result.edges["right"].a2, dtype=float)
        own, _ = law.half_width_where_possible(P2)
        wrong += int(np.sum(np.abs(a2 - own) > 4 * np.spacing(own)))
    assert (refused, wrong) == (0, 0)


def test_a_module_law_a2_is_its_half_width_at_P2_for_any_load_change():
    """The generic path (Newton, the bracketing inverse, the cancellation-free correction) on a
    law known only by P(a) = E* a^2 + k a^3."""
    E, k = 2.0, 0.5
    module = types.ModuleType("cubic_law")
    module.__asymslip_law__ = {"name": "cubic", "params": ["E_star", "k"]}
    module.load = lambda a, E_star, k: E_star * a**2 + k * a**3
    module.load_slope = lambda a, E_star, k: 2 * E_star * a + 3 * k * a**2
    module.normal_edge_multiplier = (
        lambda a, E_star, k: np.sqrt(2 / a) / np.pi * (2 * E_star * a + 3 * k * a**2)
    )
    law = ModuleLaw(module, "cubic_law", E_star=E, k=k)
    rng = np.random.default_rng(14)
    P1, P2 = random_cycles(rng, 300)

    def root(P: float) -> mp.mpf:
        guess = min(mp.sqrt(mp.mpf(P) / E), mp.cbrt(mp.mpf(P) / k))
        return mp.findroot(lambda a: E * a**2 + k * a**3 - mp.mpf(P), guess)

    check_state_two(law, P1, P2, root)


def table_half_width(law: TableLaw, P: float) -> mp.mpf:
    """The table law's fitted curve in mpmath: a = exp(s(log P)), s the cubic of its piece."""
    curve = law._curve
    u = mp.log(mp.mpf(P))
    j = int(curve.piece(np.array([float(u)]))[0])
    t = u - mp.mpf(float(curve.base[j]))
    c0, c1, c2, c3 = (mp.mpf(float(c[j])) for c in (curve.c0, curve.c1, curve.c2, curve.c3))
    return mp.exp(c0 + t * (c1 + t * (c2 + t * c3)))


def test_a_table_law_a2_is_its_half_width_at_P2_for_any_load_change():
    """A table of the rounded flat (20 points); cycles inside, across and beyond it."""
    flat = FlatRoundedLaw(1.0, 10.0, 1.0)
    P = np.geomspace(0.01, 1.0, 20)
    law = TableLaw(P, flat.half_width(P))
    rng = np.random.default_rng(15)
    P1 = 10 ** rng.uniform(-2.5, 0.5, 300)
    P2 = P1 * np.where(
        rng.random(300) < 0.5, 1 + 10 ** rng.uniform(-12, 0, 300), 10 ** rng.uniform(0, 1.5, 300)
    )
    keep = (P2 > P1) & (np.searchsorted(P, P1) == np.searchsorted(P, P2 * (1 + 1e-12)))
    # within one piece the fit is one cubic: the mpmath evaluation uses the same piece
    check_state_two(law, P1[keep], P2[keep], lambda load: table_half_width(law, load))
    state = law.cycle_state(P1, P2 - P1)
    assert np.array_equal(state.a2, law.half_width(state.P2))  # its own a(P2), every cycle
