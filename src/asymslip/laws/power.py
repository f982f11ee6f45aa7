"""Power-law punch h = A |x|^n, n >= 1: law, closed-form inverse, multiplier and pressure.

The formulas are generated from ``derivations/contact_law_power.py`` (beyond the paper).
Everything is NumPy-only except the pressure for n other than 1 (wedge) and 2 (cylinder), which
needs the Gauss hypergeometric function from SciPy: install the ``special`` extra.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from functools import cached_property

import numpy as np
from numpy.typing import ArrayLike

from asymslip_gen.power_law import (
    power_law_half_width,
    power_law_half_width_growth,
    power_law_hypergeometric_argument,
    power_law_load,
    power_law_load_slope,
    power_law_normal_edge_multiplier,
    power_law_normal_edge_multiplier_slope,
    power_law_pressure,
    power_law_profile,
    wedge_pressure,
)

from ..errors import InputError, as_float_array, positive, require
from .base import BoolArray, ContactLaw, LawState, Number
from .parameters import law_parameter, positive_parameter

#: Above this n, Gamma((n + 1)/2) overflows a double; use log-Gamma instead.
_GAMMA_LIMIT = 300.0


def shape_factor(n: float) -> float:
    """K(n) = sqrt(pi) Gamma((n + 1)/2) / Gamma(n/2) of P = K E* A a^n.

    Derived (and checked against quadrature) in ``derivations/contact_law_power.py``; NumPy has
    no Gamma function, so the generated kernels take K as an argument.  K(1) = 1, K(2) = pi/2.
    """
    if n < _GAMMA_LIMIT:
        return math.sqrt(math.pi) * math.gamma((n + 1) / 2) / math.gamma(n / 2)
    return math.sqrt(math.pi) * math.exp(math.lgamma((n + 1) / 2) - math.lgamma(n / 2))


def _hyp2f1() -> Callable[..., Number]:
    """SciPy's hyp2f1, imported only when a pressure needs it."""
    try:
        from scipy.special import hyp2f1
    except ImportError:
        raise InputError(
            "n",
            "the power-law pressure for n other than 1 or 2 needs SciPy's "
            "hyp2f1: install the 'special' extra (pip install "
            "'asymslip[special]')",
        ) from None
    function: Callable[..., Number] = hyp2f1  # SciPy's ufuncs carry no type information
    return function


@dataclass(frozen=True)
class _PowerParameters:
    """The checked parameters of :class:`PowerLaw`: set once, by the generated constructor."""

    A: float
    n: float
    E_star: float


@dataclass(frozen=True, init=False)
class PowerLaw(_PowerParameters, ContactLaw):
    """Punch of profile h = A |x|^n (n >= 1) on a half-plane: P = K(n) E* A a^n.

    n = 1 is the wedge (A = the tangent of its base angle), n = 2 with A = 1/(2R) the cylinder
    of (29).  n < 1 is refused: its slope h' is unbounded at the apex, outside the smooth
    incomplete contacts the method is built for.

    Parameters
    ----------
    A
        Profile coefficient, A > 0 [length^(1-n)].
    n
        Profile exponent, n >= 1.
    E_star
        Plane-strain contact modulus E* > 0 [force/length^2].

    Raises
    ------
    InputError
        A parameter that is missing (None), not one finite number (an array, text, a boolean)
        or out of its range, naming it (:mod:`asymslip.laws.parameters`).

    Examples
    --------
    >>> law = PowerLaw(A=0.5, n=2.0, E_star=1.0)   # the cylinder of radius 1
    >>> round(float(law.half_width(100.0)), 6)
    11.283792
    """

    name = "power"

    def __init__(self, A: float, n: float, E_star: float) -> None:
        # Checked and made Python floats before the frozen record is built: nothing set twice.
        coefficient = positive_parameter("A", A)
        exponent = law_parameter("n", n)
        require(exponent >= 1, "n", "must be >= 1 (n < 1 is not an incomplete contact)", exponent)
        try:
            shape_factor(exponent)
        except OverflowError:  # log Gamma(n/2) beyond the double range: n above about 5e305
            raise InputError(
                "n",
                "is too large: the factor K(n) of P = K E* A a^n overflows double precision",
                float(exponent),
            ) from None
        super().__init__(coefficient, exponent, positive_parameter("E_star", E_star))

    # Constants of the law, computed once per law (cached_property writes the instance's
    # __dict__ itself: the frozen record is not mutated).
    @cached_property
    def shape_factor(self) -> float:
        """K(n) of P = K E* A a^n."""
        return shape_factor(self.n)

    @cached_property
    def _parameters(self) -> tuple[np.float64, np.float64, np.float64, np.float64]:
        # NumPy scalars, not Python floats: a kernel's A**(3/2) of a huge A is then inf (which
        # the rules refuse, naming the load) instead of Python's OverflowError.
        return (
            np.float64(self.n),
            np.float64(self.A),
            np.float64(self.E_star),
            np.float64(self.shape_factor),
        )

    def load(self, a: ArrayLike) -> Number:
        return power_law_load(a, *self._parameters)

    def load_slope(self, a: ArrayLike) -> Number:
        return power_law_load_slope(a, *self._parameters)

    def half_width(self, P: ArrayLike) -> Number:
        """a(P) = (P/(K E* A))^(1/n), closed form."""
        return power_law_half_width(positive("P", P), *self._parameters)

    def half_width_growth(self, P1: ArrayLike, dP: ArrayLike) -> Number:
        """a1 expm1(log1p(dP/P1)/n): full relative precision however small dP/P1 is."""
        change = as_float_array("dP", dP)
        require(change >= 0, "dP", "must be >= 0", change)
        return power_law_half_width_growth(positive("P1", P1), change, *self._parameters)

    def half_width_where_possible(self, P: ArrayLike) -> tuple[Number, BoolArray]:
        with np.errstate(over="ignore", under="ignore"):
            a = power_law_half_width(P, *self._parameters)
        return a, np.isfinite(a) & (a > 0)

    def half_width_near(self, P: ArrayLike, P_ref: ArrayLike, a_ref: ArrayLike) -> Number:
        return power_law_half_width(P, *self._parameters)

    def cycle_state(self, P1: ArrayLike, dP: ArrayLike) -> LawState:
        """Closed forms: a = (P/(K E* A))^(1/n) at both states; a2 - a1 = a1 expm1(log1p(dP/P1)/n)
        (no cancellation)."""
        P1, dP = np.broadcast_arrays(
            np.asarray(P1, dtype=np.float64), np.asarray(dP, dtype=np.float64)
        )
        parameters = self._parameters
        with np.errstate(over="ignore", under="ignore", divide="ignore", invalid="ignore"):
            P2 = P1 + dP
            a1 = power_law_half_width(P1, *parameters)
            da = power_law_half_width_growth(P1, dP, *parameters)
            # a2 is the law's own a(P2), not a1 + da: the sum adds the rounding of both (up to
            # 9 units in the last place measured) where the closed form has at most 5.
            a2 = power_law_half_width(P2, *parameters)
            L_I1 = power_law_normal_edge_multiplier(P1, *parameters)
            L_I2 = power_law_normal_edge_multiplier(P2, *parameters)
            # Every load P > 0 has a half-width; overflow is caught by the finiteness rule.
            found1 = np.ones(np.shape(a1), dtype=bool)
            found2 = found1
            return LawState(
                P1=P1,
                P2=P2,
                a1=a1,
                a2=a2,
                da=da,
                L_I1=L_I1,
                L_I2=L_I2,
                load_slope1=power_law_load_slope(a1, *parameters),
                load_slope2=power_law_load_slope(a2, *parameters),
                L_I_slope1=power_law_normal_edge_multiplier_slope(P1, *parameters),
                L_I_slope2=power_law_normal_edge_multiplier_slope(P2, *parameters),
                found1=found1,
                found2=found2,
            )

    def normal_multiplier_at(self, a: ArrayLike, load_slope: ArrayLike) -> Number:
        return power_law_normal_edge_multiplier(self.load(a), *self._parameters)

    def normal_multiplier_slope_at(self, a: ArrayLike, load_slope: ArrayLike) -> Number:
        return power_law_normal_edge_multiplier_slope(self.load(a), *self._parameters)

    def normal_multiplier(self, P: ArrayLike) -> Number:
        return power_law_normal_edge_multiplier(positive("P", P), *self._parameters)

    def normal_multiplier_slope(self, P: ArrayLike) -> Number:
        """(1 - 3/(2n)) L_I / P: negative for n < 3/2."""
        return power_law_normal_edge_multiplier_slope(positive("P", P), *self._parameters)

    def profile(self, x: ArrayLike) -> Number:
        """Initial gap h(x) = A |x|^n between the punch and the half-plane."""
        return power_law_profile(as_float_array("x", x), self.n, self.A)

    def pressure(self, x: ArrayLike, P: ArrayLike) -> Number:
        """Contact pressure p(x) at load P; zero for |x| >= a(P).

        NumPy-only for n = 1 (the wedge, p = (E* A/pi) arccosh(a/|x|), +inf at the apex x = 0)
        and n = 2 (the cylinder); any other n needs SciPy (the ``special`` extra).

        Accuracy: SciPy's 2F1 loses digits as its argument 1 - x^2/a^2 approaches 1, i.e. right
        at the punch apex: for |x|/a below about 1e-7 the relative error measured against
        mpmath was 1e-2 (n = 1.25), 2e-6 (n = 1.75), 4e-11 (n = 2.5).  Away from the apex
        (|x| >= 1e-3 a) it is within 5e-16.  The edge asymptotics, which are what this package
        is about, use only the law P(a), never this pressure.
        """
        position = as_float_array("x", x)
        a = self.half_width(P)
        if self.n == 1.0:
            # The wedge's pressure is logarithmically infinite at the apex: +inf, not a warning
            # (a/|x| overflows for a subnormal x).
            with np.errstate(divide="ignore", over="ignore"):
                return wedge_pressure(position, a, self.A, self.E_star)
        if self.n == 2.0:
            factor = np.ones(np.broadcast_shapes(position.shape, np.shape(a)))  # 2F1(0, 1; 3/2; z)
        else:
            argument = power_law_hypergeometric_argument(position, a)
            factor = _hyp2f1()(1 - self.n / 2, 1.0, 1.5, argument)
        return power_law_pressure(position, a, *self._parameters, factor)
