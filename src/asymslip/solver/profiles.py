"""The initial gap h(x) between the bodies: a built-in law's profile, a formula or a table.

The solver's normal problem starts from the profile alone (the contact law a(P) is an output,
compared with the law's in the tests).  Three sources:

* :class:`LawProfile` -- a built-in law's own ``profile(x)`` (Hertz, rounded flat, power law),
  generated from the derivation that also gives the law's a(P) and pressure;
* :class:`ExpressionProfile` -- a formula in x typed by the user, read by the project's safe
  parser (:func:`asymslip.expressions.parse_formula`; needs SymPy, the ``derive`` extra) and
  turned into NumPy by ``sympy.lambdify``;
* :class:`TableProfile` -- points (x, h), joined by a monotone cubic (Fritsch-Carlson PCHIP, the
  default: C1, no overshoot between points, so a convex table stays free of spurious wiggles) or
  by straight lines (``interpolation="linear"``: exact for a faceted profile, but each kink puts
  a logarithmic peak into the pressure).  Beyond the table it continues along its end tangents;
  the contact itself must stay inside the table (the solver refuses otherwise).

Frame: x is the profile's own coordinate; its origin is the "contact centre" from which the
solver measures stick boundaries (right edge: b = x; left edge: b = -x), and the moment M is
taken about it.  A profile need not be symmetric.  The solver supports profiles whose contact
is one interval at every load of the path (convex profiles, and others that happen to touch
in one piece); it refuses a contact that splits.

Examples
--------
>>> import numpy as np
>>> from asymslip import HertzLaw
>>> from asymslip.solver.profiles import LawProfile, TableProfile
>>> LawProfile(HertzLaw(R=2, E_star=1)).heights(np.array([0.0, 1.0, -2.0]))  # x^2/(2R)
array([0.  , 0.25, 1.  ])
>>> table = TableProfile([-2.0, -1.0, 0.0, 1.0, 2.0], [1.0, 0.25, 0.0, 0.25, 1.0])
>>> table.heights(np.array([0.0, 1.0])).tolist(), table.defined_span()
([0.0, 0.25], (-2.0, 2.0))
"""

from __future__ import annotations

import abc
import csv
from collections.abc import Mapping
from pathlib import Path
from typing import Any, Literal

import numpy as np
from numpy.typing import ArrayLike

from ..errors import InputError, as_float_array
from .toeplitz import FloatArray

Interpolation = Literal["pchip", "linear"]


class Profile(abc.ABC):
    """The gap h(x) between the undeformed bodies, in the half-plane approximation."""

    #: Short description used in results.
    name: str = "profile"

    @abc.abstractmethod
    def heights(self, x: FloatArray) -> FloatArray:
        """h at the positions x (finite everywhere the solver asks)."""

    def defined_span(self) -> tuple[float, float] | None:
        """Where the profile is known (a table's x range); None when everywhere."""
        return None

    def length_scale(self, P: float, E_star: float) -> float | None:
        """A guess of the contact half-width at load P, for the first domain (None: unknown)."""
        return None

    def describe(self) -> dict[str, Any]:
        """What the results record about the profile."""
        return {"profile": self.name}

    def checked_heights(self, x: FloatArray) -> FloatArray:
        """:meth:`heights`, refusing values that are not finite (naming the position)."""
        with np.errstate(all="raise"):
            try:
                values = np.asarray(self.heights(x), dtype=np.float64)
            except (FloatingPointError, ZeroDivisionError, OverflowError, ValueError) as error:
                raise InputError(
                    "profile",
                    f"cannot be evaluated over the contact region "
                    f"[{x[0]:.6g}, {x[-1]:.6g}] ({error})",
                ) from None
        values = np.broadcast_to(values, x.shape)
        bad = ~np.isfinite(values)
        if bad.any():
            raise InputError(
                "profile",
                "must be finite over the contact region",
                f"h = {values[bad][0]!r} at x = {x[bad][0]:.6g}",
            )
        return np.array(values)


class LawProfile(Profile):
    """A built-in law's profile (``law.profile(x)``), e.g. x^2/(2R) for :class:`HertzLaw`."""

    def __init__(self, law: Any) -> None:
        if not callable(getattr(law, "profile", None)):
            raise InputError(
                "law",
                f"the {getattr(law, 'name', type(law).__name__)} law has no profile h(x): the "
                "solver needs one (the built-in hertz, flat-rounded and power laws have it; "
                "for a table or formula law give the profile as a formula or a table)",
            )
        self.law = law
        self.name = law.name

    def heights(self, x: FloatArray) -> FloatArray:
        return np.asarray(self.law.profile(x), dtype=np.float64)

    def length_scale(self, P: float, E_star: float) -> float | None:
        return float(self.law.half_width(P))

    def describe(self) -> dict[str, Any]:
        return {"profile": f"{self.name} law"}


class ExpressionProfile(Profile):
    """h(x) typed as a formula in x with named parameters, e.g. ``"x**2/(2*R)"``, R=1.

    Parameters
    ----------
    text
        The formula; the allowed names and functions are those of
        :mod:`asymslip.expressions` (``Abs``, ``sqrt``, ``exp``, ``cosh`` ..., ``pi``).
    params
        Values of the parameters the formula names.

    Raises
    ------
    InputError
        (``profile``) for anything the safe parser refuses, for a parameter without a value,
        or when SymPy is missing (the ``derive`` extra).
    """

    def __init__(self, text: str, params: Mapping[str, float] | None = None) -> None:
        from ..expressions import parse_formula, sympy_module

        sympy = sympy_module()
        params = dict(params or {})
        values = {name: float(as_float_array(name, value)) for name, value in params.items()}
        x = sympy.Symbol("x", real=True)
        expr, symbols = parse_formula(text, x, list(values), option="profile")
        expr = expr.subs({symbol: values[symbol.name] for symbol in symbols})
        if expr.free_symbols - {x}:
            names = sorted(map(str, expr.free_symbols - {x}))
            raise InputError("profile", "has names without values", names)
        self.text = text
        self.params = values
        self.name = "expression"
        self.expression = expr
        self._function = sympy.lambdify(x, expr, modules="numpy")
        # Constant curvature (a parabola): a moment cannot be resisted (see the solver).
        self.quadratic = bool(sympy.diff(expr, x, 3).equals(0))

    def heights(self, x: FloatArray) -> FloatArray:
        return np.broadcast_to(np.asarray(self._function(x), dtype=np.float64), x.shape)

    def describe(self) -> dict[str, Any]:
        return {"profile": f"h(x) = {self.text}", "profile_parameters": dict(self.params)}


def _pchip_slopes(x: FloatArray, y: FloatArray) -> FloatArray:
    """Fritsch-Carlson node slopes: weighted harmonic means of the secants, 0 at extrema."""
    h = np.diff(x)
    secant = np.diff(y) / h
    slopes = np.zeros_like(y)
    same = secant[:-1] * secant[1:] > 0
    w1 = 2 * h[1:] + h[:-1]
    w2 = h[1:] + 2 * h[:-1]
    with np.errstate(divide="ignore", invalid="ignore"):
        harmonic = (w1 + w2) / (w1 / secant[:-1] + w2 / secant[1:])
    slopes[1:-1] = np.where(same, harmonic, 0.0)
    # Ends: the one-sided three-point formula, limited so that it keeps the end secant's sign.
    for end, (h0, h1, s0, s1) in (
        (0, (h[0], h[1], secant[0], secant[1])),
        (-1, (h[-1], h[-2], secant[-1], secant[-2])),
    ):
        slope = ((2 * h0 + h1) * s0 - h0 * s1) / (h0 + h1)
        if np.sign(slope) != np.sign(s0):
            slope = 0.0
        elif np.sign(s0) != np.sign(s1) and abs(slope) > abs(3 * s0):
            slope = 3 * s0
        slopes[end] = slope
    return slopes


class TableProfile(Profile):
    """h(x) tabulated at points x_k, joined by a monotone cubic or by straight lines.

    Parameters
    ----------
    x, h
        The points: x strictly increasing, at least 3 of them, all finite.
    interpolation
        ``"pchip"`` (default): piecewise cubic Hermite with Fritsch-Carlson slopes (C1, no
        overshoot).  ``"linear"``: straight lines.

    Beyond the table the profile continues along its end tangents; the solver refuses a
    contact that reaches beyond the table.
    """

    def __init__(self, x: ArrayLike, h: ArrayLike, interpolation: Interpolation = "pchip") -> None:
        xs = as_float_array("x", x).ravel()
        hs = as_float_array("h", h).ravel()
        if xs.size != hs.size:
            raise InputError(
                "profile",
                "the x and h columns must have the same length",
                f"{xs.size} and {hs.size}",
            )
        if xs.size < 3:
            raise InputError("profile", "a table needs at least 3 points (x, h)", xs.size)
        if not np.all(np.diff(xs) > 0):
            raise InputError("profile", "the table's x must be strictly increasing")
        if interpolation not in ("pchip", "linear"):
            raise InputError("interpolation", "must be 'pchip' or 'linear'", interpolation)
        self.x, self.h, self.interpolation = xs, hs, interpolation
        self.name = f"table ({xs.size} points, {interpolation})"
        if interpolation == "pchip":
            self._slopes = _pchip_slopes(xs, hs)
        else:
            secant = np.diff(hs) / np.diff(xs)
            self._slopes = np.concatenate([secant[:1], secant[-1:]])

    @classmethod
    def from_csv(cls, path: str | Path, interpolation: Interpolation = "pchip") -> TableProfile:
        """Read a CSV file with a header naming the columns ``x`` and ``h``."""
        try:
            with open(path, newline="", encoding="utf-8") as handle:
                rows = list(csv.DictReader(handle))
        except OSError as error:
            raise InputError("profile", f"cannot read {path}: {error.strerror}") from None
        if not rows or not {"x", "h"} <= set(rows[0]):
            raise InputError("profile", f"{path} must have a header with columns x and h")
        try:
            xs = [float(row["x"]) for row in rows]
            hs = [float(row["h"]) for row in rows]
        except (TypeError, ValueError):
            raise InputError("profile", f"{path}: every x and h must be a number") from None
        return cls(xs, hs, interpolation)

    def defined_span(self) -> tuple[float, float]:
        return float(self.x[0]), float(self.x[-1])

    def length_scale(self, P: float, E_star: float) -> float | None:
        return 0.25 * float(self.x[-1] - self.x[0])

    def heights(self, x: FloatArray) -> FloatArray:
        xs, hs = self.x, self.h
        inside = np.clip(x, xs[0], xs[-1])
        if self.interpolation == "linear":
            values = np.interp(inside, xs, hs)
            start_slope, end_slope = self._slopes
        else:
            k = np.clip(np.searchsorted(xs, inside, side="right") - 1, 0, xs.size - 2)
            width = xs[k + 1] - xs[k]
            t = (inside - xs[k]) / width
            h00 = (1 + 2 * t) * (1 - t) ** 2
            h10 = t * (1 - t) ** 2
            h01 = t**2 * (3 - 2 * t)
            h11 = t**2 * (t - 1)
            values = (
                h00 * hs[k]
                + h10 * width * self._slopes[k]
                + h01 * hs[k + 1]
                + h11 * width * self._slopes[k + 1]
            )
            start_slope, end_slope = self._slopes[0], self._slopes[-1]
        values = values + np.where(x < xs[0], (x - xs[0]) * start_slope, 0.0)
        return values + np.where(x > xs[-1], (x - xs[-1]) * end_slope, 0.0)

    def describe(self) -> dict[str, Any]:
        return {"profile": self.name}


def as_profile(contact: Any) -> Profile:
    """A :class:`Profile` from a profile or a built-in law with a ``profile(x)``."""
    if isinstance(contact, Profile):
        return contact
    return LawProfile(contact)
