"""Each edge's position a and multiplier L_I at each load, from pressure traces.

:func:`calibrate` fits both edges of every trace (:mod:`.edge_fit`) and collects the results,
per edge and per load, in a :class:`Calibration`: what ``asymslip calibrate`` prints, saves
and what :class:`~asymslip.laws.calibrated.CalibratedLaw` is built from.

Distances and the origin
------------------------
Each edge's ``a`` is its distance from one fixed point, the *origin*, along the edge's outward
direction (the right edge: x_edge - origin; the left edge: origin - x_edge), which is how the
paper's a and b are measured.  By default the origin is the centre of the contact at the
smallest load that has both edges; for a symmetric contact centred at x = 0 that is 0 to
within the fit's error.  Any point inside the contact at every load may be given instead.
When only one edge was exported, the contact is taken as symmetric about x = 0 (the origin is
0 and the width is twice the edge's distance from it); the calibration records the assumption.

Runtime needs NumPy only.

Examples
--------
Hertzian pressures (48) (R = E* = 1) at three loads; the fitted edges are a(P) of (29):

>>> import numpy as np
>>> from asymslip.calibration import Traces, calibrate
>>> x = np.arange(-120, 121) * 0.1
>>> loads = [90.0, 100.0, 110.0]
>>> # (48) with a^2 = 4P/pi: 2P/(pi a^2) = 1/2
>>> pressures = [np.sqrt(np.maximum(4 * P / np.pi - x**2, 0)) / 2 for P in loads]
>>> calibration = calibrate(Traces.from_arrays(np.repeat(loads, x.size), np.tile(x, 3),
...                                            np.concatenate(pressures)))
>>> [round(float(a), 3) for a in calibration.columns("right")["a"]]
[10.705, 11.284, 11.835]
>>> [round(float(np.sqrt(4 * P / np.pi)), 3) for P in loads]
[10.705, 11.284, 11.835]
"""

from __future__ import annotations

import json
import math
from collections.abc import Callable
from dataclasses import dataclass, field, replace
from pathlib import Path

import numpy as np
from numpy.typing import NDArray

from ..errors import InputError
from ..files.atomic import atomic_write
from ..laws.calibrated import CalibratedLaw
from .edge_fit import (
    FE_ALLOWANCE_A,
    FE_ALLOWANCE_A_AT_NODE,
    FE_ALLOWANCE_L,
    FE_ALLOWANCE_L_SLOPE,
    EdgeFit,
    EdgeFitError,
    fit_edge,
)
from .traces import SIDES, Side, Traces

FloatArray = NDArray[np.float64]

FORMAT = "asymslip-calibration"
VERSION = 1


@dataclass(frozen=True)
class Calibration:
    """Edge fits per edge, in increasing load, and the origin their distances are taken from.

    Attributes
    ----------
    right, left
        The fits of each edge (possibly empty for one of them), increasing in P.
    origin
        The point (trace coordinates) the distances a are measured from.
    source
        Where the data came from.
    symmetric_about_origin
        True when only one edge was given, so the contact is taken as symmetric about the
        origin.
    warnings
        What the data do not support, in words (e.g. an edge that does not advance with P, a
        load balance far from 1).
    notes
        What the reader did to the data (an FE result: the steps used, pressures clipped).
    load_balance
        (P, the integral of p dx over P) of each trace that spans the whole contact: 1 for
        consistent data (see :func:`load_balance`).
    """

    right: tuple[EdgeFit, ...]
    left: tuple[EdgeFit, ...]
    origin: float
    source: str
    symmetric_about_origin: bool = False
    warnings: tuple[str, ...] = field(default=())
    notes: tuple[str, ...] = field(default=())
    load_balance: tuple[tuple[float, float], ...] = field(default=())

    def fits(self, side: Side) -> tuple[EdgeFit, ...]:
        """The fits of one edge."""
        return self.right if side == "right" else self.left

    @property
    def sides(self) -> tuple[Side, ...]:
        """The edges that have data."""
        return tuple(side for side in SIDES if self.fits(side))

    @property
    def loads(self) -> FloatArray:
        """Every load with data for at least one edge, increasing."""
        return np.unique([fit.P for side in SIDES for fit in self.fits(side)])

    def columns(self, side: Side) -> dict[str, FloatArray]:
        """One edge as arrays: P, a (from the origin), a_error, L_I, L_I_error."""
        fits = self.fits(side)
        return {
            "P": np.array([fit.P for fit in fits]),
            "a": np.array([fit.position(self.origin) for fit in fits]),
            "a_error": np.array([fit.a_error for fit in fits]),
            "L_I": np.array([fit.L_I for fit in fits]),
            "L_I_error": np.array([fit.L_I_error for fit in fits]),
        }

    def bound_loads(self, side: Side) -> tuple[float, ...]:
        """The loads at which the edge's errors are bounds, not estimates (EdgeFit.error_kind)."""
        return tuple(fit.P for fit in self.fits(side) if fit.error_kind == "bound")

    def law(self) -> CalibratedLaw:
        """Each edge's law a(P), L_I(P) from this calibration (refused if an edge does not
        advance or has fewer than 2 loads): ``Calibration.load(path).law()``."""
        return CalibratedLaw(self)

    # --- JSON ----------------------------------------------------------------------------------
    def to_dict(self) -> dict[str, object]:
        """The JSON object: per edge and per load, P, a, a_error, L_I, L_I_error and the window.

        ``a`` is the distance from ``origin`` (see the module notes); ``x_edge`` the edge in the
        traces' own coordinate; ``window`` the nodes in contact the chosen fit used.
        """
        return {
            "format": FORMAT,
            "version": VERSION,
            "source": self.source,
            "origin": self.origin,
            "symmetric_about_origin": self.symmetric_about_origin,
            "right": [_fit_to_dict(fit, self.origin) for fit in self.right],
            "left": [_fit_to_dict(fit, self.origin) for fit in self.left],
            "warnings": list(self.warnings),
            "notes": list(self.notes),
            "load_balance": [{"P": P, "balance": ratio} for P, ratio in self.load_balance],
        }

    def save(self, path: str | Path) -> None:
        """Write the calibration as JSON (atomically: complete or absent)."""
        text = json.dumps(self.to_dict(), indent=2, allow_nan=False) + "\n"
        with atomic_write(path, "out", mode="w") as handle:
            handle.write(text)

    @classmethod
    def load(cls, path: str | Path) -> Calibration:
        """Read a calibration written by :meth:`save`; a malformed file is refused in one line."""
        path = Path(path)
        try:
            text = path.read_text()
        except (OSError, UnicodeDecodeError) as error:
            raise InputError("calibration", f"cannot read {path}: {error}") from None
        try:
            data = json.loads(text, parse_constant=_refuse_constant)
        except json.JSONDecodeError as error:
            raise InputError(
                "calibration", f"{path}: line {error.lineno}: not valid JSON ({error.msg})"
            ) from None
        except ValueError as error:
            raise InputError("calibration", f"{path}: {error}") from None
        return cls.from_dict(data, source=str(path))

    @classmethod
    def from_dict(cls, data: object, source: str = "calibration") -> Calibration:
        """Rebuild a calibration from :meth:`to_dict`'s object, checking every field."""

        def fail(rule: str) -> InputError:
            return InputError("calibration", f"{source}: {rule}")

        if not isinstance(data, dict):
            raise fail("not a calibration (the top level must be a JSON object)")
        if data.get("format") != FORMAT:
            raise fail(f"not a calibration: 'format' must be {FORMAT!r}")
        if data.get("version") != VERSION:
            raise fail(
                f"version {data.get('version')!r} is not supported (this asymslip reads "
                f"version {VERSION})"
            )
        origin = _number(data, "origin", fail)
        symmetric = data.get("symmetric_about_origin", False)
        if not isinstance(symmetric, bool):
            raise fail("'symmetric_about_origin' must be true or false")
        warnings = data.get("warnings", [])
        if not isinstance(warnings, list) or not all(isinstance(w, str) for w in warnings):
            raise fail("'warnings' must be a list of strings")
        notes = data.get("notes", [])
        if not isinstance(notes, list) or not all(isinstance(n, str) for n in notes):
            raise fail("'notes' must be a list of strings")
        balance = data.get("load_balance", [])
        if not isinstance(balance, list) or not all(isinstance(b, dict) for b in balance):
            raise fail("'load_balance' must be a list of objects with P and balance")
        balances = tuple(
            (_number(b, "P", fail, positive=True), _number(b, "balance", fail)) for b in balance
        )
        edges = {}
        for side in SIDES:
            entries = data.get(side, [])
            if not isinstance(entries, list):
                raise fail(f"'{side}' must be a list of loads")
            fits = tuple(
                _fit_from_dict(entry, side, origin, f"{side}[{k}]", fail)
                for k, entry in enumerate(entries)
            )
            loads = [fit.P for fit in fits]
            if any(b <= a for a, b in zip(loads, loads[1:], strict=False)):
                raise fail(f"'{side}': the loads P must increase")
            edges[side] = fits
        if not edges["right"] and not edges["left"]:
            raise fail("no edge has any load")
        return cls(
            edges["right"],
            edges["left"],
            origin,
            str(data.get("source", source)),
            symmetric,
            tuple(warnings),
            tuple(notes),
            balances,
        )


def _refuse_constant(name: str) -> float:
    raise ValueError(f"{name} is not a number a calibration may hold")


def _number(
    entry: dict[str, object],
    key: str,
    fail: Callable[[str], InputError],
    *,
    positive: bool = False,
    non_negative: bool = False,
) -> float:
    value = entry.get(key)
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value):
        raise fail(f"'{key}' must be a finite number (got {value!r})")
    if positive and not value > 0:
        raise fail(f"'{key}' must be > 0 (got {value!r})")
    if non_negative and not value >= 0:
        raise fail(f"'{key}' must be >= 0 (got {value!r})")
    return float(value)


def _fit_to_dict(fit: EdgeFit, origin: float) -> dict[str, object]:
    return {
        "P": fit.P,
        "a": fit.position(origin),
        "a_error": fit.a_error,
        "L_I": fit.L_I,
        "L_I_error": fit.L_I_error,
        "window": {"x_from": fit.window[0], "x_to": fit.window[1], "nodes": fit.nodes},
        "x_edge": fit.x_edge,
        "c": fit.c,
        "noise": fit.noise,
        "noise_relative": fit.noise_relative,
        "last_node_used": fit.last_node_used,
        "error_kind": fit.error_kind,
        "notes": list(fit.notes),
    }


def _fit_from_dict(
    entry: object, side: Side, origin: float, name: str, fail: Callable[[str], InputError]
) -> EdgeFit:
    if not isinstance(entry, dict):
        raise fail(f"{name} must be an object")

    def at(rule: str) -> InputError:
        return fail(f"{name}: {rule}")

    P = _number(entry, "P", at, positive=True)
    x_edge = _number(entry, "x_edge", at)
    a = _number(entry, "a", at)
    expected = x_edge - origin if side == "right" else origin - x_edge
    if abs(a - expected) > 1e-9 * max(abs(x_edge), abs(origin), abs(a), 1e-300):
        raise at(
            f"'a' = {a!r} is not the distance of 'x_edge' = {x_edge!r} from 'origin' = {origin!r}"
        )
    window = entry.get("window")
    if not isinstance(window, dict):
        raise at("'window' must be an object with x_from, x_to and nodes")
    nodes = window.get("nodes")
    if isinstance(nodes, bool) or not isinstance(nodes, int) or nodes < 1:
        raise at("'window.nodes' must be a positive integer")
    notes = entry.get("notes", [])
    if not isinstance(notes, list) or not all(isinstance(note, str) for note in notes):
        raise at("'notes' must be a list of strings")
    used = entry.get("last_node_used", True)
    if not isinstance(used, bool):
        raise at("'last_node_used' must be true or false")
    # Files written before fits told estimates from bounds: as they were reported, estimates.
    kind = entry.get("error_kind", "estimate")
    if kind not in ("estimate", "bound"):
        raise at(f'\'error_kind\' must be "estimate" or "bound" (got {kind!r})')
    return EdgeFit(
        side=side,
        P=P,
        x_edge=x_edge,
        a_error=_number(entry, "a_error", at, non_negative=True),
        L_I=_number(entry, "L_I", at, positive=True),
        L_I_error=_number(entry, "L_I_error", at, non_negative=True),
        c=_number(entry, "c", at),
        window=(_number(window, "x_from", at), _number(window, "x_to", at)),
        nodes=nodes,
        noise=_number(entry, "noise", at, non_negative=True),
        last_node_used=used,
        notes=tuple(notes),
        # Files written before the scatter had a relative part: none.
        noise_relative=(
            _number(entry, "noise_relative", at, non_negative=True)
            if "noise_relative" in entry
            else 0.0
        ),
        error_kind="bound" if kind == "bound" else "estimate",
    )


# --- calibrating ----------------------------------------------------------------------------------
def calibrate(
    traces: Traces, *, noise: float | None = None, origin: float | None = None
) -> Calibration:
    """Fit every edge of every trace and collect the fits per edge.

    Parameters
    ----------
    traces
        From :func:`~asymslip.calibration.traces.read_traces` or :meth:`Traces.from_arrays`.
    noise
        The pressure scatter (a standard deviation, in pressure units) if known; by default it
        is estimated from each trace.
    origin
        The point the distances a are measured from (see the module notes).

    Raises
    ------
    InputError
        Naming the file line (or array row) and the problem when a trace cannot give an edge,
        when an edge has data at one load only, or when the origin is outside the contact.
    """
    if noise is not None and not (math.isfinite(noise) and noise >= 0):
        raise InputError(
            "noise", "must be a finite number >= 0", noise if math.isfinite(noise) else None
        )  # never print inf or nan
    if origin is not None and not math.isfinite(origin):  # before the fits, not after them
        raise InputError("origin", "must be a finite number (not inf or nan)")
    fits: dict[Side, list[EdgeFit]] = {"right": [], "left": []}
    seen: dict[tuple[float, Side], str] = {}
    for trace in traces.traces:
        for side in trace.sides():
            key = (trace.P, side)
            if key in seen:
                raise InputError(
                    "traces",
                    f"{trace.where()}: a second trace of the {side} edge "
                    f"at this load (the first is at {seen[key]})",
                )
            seen[key] = trace.where()
            try:
                fit = fit_edge(
                    trace.x, trace.p, side, trace.P, noise, fe_nodes=trace.unit == "node"
                )
            except EdgeFitError as error:
                raise InputError(
                    "traces", f"{trace.where(error.node)}: {side} edge: {error.rule}"
                ) from None
            fits[side].append(fit)
    for side in SIDES:
        fits[side].sort(key=lambda fit: fit.P)
        if len(fits[side]) == 1:
            only = fits[side][0]
            raise InputError(
                "traces",
                f"{traces.source}: the {side} edge has data at one load "
                f"only (P = {only.P:.6g}); its law a(P) needs two or more",
            )
    right, left = tuple(fits["right"]), tuple(fits["left"])
    symmetric = not (right and left)
    if origin is None:
        origin = 0.0 if symmetric else _centre_at_smallest_load(right, left)
    elif symmetric and origin != 0.0:
        raise InputError(
            "origin",
            "with one edge only the contact is taken as symmetric about "
            "x = 0, so the origin must be 0",
            origin,
        )
    for side, edge in (("right", right), ("left", left)):
        for fit in edge:
            if not fit.position(origin) > 0:
                raise InputError(
                    "origin",
                    f"x = {origin:.6g} is not inside the contact at "
                    f"P = {fit.P:.6g}: the {side} edge is at x = {fit.x_edge:.6g}; "
                    "the distances a must be measured from a point inside every "
                    "contact",
                    origin,
                )
    edges: tuple[tuple[Side, tuple[EdgeFit, ...]], ...] = (("right", right), ("left", left))
    warnings = [_advance_warning(side, edge, origin) for side, edge in edges]
    if symmetric:
        side = "right" if right else "left"
        warnings.append(
            f"only the {side} edge has data: the contact is taken as symmetric about "
            "x = 0 (the width in L_II is twice the edge's distance from 0)"
        )
    balances = load_balance(traces, fits)
    warnings += _balance_warnings(balances)
    notes = traces.notes
    if any(trace.unit == "node" for trace in traces.traces):
        notes += (FE_ALLOWANCE_NOTE,)
    calibration = Calibration(
        right,
        left,
        float(origin),
        traces.source,
        symmetric,
        tuple(w for w in warnings if w),
        notes,
        tuple(balances),
    )
    return replace(calibration, warnings=calibration.warnings + _edge_balance_warning(calibration))


#: The rule for the errors of fits to an FE solution's nodal pressures, stated with the result.
FE_ALLOWANCE_NOTE = (
    "FE nodal pressures: each error includes an allowance for the FE's own discretisation "
    f"error: for a, {FE_ALLOWANCE_A:g} element at the edge in quadrature where the fitted edge "
    "lies between the last node in contact and the first node out, and where the fit was "
    "moved to the last node in contact, the larger of the distance moved and "
    f"{FE_ALLOWANCE_A_AT_NODE:g} element; for L_I, ({FE_ALLOWANCE_L:g} - "
    f"{FE_ALLOWANCE_L_SLOPE:g} f) h/a in quadrature, f the fraction of the last gap at which the "
    "fit put the edge (0 where it was moved to the last node; h the spacing at the edge, a the "
    "half-width); fixed a priori from the project's CalculiX model (15 to 33 elements per a); "
    "one FE run cannot show its own, and a model unlike "
    "that one may err more (compare a run on a finer mesh)"
)


#: A load balance (the integral of p dx over P) further from 1 than this is a warning ...
BALANCE_WARNING = 0.05
#: ... and further than this a refusal: the loads or the pressure units do not fit the data.
BALANCE_LIMIT = 0.25


def load_balance(traces: Traces, fits: dict[Side, list[EdgeFit]]) -> list[tuple[float, float]]:
    """(P, integral of p dx / P) for each trace that holds the whole contact.

    The integral is the trapezoidal rule over the nodes in contact, plus, at each edge, the
    fitted expansion integrated from the last node in contact to the fitted edge (the
    trapezoidal rule would miss the square-root cap there): (2/3) L_I d^(3/2) + (2/5) c
    d^(5/2) with d that distance.  Refuses a balance further from 1 than BALANCE_LIMIT.
    """
    found: list[tuple[float, float]] = []
    by_load = {side: {fit.P: fit for fit in fits[side]} for side in SIDES}
    for trace in traces.traces:
        if trace.side is not None:
            continue
        right, left = by_load["right"].get(trace.P), by_load["left"].get(trace.P)
        if right is None or left is None:
            continue
        inside = (trace.x > left.x_edge) & (trace.x < right.x_edge) & (trace.p > 0)
        if inside.sum() < 2:
            continue
        x, p = trace.x[inside], trace.p[inside]
        total = float(np.sum(0.5 * (p[1:] + p[:-1]) * np.diff(x)))
        for fit, d in ((right, right.x_edge - x[-1]), (left, x[0] - left.x_edge)):
            d = max(d, 0.0)
            total += 2 / 3 * fit.L_I * d**1.5 + 2 / 5 * fit.c * d**2.5
        ratio = total / trace.P
        if abs(ratio - 1) > BALANCE_LIMIT:
            raise InputError(
                "traces",
                f"{trace.where()}: the pressures integrate to {ratio:.4g} times the load "
                f"(the integral of p dx must be P, within {BALANCE_LIMIT:.0%}): the loads, or "
                "the units of the pressures or of x, do not fit the data",
            )
        found.append((trace.P, ratio))
    return found


def _balance_warnings(balances: list[tuple[float, float]]) -> list[str]:
    off = [(P, ratio) for P, ratio in balances if abs(ratio - 1) > BALANCE_WARNING]
    if not off:
        return []
    listed = ", ".join(f"{ratio:.4g} times the load at P = {P:.6g}" for P, ratio in off)
    return [
        f"the pressures integrate to {listed} (1 for consistent data; more "
        f"than {BALANCE_WARNING:.0%} off): check the loads and the units; a(P) and L_I(P), "
        "and the slip zone with them, are only as right as the loads"
    ]


def _edge_balance_warning(calibration: Calibration) -> tuple[str, ...]:
    """The two edges' balance (AS6) off 1 by more than 3 times its error and 5 %: a warning."""
    if len(calibration.sides) != 2:
        return ()
    try:
        law = calibration.law()
    except InputError:
        return ()  # the law's own refusal says why, where it is built
    low, high = law.common_range
    loads = calibration.loads[(calibration.loads >= low) & (calibration.loads <= high)]
    if loads.size == 0:
        return ()
    balance = np.asarray(law.multiplier_balance(loads), dtype=np.float64)
    error = np.asarray(law.error_of(lambda fitted: fitted.multiplier_balance(loads)))
    off = (np.abs(balance - 1) > 3 * error) & (np.abs(balance - 1) > BALANCE_WARNING)
    if not off.any():
        return ()
    listed = ", ".join(
        f"{b:.4g} +- {e:.2g} at P = {P:.6g}"
        for P, b, e in zip(loads[off], balance[off], error[off], strict=True)
    )
    return (
        f"the balance of the two edges (AS6) is {listed}, not 1: the two edges' a(P) and "
        "L_I(P) are not those of one contact carrying these loads (check the loads and units)",
    )


def _centre_at_smallest_load(right: tuple[EdgeFit, ...], left: tuple[EdgeFit, ...]) -> float:
    """Midpoint of the two edges at the smallest load that has both (else at each's first)."""
    by_load = {fit.P: fit for fit in left}
    for fit in right:
        if fit.P in by_load:
            return 0.5 * (fit.x_edge + by_load[fit.P].x_edge)
    return 0.5 * (right[0].x_edge + left[0].x_edge)


def _advance_warning(side: Side, edge: tuple[EdgeFit, ...], origin: float) -> str:
    """Words when the edge does not move outwards as the load grows (empty if it does)."""
    for before, after in zip(edge, edge[1:], strict=False):
        step = after.position(origin) - before.position(origin)
        if not step > 0:
            why = (
                "it recedes, which is outside the model (the state-2 contact must contain the "
                "state-1 contact near the edge)"
                if -step > before.a_error + after.a_error
                else "the change is within the fits' errors: the loads are too close together "
                "for the mesh near this edge"
            )
            return (
                f"the {side} edge does not advance as the load grows: a = "
                f"{before.position(origin):.6g} +- {before.a_error:.2g} at P = {before.P:.6g}, "
                f"{after.position(origin):.6g} +- {after.a_error:.2g} at P = {after.P:.6g}; {why}; "
                "the law a(P) cannot be built from these loads"
            )
    return ""
