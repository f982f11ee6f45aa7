"""Flat punch with rounded corners: the law P(a), its inverse, multiplier and pressure.

The formulas are generated from ``derivations/contact_law_flat_rounded.py`` (beyond the paper);
a(P) has no closed form and is found by Newton's method (:mod:`asymslip.laws.roots`).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike

from asymslip_gen.flat_rounded import (
    flat_rounded_chord,
    flat_rounded_corner_angle,
    flat_rounded_load,
    flat_rounded_load_at_angle,
    flat_rounded_load_slope,
    flat_rounded_load_slope_at_angle,
    flat_rounded_normal_edge_multiplier_at_angle,
    flat_rounded_normal_edge_multiplier_slope_at_angle,
    flat_rounded_pressure,
    flat_rounded_profile,
)
from asymslip_gen.hertz import hertz_half_width

from ..errors import as_float_array, positive, require
from .base import BoolArray, ContactLaw, FloatArray, Number
from .parameters import law_parameter, positive_parameter
from .roots import (
    QUADRATURE_LIMIT,
    gauss_integral,
    invert_increasing_where_possible,
    newton_from,
)


@dataclass(frozen=True)
class _FlatRoundedParameters:
    """The checked parameters of :class:`FlatRoundedLaw`: set once, by the generated
    constructor."""

    c: float
    R: float
    E_star: float


@dataclass(frozen=True, init=False)
class FlatRoundedLaw(_FlatRoundedParameters, ContactLaw):
    """Flat face of half-width c with corners of radius R, on a half-plane of modulus E*.

    P(a) = E* (a^2 psi - c sqrt(a^2 - c^2)) / (2R), psi = arccos(c/a): any load P > 0 gives
    a > c, and c = 0 is the Hertz cylinder (29).

    Accuracy: a is a double, so for a contact barely wider than the flat the relative error of
    L_I grows like 1e-16 / (1 - c/a): measured 5e-13 at 1 - c/a = 1e-4 and 7e-12 at 1e-5.

    Parameters
    ----------
    c
        Half-width of the flat face, c >= 0 [length].
    R
        Radius of the rounded corners, R > 0 [length].
    E_star
        Plane-strain contact modulus E* > 0 [force/length^2].

    Raises
    ------
    InputError
        A parameter that is missing (None), not one finite number (an array, text, a boolean)
        or out of its range, naming it (:mod:`asymslip.laws.parameters`).

    Examples
    --------
    >>> law = FlatRoundedLaw(c=1.0, R=10.0, E_star=1.0)
    >>> a = law.half_width(0.05)
    >>> round(float(law.load(a)), 12)
    0.05
    """

    name = "flat-rounded"

    def __init__(self, c: float, R: float, E_star: float) -> None:
        # Checked and made Python floats before the frozen record is built: nothing set twice.
        flat = law_parameter("c", c)
        require(flat >= 0, "c", "must be >= 0 (the half-width of the flat face)", flat)
        super().__init__(flat, positive_parameter("R", R), positive_parameter("E_star", E_star))

    def load(self, a: ArrayLike) -> Number:
        """P(a); zero for a <= c."""
        return flat_rounded_load(a, self.c, self.R, self.E_star)

    def load_slope(self, a: ArrayLike) -> Number:
        """dP/da = E* a arccos(c/a) / R."""
        return flat_rounded_load_slope(a, self.c, self.R, self.E_star)

    def load_and_slope(self, a: ArrayLike) -> tuple[Number, Number]:
        """P(a) and dP/da from one chord and one corner angle (a Newton step needs both)."""
        chord = flat_rounded_chord(a, self.c)
        angle = flat_rounded_corner_angle(chord, self.c)
        return (
            flat_rounded_load_at_angle(a, self.c, self.R, self.E_star, angle, chord),
            flat_rounded_load_slope_at_angle(a, self.c, self.R, self.E_star, angle),
        )

    def half_width_where_possible(self, P: ArrayLike) -> tuple[FloatArray, BoolArray]:
        """a(P) by Newton on the convex P(a) from above, to a few units in the last place.

        The root is bracketed by max(c, a_H) <= a <= c + a_H with a_H = sqrt(4 P R/(pi E*)),
        the Hertz half-width: the rounded flat carries at most the cylinder's load at the same
        half-width, and at least the load of the cylinder of half-width a - c.  P(a) is convex,
        so Newton from the upper end converges monotonically; the bracketing inverse takes
        over for the rare element that does not settle.  a - c grows like P^(2/3): below
        P ~ 1e-23 E* c^2/R it is lost in the rounding of a, and such loads are not found.
        """
        load = np.asarray(P, dtype=np.float64)
        with np.errstate(over="ignore", invalid="ignore"):
            hertz = hertz_half_width(load, self.R, self.E_star)
            # Two upper bounds: c + a_H, and the root of the law's expansion for a >> c,
            # P ~ pi E*/(4R) (a^2 - 4 a c/pi), whose neglected terms are positive; the smaller
            # one is within 30 % (within 1e-5 once a > 10 c), and Newton from above on the
            # convex P(a) converges monotonically.
            lever = 2 * self.c / np.pi
            upper = np.minimum(self.c + hertz, lever + np.sqrt(hertz * hertz + lever * lever))
            a, converged = newton_from(
                self.load, self.load_slope, load, upper, both=self.load_and_slope
            )
        if not np.all(converged):
            a = np.array(a, dtype=float)
            retry = ~np.asarray(converged) & np.isfinite(hertz) & (load > 0)
            if retry.any():
                a[retry], _ = invert_increasing_where_possible(
                    self.load,
                    np.broadcast_to(load, a.shape)[retry],
                    self.load_slope,
                    lower=np.maximum(self.c, np.broadcast_to(hertz, a.shape)[retry]),
                    upper=self.c + np.broadcast_to(hertz, a.shape)[retry],
                )
            a = a[()] if a.ndim == 0 else a
        # a - c must be resolved: the nearest doubles to c can carry loads far above a tiny P.
        with np.errstate(invalid="ignore"):
            found = np.isfinite(a) & (a > self.c) & (np.abs(self.load(a) - load) <= 0.5 * load)
        return np.where(found, a, np.nan)[()], found[()]

    def half_width(self, P: ArrayLike) -> FloatArray:
        """a(P), refusing a load too small to separate a from c in double precision."""
        load = positive("P", P)
        a, found = self.half_width_where_possible(load)
        require(
            found,
            "P",
            "is too small: a(P) equals the flat half-width c in double "
            "precision (P R/(E* c^2) below about 1e-23)",
            load,
        )
        return a

    def load_difference(self, a: ArrayLike, d: ArrayLike) -> FloatArray:
        """P(a + d) - P(a) without cancellation, also for a contact barely wider than the flat.

        P'(a) = E* a arccos(c/a)/R has a branch point at a = c, which may lie much closer to
        a than d; in u = sqrt(a - c) the integrand 2u P'(c + u^2) is analytic there (its
        nearest singularities are at u^2 = -c and u^2 = -2c, at least sqrt(a) from [u1, u2]),
        so Gauss-Legendre in u is exact to rounding for du <= sqrt(a)/4 with the rule chosen
        by du/sqrt(a); u2 - u1 = d/(u1 + u2), without cancellation.  Beyond that (a large
        growth from a contact barely wider than the flat: du/sqrt(a) can reach sqrt(d/a)) d is
        no longer small against a - c and the plain difference is accurate.
        """
        a, d = np.broadcast_arrays(np.asarray(a, dtype=np.float64), np.asarray(d, dtype=np.float64))
        with np.errstate(invalid="ignore"):  # a <= c or d < 0: not near, the plain difference
            u1 = np.sqrt(a - self.c)
            u2 = np.sqrt(a + d - self.c)
            du = d / (u1 + u2)
            ratio = du / np.sqrt(a)
            near = ratio <= QUADRATURE_LIMIT
        out = np.empty(a.shape)
        if near.any():
            out[near] = gauss_integral(
                lambda u: 2 * u * self.load_slope(self.c + u * u), u1[near], du[near], ratio[near]
            )
        if (~near).any():
            out[~near] = self.load(a[~near] + d[~near]) - self.load(a[~near])
        return out[()] if out.ndim == 0 else out

    def half_width_growth(self, P1: ArrayLike, dP: ArrayLike) -> Number:
        """a(P1 + dP) - a(P1) with full relative precision for any dP/P1."""
        start = positive("P1", P1)
        change = as_float_array("dP", dP)
        require(change >= 0, "dP", "must be >= 0", change)
        return self.cycle_state(start, change).da

    def quantities_at(self, a: FloatArray) -> tuple[Number, Number, Number]:
        """dP/da, L_I and dL_I/dP from one chord and one corner angle."""
        chord = flat_rounded_chord(a, self.c)
        parameters = (a, self.c, self.R, self.E_star, flat_rounded_corner_angle(chord, self.c))
        return (
            flat_rounded_load_slope_at_angle(*parameters),
            flat_rounded_normal_edge_multiplier_at_angle(*parameters),
            flat_rounded_normal_edge_multiplier_slope_at_angle(*parameters, chord),
        )

    @property
    def stand_in_half_width(self) -> float:  # type: ignore[override]
        return self.c + 1.0

    def normal_multiplier_at(self, a: ArrayLike, load_slope: ArrayLike) -> Number:
        chord = flat_rounded_chord(a, self.c)
        return flat_rounded_normal_edge_multiplier_at_angle(
            a, self.c, self.R, self.E_star, flat_rounded_corner_angle(chord, self.c)
        )

    def normal_multiplier_slope_at(self, a: ArrayLike, load_slope: ArrayLike) -> Number:
        chord = flat_rounded_chord(a, self.c)
        return flat_rounded_normal_edge_multiplier_slope_at_angle(
            a, self.c, self.R, self.E_star, flat_rounded_corner_angle(chord, self.c), chord
        )

    def profile(self, x: ArrayLike) -> Number:
        """Initial gap h(x) = Max(0, |x| - c)^2/(2R): flat over |x| < c, rounded beyond."""
        return flat_rounded_profile(as_float_array("x", x), self.c, self.R)

    def pressure(self, x: ArrayLike, P: ArrayLike) -> Number:
        """Contact pressure p(x) at load P; zero for |x| >= a(P)."""
        position = as_float_array("x", x)
        return flat_rounded_pressure(position, self.half_width(P), self.c, self.R, self.E_star)
