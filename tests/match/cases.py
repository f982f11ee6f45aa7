"""Prototypes the match tests share, and (17) transcribed by hand for independent numbers."""

from __future__ import annotations

import math

import numpy as np

from asymslip import FlatRoundedLaw, LoadCycle, PowerLaw

MU = 0.3

#: A blade-root-like rounded flat with bulk tension (a2/a1 = 1.015).
BLADE = FlatRoundedLaw(c=1.0, R=10.0, E_star=1.0)
BLADE_CYCLE = LoadCycle(0.5, 0.0, 0.52, 0.04, 0.0, 0.002)

#: A power-law punch h = A |x|^3 with tension.
POWER = PowerLaw(A=0.01, n=3.0, E_star=1.0)
POWER_CYCLE = LoadCycle(100.0, 0.0, 104.0, 1.6, 0.0, 0.05)


def width_17(mu: float, L_I1: float, L_I2: float, L_II1: float, L_II2: float, da: float) -> float:
    """a1 - b of (17) with a2 = a1 + da, forward slip, transcribed from the paper by hand:
    b = (A a2 + C a1)/(A + C), A = mu L_I2 - L_II2, C = mu L_I1 + L_II1."""
    A = mu * L_I2 - L_II2
    C = mu * L_I1 + L_II1
    return -A * da / (A + C)


def rounded_flat_at(c_over_a1: float, growth: float, lam_over_mu: float) -> tuple:
    """A rounded flat (R = 10, E* = 1) at P1 = 0.5 with c/a1 and a2/a1 = 1 + growth, no tension,
    lambda = lam_over_mu * MU, Q centred between the two friction limits."""
    probe = FlatRoundedLaw(c=1.0, R=10.0, E_star=1.0)
    # Scale the flat so that c/a1 is as asked at P1 = 0.5: a1(c) found by bisection on c.
    low, high = 1e-6, 50.0
    for _ in range(200):
        c = 0.5 * (low + high)
        probe = FlatRoundedLaw(c=c, R=10.0, E_star=1.0)
        if c / float(probe.half_width(0.5)) < c_over_a1:
            low = c
        else:
            high = c
    a1 = float(probe.half_width(0.5))
    P2 = float(probe.load(a1 * (1 + growth)))
    dQ = lam_over_mu * MU * (P2 - 0.5)
    Q1 = -dQ * 0.5 / (0.5 + P2)
    return probe, LoadCycle(0.5, Q1, P2, Q1 + dQ)


def relative(a: float, b: float) -> float:
    return abs(a - b) / abs(b)


def finite(*values: float) -> bool:
    return all(math.isfinite(value) for value in values) and bool(np.all(np.isfinite(values)))
