"""Steady-state slip zone at a contact edge: the paper's Section 2 applied to a law and a cycle.

:func:`slip_zone` is the public, validating entry point (one cycle, or arrays of cycles that
are all valid).  :func:`edge_quantities` is the vectorised core that sweeps reuse.
"""

from __future__ import annotations

from dataclasses import asdict, dataclass, field
from typing import Literal

import numpy as np
from numpy.typing import ArrayLike, NDArray

from asymslip_gen.corrective_slip import (
    slip_zone_width,
    stick_boundary_denominator,
    stick_boundary_proportional,
)
from asymslip_gen.corrective_stick import corrective_stick_slip_zone_width
from asymslip_gen.edge_multipliers import shear_edge_multiplier_proportional
from asymslip_gen.exact_solution import permanent_stick_load
from asymslip_gen.validity import (
    contact_growth_measure,
    multiplier_growth_measure,
    relative_slip_zone_measure,
    slip_zone_growth_measure,
    stick_ratio_first_order,
)

from .cycle import LoadCycle
from .errors import InputError, positive
from .laws.base import ContactLaw

FloatArray = NDArray[np.float64]
Edge = Literal["right", "left"]

#: A validity measure above this is reported in ``warnings`` ("<< 1" made concrete).
VALIDITY_THRESHOLD = 0.1

VALIDITY_MEANING = {
    "eq24": "contact growth dP a'(P)/a1",
    "eq25": "slip-zone size |b - a1|/a1",
    "eq26": "edge-multiplier growth dP |L_I'(P)|/L_I1",
    "eq27": "necessary condition dP a'(P)/a1 |1 - lam/mu - pi eta a1/(4 mu)|",
}


@dataclass(frozen=True)
class SlipZoneResult:
    """Everything `asymslip slip-zone` reports for one edge; field names are the JSON keys.

    Lengths are in the units of the law's parameters.  ``b`` is measured from the contact
    centre along the edge's outward direction (for the left edge, b is the distance of the
    left stick boundary from the centre).
    """

    a1: float
    a2: float
    lam: float
    eta: float
    L_I1: float
    L_I2: float
    L_II1: float
    L_II2: float
    b: float
    slip_zone_width: float
    b_first_order: float
    b_exact: float | None
    b_corrective_stick: float
    validity: dict[str, float]
    warnings: list[str] = field(default_factory=list)
    left: SlipZoneResult | None = None

    def to_dict(self) -> dict[str, object]:
        """The JSON object: these keys, with ``left`` only when both edges were asked for."""
        data = asdict(self)
        data.pop("left")
        if self.left is not None:
            data["left"] = self.left.to_dict()
        return data


def slip_direction(mu: ArrayLike, L_I2: ArrayLike, L_II2: ArrayLike) -> FloatArray:
    """+1 (forward), -1 (backward) or 0 (no slip) on loading, at the right-hand edge.

    Next to the state-2 edge (a1 < x < a2) the state-1 traction is zero, so loading slips there
    iff |L_II2| > mu L_I2 (derivations/edge_symmetry.py).
    """
    capacity = np.asarray(mu) * np.asarray(L_I2)
    return np.where(L_II2 > capacity, 1.0, np.where(L_II2 < -capacity, -1.0, 0.0))


def edge_quantities(
    law: ContactLaw, cycle: LoadCycle, mu: ArrayLike, edge: Edge = "right"
) -> dict[str, FloatArray]:
    """All slip-zone quantities of one edge, elementwise, without validation.

    The left edge is the right edge of the mirrored cycle (lam -> -lam, eta kept); backward
    slip is forward slip with (lam, eta) -> (-lam, -eta) (derivations/edge_symmetry.py).  The
    paper's formulas are evaluated on the forward-slip ("oriented") slopes.  Where the edge does
    not slip, b = a1 and the width is zero.  Call :func:`slip_zone` unless the inputs are
    already known to be valid.
    """
    mu = np.asarray(mu, dtype=np.float64)
    lam = cycle.lam if edge == "right" else -cycle.lam
    eta, dP = cycle.eta, cycle.dP
    a1 = law.half_width(cycle.P1)
    da = law.half_width_growth(cycle.P1, dP)
    a2 = a1 + da
    L_I1 = law.normal_multiplier(cycle.P1)
    L_I2 = law.normal_multiplier(cycle.P2)
    L_II1 = shear_edge_multiplier_proportional(lam, eta, a1, L_I1)
    L_II2 = shear_edge_multiplier_proportional(lam, eta, a2, L_I2)
    direction = slip_direction(mu, L_I2, L_II2)
    orientation = np.where(direction == 0, 1.0, direction)
    lam_o, eta_o = orientation * lam, orientation * eta
    slope1 = law.half_width_slope(cycle.P1)
    # The measures ask for the worst a'(P), L_I'(P) on (P1, P2); the ends stand in for it.
    worst_slope = np.maximum(slope1, law.half_width_slope(cycle.P2))
    worst_multiplier_slope = np.maximum(
        np.abs(law.normal_multiplier_slope(cycle.P1)),
        np.abs(law.normal_multiplier_slope(cycle.P2)),
    )
    slips = direction != 0
    width = np.where(slips, slip_zone_width(mu, lam_o, eta_o, a1, da, L_I1, L_I2), 0.0)
    b = np.where(slips, stick_boundary_proportional(mu, lam_o, eta_o, a1, a2, L_I1, L_I2), a1)
    first_order = a1 * stick_ratio_first_order(mu, lam_o, eta_o, a1, dP, slope1)
    stick_method = a1 - corrective_stick_slip_zone_width(mu, lam_o, eta_o, a1, da, L_I1, dP)
    return {
        "a1": a1,
        "a2": a2,
        "lam": lam,
        "eta": eta,
        "L_I1": L_I1,
        "L_I2": L_I2,
        "L_II1": L_II1,
        "L_II2": L_II2,
        "b": b,
        "slip_zone_width": width,
        "b_first_order": np.where(slips, first_order, a1),
        "b_corrective_stick": np.where(slips, stick_method, a1),
        "eq24": contact_growth_measure(dP, worst_slope, a1),
        "eq25": relative_slip_zone_measure(mu, lam_o, eta_o, a1, da, L_I1, L_I2),
        "eq26": multiplier_growth_measure(dP, worst_multiplier_slope, L_I1),
        "eq27": slip_zone_growth_measure(mu, lam_o, eta_o, a1, dP, worst_slope),
        # Internal: not part of the result.
        "direction": direction,
        "lam_oriented": lam_o,
        "eta_oriented": eta_o,
        "denominator": stick_boundary_denominator(mu, lam_o, eta_o, a1, a2, L_I1, L_I2),
        "permanent_stick_load": np.where(
            slips, permanent_stick_load(cycle.P1, dP, lam_o, mu), cycle.P1
        ),
    }


INTERNAL_KEYS = ("direction", "lam_oriented", "eta_oriented", "denominator",
                 "permanent_stick_load")  # fmt: skip


#: The message of :class:`InputError` when (17) has no root (shared with the sweep).
ZERO_DENOMINATOR_RULE = (
    "the denominator of (17), mu (L_I1 + L_I2) + L_II1 - L_II2, is zero for this friction "
    "coefficient and load path: no stick boundary exists"
)


def denominator_vanishes(values: dict[str, FloatArray], mu: ArrayLike) -> NDArray[np.bool_]:
    """Where an edge slips but the denominator of (17) is zero to rounding."""
    scale = (
        2 * np.asarray(mu) * (values["L_I1"] + values["L_I2"])
        + np.abs(values["L_II1"])
        + np.abs(values["L_II2"])
    )
    return (values["direction"] != 0) & (
        np.abs(values["denominator"]) <= 64 * np.finfo(float).eps * scale
    )


def edge_warnings(
    law: ContactLaw, cycle: LoadCycle, values: dict[str, FloatArray]
) -> tuple[list[list[str]], FloatArray]:
    """Per-cycle warnings, in words, and b_exact (NaN where it does not exist), vectorised.

    ``values`` is what :func:`edge_quantities` returns.  b_exact = a(P_K) (Jaeger-Ciavarella)
    is exact for any symmetric law when eta = 0.  Law-specific warnings (e.g. a table law's
    extrapolation) are the caller's: see :meth:`ContactLaw.load_warnings`.
    """
    rows = int(np.size(values["b"]))
    texts: list[list[str]] = [[] for _ in range(rows)]

    def column(name: str) -> FloatArray:
        return np.broadcast_to(values[name], (rows,))

    def add(mask: NDArray[np.bool_], message) -> None:
        for i in np.flatnonzero(np.broadcast_to(mask, (rows,))):
            texts[i].append(message(int(i)))

    still = column("direction") == 0
    add(still, lambda i: (
        "no slip at this edge: |L_II2| <= mu L_I2 (|lam + pi eta a2/4| <= mu), so the edge "
        "sticks wherever it is in contact; b = a1 and the slip-zone width is 0"))  # fmt: skip
    add(~still & (column("denominator") < 0),
        lambda i: "the denominator of (17) is negative: no steady partial-slip state")  # fmt: skip
    for key, meaning in VALIDITY_MEANING.items():
        measure = column(key)
        add(measure > VALIDITY_THRESHOLD,
            lambda i, key=key, measure=measure, meaning=meaning: (
                f"{key} = {measure[i]:.3g} > {VALIDITY_THRESHOLD}: {meaning} is not "
                "small, so the asymptotic solution is doubtful"))  # fmt: skip
    P_K = column("permanent_stick_load")
    no_tension = np.broadcast_to(np.asarray(cycle.eta) == 0.0, (rows,))
    add(no_tension & ~(P_K > 0), lambda i: (
        f"P_K = {P_K[i]:.6g} <= 0: the shear change exceeds friction over the whole cycle, "
        "so this is not a cycle of partial slip and b_exact does not exist"))  # fmt: skip
    exists = no_tension & (P_K > 0)
    b_exact = np.full(rows, np.nan)
    if exists.any():
        b_exact[exists] = law.half_width(P_K[exists])
    return texts, b_exact


def _single_edge(law: ContactLaw, cycle: LoadCycle, mu: float, edge: Edge) -> SlipZoneResult:
    arrays = edge_quantities(law, cycle, mu, edge)
    law.check_increasing(np.asarray(arrays["a1"]), np.asarray(arrays["a2"]))
    if denominator_vanishes(arrays, mu).any():
        raise InputError("mu", ZERO_DENOMINATOR_RULE, mu)
    (warnings,), (b_exact,) = edge_warnings(law, cycle, arrays)
    warnings.extend(law.load_warnings(float(cycle.P1), float(cycle.P2)))
    values = {key: float(value) for key, value in arrays.items() if key not in INTERNAL_KEYS}
    validity = {key: values.pop(key) for key in VALIDITY_MEANING}
    return SlipZoneResult(
        **values,
        b_exact=None if np.isnan(b_exact) else float(b_exact),
        validity=validity,
        warnings=warnings,
    )


def slip_zone(
    law: ContactLaw,
    cycle: LoadCycle,
    mu: float,
    *,
    edge: Literal["right", "left", "both"] = "right",
) -> SlipZoneResult:
    """Steady-state slip zone at a contact edge for one load cycle.

    Parameters
    ----------
    law
        The contact law, e.g. ``HertzLaw(R=1, E_star=1)``.
    cycle
        The load cycle (states 1 and 2, P2 > P1).
    mu
        Coefficient of friction, > 0.
    edge
        ``"right"`` (the paper's edge), ``"left"``, or ``"both"`` (right-edge fields at the
        top level and the left edge's in ``.left``).

    Returns
    -------
    SlipZoneResult
        b from (22), the slip-zone width a1 - b (cancellation-free), b/a1 to first order (28),
        the exact b = a(P_K) of (33)-(34) when eta = 0, and the validity measures (24)-(27).

    Raises
    ------
    InputError
        Naming the parameter and the rule: mu <= 0, non-finite values, a decreasing law, a zero
        denominator in (17).

    Examples
    --------
    >>> from asymslip import HertzLaw, LoadCycle, slip_zone
    >>> result = slip_zone(HertzLaw(R=1, E_star=1), LoadCycle(100, 0, 105, 1), mu=0.1)
    >>> round(result.slip_zone_width, 6)
    0.141908
    """
    mu = float(positive("mu", mu))
    if np.ndim(cycle.P1) or np.ndim(cycle.P2):
        raise InputError("cycle", "slip_zone takes one cycle; use asymslip sweep for many")
    if edge not in ("right", "left", "both"):
        raise InputError("edge", "must be 'right', 'left' or 'both'", edge)
    if edge == "left":
        return _single_edge(law, cycle, mu, "left")
    right = _single_edge(law, cycle, mu, "right")
    if edge == "both":
        left = _single_edge(law, cycle, mu, "left")
        return SlipZoneResult(**{**right.__dict__, "left": left})
    return right
