"""Hypothesis strategies for valid inputs of the Section 2 formulas."""

from __future__ import annotations

from hypothesis import strategies as st

finite = {"allow_nan": False, "allow_infinity": False, "allow_subnormal": False}

mu = st.floats(0.05, 1.5, **finite)
lam = st.floats(-3.0, 3.0, **finite)
eta = st.floats(-0.05, 0.05, **finite)  # [1/length]; pi eta a/4 of order 0.1 for a ~ 1-10
half_width = st.floats(0.1, 10.0, **finite)
relative_growth = st.floats(1e-8, 0.1, **finite)
multiplier = st.floats(0.1, 10.0, **finite)
multiplier_ratio = st.floats(0.9, 1.1, **finite)
modulus = st.floats(0.1, 1e3, **finite)


@st.composite
def proportional_cycle(draw: st.DrawFn) -> dict[str, float]:
    """(mu, lam, eta, a1, a2, da, L_I1, L_I2) of a small-growth proportional cycle."""
    a1 = draw(half_width)
    da = a1 * draw(relative_growth)
    L_I1 = draw(multiplier)
    return {
        "mu": draw(mu),
        "lam": draw(lam),
        "eta": draw(eta),
        "a1": a1,
        "da": da,
        "a2": a1 + da,
        "L_I1": L_I1,
        "L_I2": L_I1 * draw(multiplier_ratio),
    }


def real(low: float, high: float) -> st.SearchStrategy[float]:
    """Finite floats in [low, high] without subnormals (they carry too few digits to compare)."""
    return st.floats(low, high, **finite)
