"""Section 2 of the paper, transcribed by hand (equation numbers as printed)."""

from __future__ import annotations

import numpy as np

pi = np.pi


def eq14(beta: float, x: float) -> float:
    """int_beta^1 sqrt((1-t)/(t-beta)) dt/(t-x), for beta < 1."""
    if beta < x < 1:
        return -pi
    return -pi * (1 - np.sqrt((x - 1) / (x - beta)))


def eq15(x, b, a1, mu, L_I1, L_I2, L_II1, L_II2, E_star):
    """B^{1->2}(a2 - x) for b < x < a2, with H(x - a1) written out."""
    heaviside = np.where(x > a1, 1.0, 0.0)
    beyond_a1 = np.sqrt(np.where(x > a1, x - a1, 0.0))
    return -2 * np.sqrt(x - b) / E_star * (mu * (L_I1 + L_I2) + L_II1 - L_II2) + (
        2 * (mu * L_I1 + L_II1) / E_star * heaviside * beyond_a1
    )


def eq16_integral(lower: float, top: float) -> float:
    """int_lower^top sqrt((top - t)/(t - lower)) dt, as the consistency condition uses it."""
    return pi * (top - lower) / 2


def eq17(mu, a1, a2, L_I1, L_I2, L_II1, L_II2):
    return ((mu * L_I2 - L_II2) * a2 + (mu * L_I1 + L_II1) * a1) / (
        (mu * L_I2 - L_II2) + (mu * L_I1 + L_II1)
    )


def eq19(a, dP_da):
    return 1 / pi * np.sqrt(2 / a) * dP_da


def eq20(a, dQ_da, dsigma_da):
    return 1 / pi * np.sqrt(2 / a) * dQ_da + 1 / 4 * np.sqrt(2 * a) * dsigma_da


def eq21(lam, eta, a, L_I):
    return (lam + pi * eta * a / 4) * L_I


def eq22(mu, lam, eta, a1, a2, L_I1, L_I2):
    bracket2 = 1 - lam / mu - pi * a2 / 4 * eta / mu
    bracket1 = 1 + lam / mu + pi * a1 / 4 * eta / mu
    return (bracket2 * L_I2 * a2 + bracket1 * L_I1 * a1) / (bracket2 * L_I2 + bracket1 * L_I1)


def eq24(dP, da_dP, a1):
    return dP * da_dP / a1


def eq25_corrected(mu, lam, eta, a1, a2, L_I1, L_I2, *, da=None):
    """(b - a1)/a1 = ((a2 - a1)/a1) (1 + C/A)^-1 -- the erratum-corrected identity.

    ``da`` may be given to avoid forming a2 - a1.
    """
    A = (1 - lam / mu - pi * a2 / 4 * eta / mu) * L_I2
    C = (1 + lam / mu + pi * a1 / 4 * eta / mu) * L_I1
    growth = (a2 - a1) if da is None else da
    return growth / a1 / (1 + C / A)


def eq26(dP, dL_I_dP, L_I1):
    return dP * dL_I_dP / L_I1


def eq27(mu, lam, eta, a1, dP, da_dP):
    return dP * da_dP / a1 * abs(1 - lam / mu - pi * eta * a1 / (4 * mu))


def eq28(mu, lam, eta, a1, dP, da_dP):
    """b / a1 to first order."""
    return 1 - dP * da_dP / (2 * a1) * (lam / mu + pi * a1 / 4 * eta / mu - 1)
