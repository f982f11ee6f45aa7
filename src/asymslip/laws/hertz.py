"""The Hertzian (cylinder) contact law (29), from the generated kernels."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike

from asymslip_gen import programs, scalar_programs
from asymslip_gen import scalar as scalar_kernels
from asymslip_gen.hertz import (
    hertz_half_width,
    hertz_half_width_growth,
    hertz_load,
    hertz_load_slope,
    hertz_normal_edge_multiplier,
    hertz_normal_edge_multiplier_slope,
    hertz_profile,
)
from asymslip_gen.tractions import hertz_pressure

from ..errors import as_float_array
from .base import BoolArray, ContactLaw, LawState, Number
from .parameters import positive_parameter


@dataclass(frozen=True)
class _HertzParameters:
    """The checked parameters of :class:`HertzLaw`: set once, by the generated constructor."""

    R: float
    E_star: float


@dataclass(frozen=True, init=False)
class HertzLaw(_HertzParameters, ContactLaw):
    """Cylinder of radius R on a half-plane, plane-strain modulus E*: a^2 = 4 P R / (pi E*).

    Parameters
    ----------
    R
        Radius of the cylinder, R > 0 [length].
    E_star
        Plane-strain contact modulus E* > 0 [force/length^2].

    Raises
    ------
    InputError
        A parameter that is missing (None), not one finite number (an array, text, a boolean)
        or not > 0, naming it (:mod:`asymslip.laws.parameters`).

    Examples
    --------
    >>> law = HertzLaw(R=1.0, E_star=1.0)
    >>> round(float(law.half_width(100.0)), 6)
    11.283792
    """

    name = "hertz"
    floats_only = True  # one cycle: the math kernels throughout

    def __init__(self, R: float, E_star: float) -> None:
        # Checked and made Python floats before the frozen record is built: nothing set twice.
        super().__init__(positive_parameter("R", R), positive_parameter("E_star", E_star))

    def load(self, a: ArrayLike) -> Number:
        return hertz_load(a, self.R, self.E_star)

    def load_slope(self, a: ArrayLike) -> Number:
        return hertz_load_slope(a, self.R, self.E_star)

    def half_width(self, P: ArrayLike) -> Number:
        return hertz_half_width(P, self.R, self.E_star)

    def half_width_where_possible(self, P: ArrayLike) -> tuple[Number, BoolArray]:
        with np.errstate(over="ignore"):  # a load beyond the double range: marked, not warned
            a = hertz_half_width(P, self.R, self.E_star)
        return a, np.asarray(np.isfinite(a))

    def half_width_near(self, P: Number, P_ref: ArrayLike, a_ref: ArrayLike) -> Number:
        if type(P) is float:  # one cycle: the math kernel (the same CSE'd body)
            return scalar_kernels.hertz_half_width(P, self.R, self.E_star)
        return hertz_half_width(P, self.R, self.E_star)

    def half_width_growth(self, P1: ArrayLike, dP: ArrayLike) -> Number:
        return hertz_half_width_growth(P1, dP, self.R, self.E_star)

    def cycle_state(self, P1: Number, dP: Number) -> LawState:
        """Closed forms (29)-(31): no root solve, a2 - a1 without cancellation.

        One call of the generated program ``hertz_cycle_state`` (``derivations/
        edge_programs.py``): on Python floats for one cycle (the ``math`` kernels), on NumPy
        arrays for many.
        """
        R, E_star = self.R, self.E_star
        if type(P1) is float and type(dP) is float:  # inside the core's errstate
            P2, a1, a2, da, L_I1, L_I2, slope1, slope2, L_I_slope1, L_I_slope2 = (
                scalar_programs.hertz_cycle_state(P1, dP, R, E_star)
            )
            return LawState(
                P1, P2, a1, a2, da, L_I1, L_I2, slope1, slope2, L_I_slope1, L_I_slope2, True, True
            )
        return self._cycle_state_on_arrays(P1, dP)

    def _cycle_state_on_arrays(self, P1: ArrayLike, dP: ArrayLike) -> LawState:
        """The closed forms on NumPy arrays (many cycles, or one the float path left)."""
        loads, changes = np.broadcast_arrays(
            np.asarray(P1, dtype=np.float64), np.asarray(dP, dtype=np.float64)
        )
        with np.errstate(over="ignore"):  # overflow is marked by the rules, not warned
            P2, a1, a2, da, L_I1, L_I2, slope1, slope2, L_I_slope1, L_I_slope2 = (
                programs.hertz_cycle_state(loads, changes, self.R, self.E_star)
            )
        # Every load P > 0 has a half-width; an overflow is caught by the finiteness rule.
        found = np.ones(np.shape(loads), dtype=bool)
        return LawState(
            loads, P2, a1, a2, da, L_I1, L_I2, slope1, slope2, L_I_slope1, L_I_slope2, found, found
        )

    def normal_multiplier_at(self, a: ArrayLike, load_slope: ArrayLike) -> Number:
        return hertz_normal_edge_multiplier(self.load(a), self.R, self.E_star)

    def normal_multiplier_slope_at(self, a: ArrayLike, load_slope: ArrayLike) -> Number:
        return hertz_normal_edge_multiplier_slope(self.load(a), self.R, self.E_star)

    def normal_multiplier(self, P: ArrayLike) -> Number:
        return hertz_normal_edge_multiplier(P, self.R, self.E_star)

    def pressure(self, x: ArrayLike, P: ArrayLike) -> Number:
        """Hertz pressure (48), zero outside the contact."""
        return hertz_pressure(x, P, self.R, self.E_star)

    def normal_multiplier_slope(self, P: ArrayLike) -> Number:
        return hertz_normal_edge_multiplier_slope(P, self.R, self.E_star)

    def profile(self, x: ArrayLike) -> Number:
        """Initial gap h(x) = x^2/(2R) between the cylinder and the half-plane (29)."""
        return hertz_profile(as_float_array("x", x), self.R)
