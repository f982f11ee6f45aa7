"""What the accuracy harness checks: contact laws that make problems, quantities that use them.

Adding a contact law or a generated quantity is one registration each, in ``references.py``:

* :func:`register_law` with a :class:`LawCase`: how to draw the law's parameters and the law
  written by hand from the paper (a(P) and dP/da in mpmath).  Every law-independent quantity is
  then checked on that law's problems too.
* :func:`register_quantity` with a :class:`Quantity`: the generated function (``module.name`` in
  ``asymslip_gen``), which problem values feed its parameters, and an independent mpmath
  evaluation written by hand from the paper's equations (never from SymPy's derived forms).
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass

import mpmath
import numpy as np

Values = Mapping[str, float]
MpValues = Mapping[str, mpmath.mpf]


@dataclass(frozen=True)
class LawCase:
    """A contact law a(P) as the harness needs it.

    Attributes
    ----------
    name
        Law name (``"hertz"``); quantities restrict themselves to laws by this name.
    parameters
        Draws the law's parameters as doubles, e.g. ``{"R": ..., "E_star": ...}``.
    half_width
        a(P) written by hand from the law, in mpmath: ``half_width(P, parameters)``.
    load_slope
        dP/da at half-width a, in mpmath: ``load_slope(a, parameters)``.  The harness
        differentiates it once more (mpmath.diff) for a''(P) and L_I'(P).
    """

    name: str
    parameters: Callable[[np.random.Generator], dict[str, float]]
    half_width: Callable[[mpmath.mpf, MpValues], mpmath.mpf]
    load_slope: Callable[[mpmath.mpf, MpValues], mpmath.mpf]
    #: Further exact values of the law at the half-width a1, for kernels that take
    #: intermediate quantities (the rounded flat's chord and corner angle): ``extras(a1, law)``.
    extras: Callable[[mpmath.mpf, MpValues], dict[str, mpmath.mpf]] | None = None


@dataclass(frozen=True)
class Quantity:
    """One generated function and its independent 50-digit reference.

    Attributes
    ----------
    function
        ``"module.name"`` of the generated function in ``asymslip_gen``.  A quantity whose
        module or function does not exist yet is reported as "not generated", not as a failure.
    args
        The function's parameters in order, each ``"name"`` (fed the problem value of that
        name) or ``"name=key"`` (fed the problem value ``key``).  The harness checks them
        against the generated signature, so a changed signature is an error, not a silent
        mismatch.
    reference
        The paper's equation transcribed by hand in mpmath; called with the same keyword
        arguments as mpmath numbers (the exact values of the doubles the function receives).
    equations
        The paper's equation numbers, for the report.
    laws
        Law names whose problems apply (empty: every law).
    where
        Optional filter on a problem's values (a domain condition such as P_K > 0).
    every
        Check every n-th problem only: for references that need quadrature.
    label
        Report name when it differs from the function name (several checks of one function).
    compose
        For an end-to-end check: a chain of generated functions (or the public API) called
        instead of ``function`` (which then names the last link, for the report).
    costly
        The reference is slow (root finding, quadrature): condition numbers are computed only
        for samples over the target, as for ``every`` > 1.
    """

    function: str
    args: tuple[str, ...]
    reference: Callable[..., mpmath.mpf]
    equations: tuple[str, ...]
    laws: tuple[str, ...] = ()
    where: Callable[[Values], bool] | None = None
    every: int = 1
    label: str = ""
    compose: Callable[..., object] | None = None
    costly: bool = False

    @property
    def name(self) -> str:
        return self.label or self.function.rsplit(".", 1)[-1]

    @property
    def parameters(self) -> tuple[tuple[str, str], ...]:
        """(parameter name, problem key) pairs."""
        pairs = []
        for arg in self.args:
            parameter, _, key = arg.partition("=")
            pairs.append((parameter, key or parameter))
        return tuple(pairs)


LAWS: dict[str, LawCase] = {}
QUANTITIES: dict[str, Quantity] = {}


def register_law(law: LawCase) -> LawCase:
    if law.name in LAWS:
        raise ValueError(f"law {law.name!r} registered twice")
    LAWS[law.name] = law
    return law


def register_quantity(quantity: Quantity) -> Quantity:
    if quantity.name in QUANTITIES:
        raise ValueError(f"quantity {quantity.name!r} registered twice")
    QUANTITIES[quantity.name] = quantity
    return quantity
