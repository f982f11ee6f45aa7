"""The drawn cycles of the language comparison are the paper's steady partial-slip cycles."""

from __future__ import annotations

import numpy as np

from .domains import Draw


def test_drawn_stick_boundary_solves_the_consistency_condition_16() -> None:
    # (16) with (14)'s integral, int_b^a sqrt((a - t)/(t - b)) dt = pi (a - b)/2:
    # (mu L_I1 + L_II1)(a1 - b) + (mu L_I2 - L_II2)(a2 - b) = 0 at the drawn b.
    p = Draw(2000, 13).cycle()
    first = (p["mu"] * p["L_I1"] + p["L_II1"]) * (p["a1"] - p["b"])
    second = (p["mu"] * p["L_I2"] - p["L_II2"]) * (p["a2"] - p["b"])
    # The residual is linear in b with slope -(A + C): the drawn b's error is residual/(A + C),
    # which must be rounding of b (b ~ a1, and a1 - b may be 1e-9 a1: no relative test there).
    slope = p["mu"] * (p["L_I1"] + p["L_I2"]) + p["L_II1"] - p["L_II2"]
    error = np.abs(first + second) / np.abs(slope)
    assert np.max(error / p["a2"]) < 64 * np.finfo(float).eps


def test_drawn_forward_slip_zone_lies_between_a1_and_the_far_edge() -> None:
    # lam > mu: the slip zone b < x < a2 starts inside a1 and is narrower than the contact.
    p = Draw(2000, 13).cycle()
    assert np.all(p["b"] < p["a1"])
    assert np.all(p["b"] > -p["a1"])
