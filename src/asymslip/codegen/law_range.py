"""Where a user's law P(a) is a valid incomplete-contact law, as far as SymPy can establish.

An incomplete contact grows under load: P(a) must be positive and increasing in the half-width
a.  With a > 0 and every parameter positive (the rule ``asymslip derive`` states), this module
decides symbolically:

* a law whose slope dP/da is <= 0 for every a > 0 (``1/a``, ``k - a``) is refused;
* otherwise the interval of a where dP/da > 0 is found from the roots of dP/da (``E_star*a**2
  - k*a**3`` increases only for a < 2 E_star/(3 k)); a law that increases on two separate
  intervals is refused (it is not monotonic);
* on that interval the law must be positive somewhere: a law that is not (``-exp(-a)``) is
  refused; where it starts negative (``a**2 - c*a``) the range starts at its root (a = c);
* the loads it reaches are the limits at the ends (``k*tanh(a)`` is bounded by k).

What is established becomes :class:`LawRange`, recorded in the law module so that the law can
refuse loads outside it.  What SymPy cannot settle (or not within :data:`TIME_LIMIT` seconds)
is recorded as not established, and the law is then checked numerically where it is used.
"""

from __future__ import annotations

import signal
import threading
from collections.abc import Iterator
from contextlib import contextmanager
from dataclasses import dataclass, field
from typing import Any

from ..errors import InputError
from ..expressions import sympy_module

#: Seconds SymPy may spend establishing the range before it is recorded as not established.
TIME_LIMIT = 20.0


class _OutOfTime(BaseException):
    """Raised by the alarm; a BaseException so that no ``except Exception`` in SymPy eats it."""


@contextmanager
def _time_limit(seconds: float) -> Iterator[None]:
    """Interrupt the block after ``seconds`` (main thread on POSIX; elsewhere no limit)."""
    usable = hasattr(signal, "setitimer") and threading.current_thread() is threading.main_thread()
    if not usable:
        yield
        return

    def expired(signum: int, frame: Any) -> None:
        raise _OutOfTime

    previous = signal.signal(signal.SIGALRM, expired)
    signal.setitimer(signal.ITIMER_REAL, seconds)
    try:
        yield
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, previous)


@dataclass(frozen=True)
class LawRange:
    """Half-widths (a_min, a_max) where the law is positive and increasing, and its loads.

    ``established`` is False when SymPy could not settle it; the bounds are then the trivial
    (0, oo) and say nothing.
    """

    a_min: Any
    a_max: Any
    P_min: Any
    P_max: Any
    established: bool
    notes: tuple[str, ...] = field(default_factory=tuple)

    def expressions(self) -> dict[str, Any]:
        """The range functions of the law module, by name."""
        return {
            "half_width_minimum": self.a_min,
            "half_width_maximum": self.a_max,
            "load_minimum": self.P_min,
            "load_maximum": self.P_max,
        }

    @property
    def summary(self) -> str:
        """One sentence on where the law is valid."""
        sympy = sympy_module()
        text = sympy.sstr
        if not self.established:
            notes = "; ".join(self.notes)
            return (
                f"Where P(a) is positive and increasing was not established symbolically "
                f"({notes}): it is checked where the law is used."
            )
        if self.a_min == 0 and self.a_max == sympy.oo:
            where = "for every a > 0"
        elif self.a_max == sympy.oo:
            where = f"for a > {text(self.a_min)}"
        elif self.a_min == 0:
            where = f"for 0 < a < {text(self.a_max)}"
        else:
            where = f"for {text(self.a_min)} < a < {text(self.a_max)}"
        loads = f"loads from {text(self.P_min)}"
        if self.P_max == sympy.oo:
            loads += " without bound"
        else:
            loads += f" up to {text(self.P_max)} (larger loads have no half-width)"
        return f"P(a) is positive and increasing {where} (SymPy, positive parameters); {loads}."

    def describe(self) -> str:
        return self.summary

    def record(self) -> dict[str, Any]:
        """The range as plain data for ``__asymslip_law__``."""
        sympy = sympy_module()
        return {
            "established": self.established,
            "half_width": [sympy.sstr(self.a_min), sympy.sstr(self.a_max)],
            "load": [sympy.sstr(self.P_min), sympy.sstr(self.P_max)],
            "summary": self.summary,
        }


def _sign(expr: Any) -> str | None:
    """ "+" if provably > 0, "-" if provably <= 0, else None (tries a few rewritings)."""
    sympy = sympy_module()
    for candidate in (expr, sympy.factor(expr), sympy.simplify(expr)):
        if candidate.is_positive:
            return "+"
        if candidate.is_nonpositive:
            return "-"
    return None


def _positive_roots(expr: Any, a: Any, low: Any, high: Any) -> list[Any] | None:
    """The roots of ``expr`` in (low, high), sorted, or None if SymPy cannot list and order them."""
    sympy = sympy_module()
    roots = sympy.solveset(expr, a, sympy.Interval.open(low, high))
    if not isinstance(roots, sympy.FiniteSet):
        return None
    listed = list(roots)
    if not all(root.is_positive for root in listed):
        return None
    for i, first in enumerate(listed):
        for second in listed[i + 1 :]:
            if _sign(second - first) is None:
                return None
    return sorted(listed, key=lambda root: sum(_sign(root - other) == "+" for other in listed))


def _refuse(text: str, rule: str) -> InputError:
    return InputError("P_of_a", rule, text)


def _increasing_interval(slope: Any, a: Any, text: str) -> tuple[Any, Any] | str:
    """(lo, hi) where dP/da > 0, or a reason it could not be established."""
    sympy = sympy_module()
    shown = sympy.sstr(sympy.factor(slope))
    sign = _sign(slope)
    if sign == "+":
        return (sympy.Integer(0), sympy.oo)
    if sign == "-":
        raise _refuse(
            text,
            f"decreases with a: dP/da = {shown} is <= 0 for every a > 0 "
            "(parameters positive); a contact law must increase with the half-width a "
            "(an incomplete contact grows under load)",
        )
    roots = _positive_roots(slope, a, 0, sympy.oo)
    if roots is None:
        return f"the sign of dP/da = {shown} depends on a in a way SymPy cannot resolve"
    edges = [sympy.Integer(0), *roots, sympy.oo]
    increasing: list[tuple[Any, Any]] = []
    for low, high in zip(edges, edges[1:], strict=False):
        probe = high / 2 if low == 0 else 2 * low if high == sympy.oo else (low + high) / 2
        sign = _sign(slope.subs(a, probe))
        if sign is None:
            return (
                f"the sign of dP/da between a = {sympy.sstr(low)} and {sympy.sstr(high)} "
                "is not decidable"
            )
        if sign == "+":
            if increasing and increasing[-1][1] == low:  # dP/da only touches 0 at low
                increasing[-1] = (increasing[-1][0], high)
            else:
                increasing.append((low, high))
    if not increasing:
        raise _refuse(
            text,
            f"decreases with a: dP/da = {shown} is <= 0 for every a > 0 "
            "(parameters positive); a contact law must increase with the half-width "
            "a",
        )
    if len(increasing) > 1:
        listed = ", ".join(f"({sympy.sstr(lo)}, {sympy.sstr(hi)})" for lo, hi in increasing)
        raise _refuse(
            text,
            f"is not monotonic: dP/da = {shown} is > 0 on separate intervals "
            f"of a {listed}; a contact law must increase with a over the range it is "
            "used on (write the formula for one branch)",
        )
    return increasing[0]


def _analyse(load: Any, slope: Any, a: Any, text: str) -> LawRange:
    sympy = sympy_module()
    interval = _increasing_interval(slope, a, text)
    if isinstance(interval, str):
        return _unknown(interval)
    low, high = interval
    P_low = sympy.limit(load, a, low, "+") if low == 0 else sympy.simplify(load.subs(a, low))
    P_high = (
        sympy.limit(load, a, sympy.oo) if high == sympy.oo else sympy.simplify(load.subs(a, high))
    )
    # Limits may be infinite: the extended predicates include -oo and oo.
    if P_high.is_extended_nonpositive:
        raise _refuse(
            text,
            f"is not positive where it increases: P(a) <= {sympy.sstr(P_high)} "
            f"for a in ({sympy.sstr(low)}, {sympy.sstr(high)}) (parameters positive); "
            "a contact law needs P > 0",
        )
    if P_low.is_extended_nonnegative:
        return LawRange(low, high, P_low, P_high, True)
    if P_low.is_extended_negative:
        roots = _positive_roots(load, a, low, high)
        if roots is not None and len(roots) == 1:
            return LawRange(roots[0], high, sympy.Integer(0), P_high, True)
    return _unknown(f"the sign of P(a) near a = {sympy.sstr(low)} is not decidable")


def _unknown(note: str) -> LawRange:
    sympy = sympy_module()
    return LawRange(sympy.Integer(0), sympy.oo, sympy.Integer(0), sympy.oo, False, (note,))


def analyse_law(load: Any, slope: Any, a: Any, text: str) -> LawRange:
    """The range where ``load`` (with ``slope`` = dP/da) is a valid law; refuse an invalid one.

    Raises
    ------
    InputError
        (parameter ``P_of_a``) when the law provably decreases everywhere, increases on
        separate intervals, or is nowhere positive where it increases.
    """
    try:
        with _time_limit(TIME_LIMIT):
            return _analyse(load, slope, a, text)
    except InputError:
        raise
    except _OutOfTime:
        return _unknown(f"SymPy did not settle it within {TIME_LIMIT:g} s")
    except (
        ArithmeticError,
        NotImplementedError,
        TypeError,
        ValueError,
        RecursionError,
        AttributeError,
    ) as error:
        return _unknown(f"SymPy could not decide it ({type(error).__name__})")
