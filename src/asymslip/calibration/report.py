"""What ``asymslip calibrate`` prints: the calibration per edge and load, and its checks.

:func:`checks` gives, at each calibrated load, each edge's moment factor f (AS4: 1 when the
contact's rotation does not change along the path, so that (21) and b_exact = a(P_K) would
hold) and the two edges' balance (AS6: exactly 1 for consistent data whatever the moment), each
with its propagated error; :func:`format_calibration` the text table.  Both build the
calibrated law, so they also say when it cannot be built (an edge that does not advance).

Runtime needs NumPy only.

Examples
--------
Consistent data give a balance of 1 (AS6) and, without a moment, a moment factor of 1 (AS4),
within their errors: Hertzian pressures (48) (R = E* = 1) at three loads.

>>> import numpy as np
>>> from asymslip.calibration import Traces, calibrate
>>> from asymslip.calibration.report import checks
>>> x = np.arange(-120, 121) * 0.1
>>> loads = [90.0, 100.0, 110.0]
>>> pressures = [np.sqrt(np.maximum(4 * P / np.pi - x**2, 0)) / 2 for P in loads]  # (48)
>>> found = checks(calibrate(Traces.from_arrays(np.repeat(loads, x.size), np.tile(x, 3),
...                                             np.concatenate(pressures))))
>>> [bool(abs(b - 1) <= e) for b, e in zip(found.balance, found.balance_error)]
[True, True, True]
>>> right = found.edge("right")
>>> [bool(abs(f - 1) <= e) for f, e in zip(right.moment_factor, right.moment_factor_error)]
[True, True, True]
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..errors import InputError
from ..laws.calibrated import CalibratedLaw
from .calibration import Calibration
from .traces import SIDES, Side

FloatArray = NDArray[np.float64]


@dataclass(frozen=True)
class EdgeChecks:
    """One edge's moment factor f (AS4) at the checked loads, and its propagated error."""

    moment_factor: tuple[float, ...]
    moment_factor_error: tuple[float, ...]


@dataclass(frozen=True)
class LawChecks:
    """The law-level checks of a calibration (:func:`checks`).

    ``refusal`` is why the calibrated law cannot be built (then nothing else is filled);
    ``edges`` the moment factor of each calibrated edge; ``balance`` the two edges' balance
    (AS6) with its error, ``None`` with one edge.
    """

    loads: tuple[float, ...] = ()
    edges: tuple[tuple[Side, EdgeChecks], ...] = ()
    balance: tuple[float, ...] | None = None
    balance_error: tuple[float, ...] | None = None
    refusal: str | None = None

    def edge(self, side: Side) -> EdgeChecks:
        """The checks of edge ``side`` (KeyError when it was not calibrated)."""
        return dict(self.edges)[side]

    def to_dict(self) -> dict[str, object]:
        """For ``--json`` (key ``checks``): ``{"P": [...], "right": {"moment_factor": [...],
        "moment_factor_error": [...]}, "left": {...}, "balance": [...], "balance_error": [...]}``,
        or ``{"law": "<why it cannot be built>"}``."""
        if self.refusal is not None:
            return {"law": self.refusal}
        found: dict[str, object] = {"P": list(self.loads)}
        for side, edge in self.edges:
            found[side] = {
                "moment_factor": list(edge.moment_factor),
                "moment_factor_error": list(edge.moment_factor_error),
            }
        if self.balance is not None and self.balance_error is not None:
            found["balance"] = list(self.balance)
            found["balance_error"] = list(self.balance_error)
        return found


def _values(array: ArrayLike) -> tuple[float, ...]:
    return tuple(float(value) for value in np.asarray(array, dtype=np.float64).ravel())


def checks(calibration: Calibration) -> LawChecks:
    """The law-level checks at every calibrated load (:class:`LawChecks`).

    Loads outside an edge's calibrated range are left out; the balance needs both edges.
    """
    try:
        law = calibration.law()
    except InputError as error:
        return LawChecks(refusal=error.rule)
    low, high = law.common_range
    loads = calibration.loads
    loads = loads[(loads >= low) & (loads <= high)]
    edges: list[tuple[Side, EdgeChecks]] = []
    for side in calibration.sides:

        def factor(fitted: CalibratedLaw, side: Side = side) -> FloatArray:
            return fitted.for_edge(side).moment_factor(loads)

        edges.append((side, EdgeChecks(_values(factor(law)), _values(law.error_of(factor)))))
    balance = balance_error = None
    if len(calibration.sides) == 2:
        balance = _values(law.multiplier_balance(loads))
        balance_error = _values(law.error_of(lambda fitted: fitted.multiplier_balance(loads)))
    return LawChecks(_values(loads), tuple(edges), balance, balance_error)


def format_calibration(calibration: Calibration) -> str:
    """The calibration as text: per edge and load, a, L_I, their errors and the window."""
    lines = [
        f"calibration of {calibration.source}: {calibration.loads.size} loads; distances a "
        f"from x = {calibration.origin:.6g}"
        + (
            " (one edge only: the contact is taken as symmetric about it)"
            if calibration.symmetric_about_origin
            else ""
        ),
    ]
    header = (
        f"{'P':>12} {'a':>12} {'a_error':>9} {'L_I':>12} {'L_I_error':>9} {'errors':>8}  "
        f"{'window x':>25} {'nodes':>5}"
    )
    for side in SIDES:
        fits = calibration.fits(side)
        if not fits:
            continue
        lines += ["", f"{side} edge", header]
        for fit in fits:
            window = f"{fit.window[0]:.6g} .. {fit.window[1]:.6g}"
            lines.append(
                f"{fit.P:12.6g} {fit.position(calibration.origin):12.6g} {fit.a_error:9.2g} "
                f"{fit.L_I:12.6g} {fit.L_I_error:9.2g} {fit.error_kind:>8}  {window:>25} "
                f"{fit.nodes:5d}"
            )
            lines += [f"{'':12} note: {note}" for note in fit.notes]
    found = checks(calibration)
    lines.append("")
    if found.refusal is not None:
        lines.append(f"the law a(P), L_I(P) cannot be built: {found.refusal}")
    else:
        loads = found.loads
        for side, values in found.edges:
            pairs = ", ".join(
                f"{f:.4g} +- {e:.2g}"
                for f, e in zip(values.moment_factor, values.moment_factor_error, strict=True)
            )
            lines.append(
                f"{side} edge moment factor f (1 without rotation) at P = "
                f"{', '.join(f'{P:g}' for P in loads)}: {pairs}"
            )
        if found.balance is not None and found.balance_error is not None:
            pairs = ", ".join(
                f"{f:.6g} +- {e:.2g}"
                for f, e in zip(found.balance, found.balance_error, strict=True)
            )
            lines.append(f"balance of the two edges (exactly 1 for consistent data): {pairs}")
    if calibration.load_balance:
        lines.append(
            "load balance, the integral of p dx over P (1 for consistent data): "
            + ", ".join(f"{ratio:.4g} at P = {P:.6g}" for P, ratio in calibration.load_balance)
        )
    lines += [f"read: {note}" for note in calibration.notes]
    lines += [f"warning: {warning}" for warning in calibration.warnings]
    return "\n".join(lines)
