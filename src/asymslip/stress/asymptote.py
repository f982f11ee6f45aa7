"""The stress amplitude near one contact edge from the paper's edge asymptotes, no solver.

Near an edge the amplitude of the cycle (state 2 minus state 1; conventions:
:mod:`asymslip.stress`) is the field of square-root loads on half-lines, derived in
``derivations/stress_edge_asymptote.py``:

* the pressure change of (4): L_I2 at a2 and -L_I1 at a1;
* the shear change of (49) with b from (17) (for which (15) solves (12)): mu L_I2 at a2,
  mu L_I1 at a1 and -K at b (EA-4), in the paper's frame -- the traction on the indenter, in
  the edge's slip direction; the lower body carries its negative.  An edge that does not
  slip carries the full-stick change (6): L_II2 at a2 and -L_II1 at a1;
* a uniform sxx of dsigma/2, the stick zone's strain compatibility (EA-3).

Each load's field is the edge eigenfield (EA-1, EA-2), summed in the edge's outward frame
(x along the outward direction, depth y) and turned back to the global frame (for the left
edge sxy changes sign).

How far to trust it
-------------------
The neglected terms are the next ones of the same expansions (EA-6): each load's next term
(c - t)^(3/2), with the coefficients M_I of the law's pressure (the slip zone's tractions are
mu times it) and M_II of the full-stick shear; the stick boundary's load takes their
combination mu (M_I1 + M_I2) + M_II1 - M_II2, as K does.  The stated accuracy of every
component at a point is ``SAFETY`` times the largest component of their field there, plus the
field of moving the stick boundary by the uncertainty of b (|b17 - b| plus the headline's
stated accuracy) -- a bound that grows with the distance from the edge.  On the paper's Fig. 5
cycle the actual error against the exact Jaeger-Ciavarella field is 0.99-1.08 times the
next-order field (EA-5); over the near-edge error map (``asymslip.stress.error_map``) the error
stays within 0.95 of the stated accuracy near the edge wherever the shear force drives the slip
at least as much as the bulk tension, and reaches 2.4 times it where the tension dominates
(pi eta a1/(4 mu) > |lam/mu|), which a warning says.  Points farther than
``NEAR_EDGE_FRACTION`` of the edge's length scale from the edge (the contact half-width, or
1/|k_p| when the law's pressure departs from its square root sooner, as on a rounded flat) are
flagged (``near_edge`` False, and a warning); points as far from the edge as the middle of the
contact half (``FARTHEST`` a1) are refused.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import Literal

import numpy as np
from numpy.typing import ArrayLike

from asymslip_gen.corrective_slip import slip_zone_width_from_multipliers
from asymslip_gen.edge_stress import (
    edge_eigenfield_pressure_sxx,
    edge_eigenfield_pressure_sxy,
    edge_eigenfield_pressure_syy,
    edge_eigenfield_shear_sxx,
    edge_eigenfield_shear_sxy,
    edge_eigenfield_shear_syy,
    edge_pressure_next_coefficient,
    edge_shear_amplitude_state1,
    edge_shear_amplitude_state2,
    edge_shear_amplitude_stick,
    edge_shear_next_coefficient,
    edge_uniform_sxx,
)

from ..cycle import LoadCycle
from ..errors import InputError
from ..laws.base import ContactLaw
from ..slip_zones import SlipZoneResult, slip_zone
from ..tractions import NEAR_EDGE_FRACTION
from .field import COMPONENTS, CycleStress, FloatArray, StressField
from .half_plane import points

Side = Literal["right", "left"]
SOURCE = "asymptote"
#: Stated accuracy = SAFETY x the next-order field (measured 0.99-1.08 of it on Fig. 5).
SAFETY = 2.0
#: Points farther than this many a1 from the edge are refused.
FARTHEST = 0.5

_EIGENFIELDS: dict[str, tuple[Callable[..., object], Callable[..., object]]] = {
    "sxx": (edge_eigenfield_pressure_sxx, edge_eigenfield_shear_sxx),
    "syy": (edge_eigenfield_pressure_syy, edge_eigenfield_shear_syy),
    "sxy": (edge_eigenfield_pressure_sxy, edge_eigenfield_shear_sxy),
}


@dataclass(frozen=True)
class EdgeLoad:
    """A square-root load (c - t)^power on t < c in the edge's outward frame: its edge c, and
    its pressure and shear amplitudes on the lower body."""

    edge: float
    pressure: float
    shear: float


@dataclass(frozen=True)
class EdgeLoads:
    """Everything the field of one edge needs, in its outward frame."""

    side: Side
    a1: float
    a2: float
    b: float | None
    loads: tuple[EdgeLoad, ...]  # power 1/2: the amplitude
    next_loads: tuple[EdgeLoad, ...]  # power 3/2: the neglected next terms
    boundary_strength: float  # |K|, the stick boundary's load
    boundary_uncertainty: float  # how far b may lie from b17
    uniform: float  # the amplitude's uniform sxx
    length_scale: float  # where the square root (4) holds: min(a1, 1/|k_p|)
    warnings: tuple[str, ...]


def _polar_parts(offset: FloatArray, y: FloatArray, power: float) -> tuple[FloatArray, ...]:
    """The arguments of EA-2's fields at w = offset - i y = rho e^(i phi), phi in [-pi, 0]:
    rho^lam, cos(lam phi), sin(lam phi), sin(-phi), cos((lam-1) phi), sin((lam-1) phi).

    Every term of those fields is rho^lam times one angle factor (or sin(-phi) times one), so
    rho^lam may be passed as 1 with the angle factors multiplied by it.  For lam = 1/2 and 3/2
    that product is algebraic -- sqrt(w) = A + i B with A = sqrt((rho + x)/2), B =
    -sqrt((rho - x)/2), and w sqrt(w) -- which avoids the trigonometric functions (five times
    faster).  sin(-phi) = y/rho is 0 at the edge itself.
    """
    rho = np.hypot(offset, y)
    sine = np.divide(y, rho, out=np.zeros_like(rho), where=rho > 0)
    if power in (0.5, 1.5):
        A = np.sqrt(0.5 * (rho + offset))
        B = -np.sqrt(np.maximum(0.5 * (rho - offset), 0.0))
        if power == 0.5:  # rho^(1/2) e^(i phi/2), and e^(-i phi/2) = conj: (A, -B)
            return np.ones_like(rho), A, B, sine, A, -B
        # rho^(3/2) e^(3 i phi/2) = w sqrt(w); rho^(3/2) e^(i phi/2) = rho sqrt(w)
        return np.ones_like(rho), offset * A + y * B, offset * B - y * A, sine, rho * A, rho * B
    return _trigonometric_parts(offset, y, power)


def _trigonometric_parts(offset: FloatArray, y: FloatArray, power: float) -> tuple[FloatArray, ...]:
    """The same parts by trigonometric functions (tests compare the two)."""
    rho = np.hypot(offset, y)
    sine = np.divide(y, rho, out=np.zeros_like(rho), where=rho > 0)
    phi = np.arctan2(-y, offset)
    angle = power * phi
    slope = angle - phi
    return rho**power, np.cos(angle), np.sin(angle), sine, np.cos(slope), np.sin(slope)


def _field(
    loads: Sequence[EdgeLoad], X: FloatArray, y: FloatArray, power: float
) -> dict[str, FloatArray]:
    """sxx, syy, sxy of the loads (c - t)^power at outward positions X, depth y."""
    result = {name: np.zeros_like(X) for name in COMPONENTS}
    for load in loads:
        parts = _polar_parts(X - load.edge, y, power)
        for name, (pressure, shear) in _EIGENFIELDS.items():
            if load.pressure != 0:
                result[name] += load.pressure * np.asarray(pressure(*parts, power))
            if load.shear != 0:
                result[name] += load.shear * np.asarray(shear(*parts, power))
    return result


def edge_loads(law: ContactLaw, cycle: LoadCycle, mu: float, edge: Side = "right") -> EdgeLoads:
    """The square-root loads of one edge's amplitude, from :func:`asymslip.slip_zone`."""
    if edge not in ("right", "left"):
        raise InputError("edge", "must be 'right' or 'left'", edge)
    both = slip_zone(law, cycle, mu, edge="both")  # checks both edges, raises if invalid
    result: SlipZoneResult = both if edge == "right" else both.left  # type: ignore[assignment]
    if np.ndim(result.a1):
        raise InputError("cycle", "the stress field is computed for one cycle at a time")
    a1, a2 = float(result.a1), float(result.a2)
    L_I1, L_I2 = float(result.L_I1), float(result.L_I2)
    L_II1, L_II2 = float(result.L_II1), float(result.L_II2)
    direction = int(result.slip_direction)
    lam, eta = float(result.lam), float(result.eta)
    state = law.for_edge(edge).cycle_state(float(cycle.P1), float(cycle.P2) - float(cycle.P1))
    slopes = [
        float(state.L_I_slope1 * state.load_slope1),
        float(state.L_I_slope2 * state.load_slope2),
    ]
    M_I1 = float(edge_pressure_next_coefficient(a1, L_I1, slopes[0]))
    M_I2 = float(edge_pressure_next_coefficient(a2, L_I2, slopes[1]))
    M_II1 = float(edge_shear_next_coefficient(a1, lam, eta, L_I1, slopes[0]))
    M_II2 = float(edge_shear_next_coefficient(a2, lam, eta, L_I2, slopes[1]))
    warnings = [str(w) for w in result.warnings]
    tension = np.pi * eta * a1 / (4 * mu)  # the tension's share of L_II/L_I (21), over mu
    if abs(tension) > abs(lam / mu):
        warnings.append(
            f"the bulk tension drives this edge's slip more than the shear force (pi eta a1/"
            f"(4 mu) = {tension:.3g} against lam/mu = {lam / mu:.3g}): there the near-edge "
            "error map measured errors up to 2.4 times the stated accuracy, which holds to 0.95 "
            "of it where the shear force dominates"
        )
    pressure: tuple[EdgeLoad, ...] = (EdgeLoad(a2, L_I2, 0.0), EdgeLoad(a1, -L_I1, 0.0))  # (4)
    next_pressure: tuple[EdgeLoad, ...] = (EdgeLoad(a2, M_I2, 0.0), EdgeLoad(a1, -M_I1, 0.0))
    shear: tuple[EdgeLoad, ...]
    next_shear: tuple[EdgeLoad, ...]
    if direction == 0:
        # No slip at this edge: the full-stick change (6), on the lower body.
        b = None
        shear = (EdgeLoad(a2, 0.0, -L_II2), EdgeLoad(a1, 0.0, L_II1))
        next_shear = (EdgeLoad(a2, 0.0, -M_II2), EdgeLoad(a1, 0.0, M_II1))
        strength, uncertainty = 0.0, 0.0
    else:
        # The paper's frame is forward slip: backward slip is forward slip of the reversed
        # shear loads, with q_diff negated (derivations/edge_symmetry.py).
        d = float(direction)
        width = float(
            slip_zone_width_from_multipliers(mu, a2 - a1, L_I1, L_I2, d * L_II1, d * L_II2)
        )
        b = a1 - width  # (17), for which (15) solves (12)
        stick = float(edge_shear_amplitude_stick(L_I1, L_I2, d * L_II1, d * L_II2, mu))
        # The lower body carries -d times the paper's traction (conventions).
        shear = (
            EdgeLoad(a2, 0.0, -d * float(edge_shear_amplitude_state2(L_I2, mu))),
            EdgeLoad(a1, 0.0, -d * float(edge_shear_amplitude_state1(L_I1, mu))),
            EdgeLoad(b, 0.0, -d * stick),
        )
        next_stick = -(mu * (M_I1 + M_I2) + d * M_II1 - d * M_II2)
        next_shear = (
            EdgeLoad(a2, 0.0, -d * mu * M_I2),
            EdgeLoad(a1, 0.0, -d * mu * M_I1),
            EdgeLoad(b, 0.0, -d * next_stick),
        )
        strength = abs(stick)
        uncertainty = abs(b - float(result.b)) + float(result.b_accuracy)
    kappa = abs(M_I1 / L_I1)
    length = min(a1, 1.0 / kappa) if kappa > 0 else a1
    return EdgeLoads(
        side=edge,
        a1=a1,
        a2=a2,
        b=b,
        loads=pressure + shear,
        next_loads=next_pressure + next_shear,
        boundary_strength=strength,
        boundary_uncertainty=uncertainty,
        uniform=float(edge_uniform_sxx(float(cycle.sigma2) - float(cycle.sigma1))),
        length_scale=length,
        warnings=tuple(warnings),
    )


def _boundary_error(loads: EdgeLoads, X: FloatArray, y: FloatArray) -> FloatArray:
    """The largest component of |K| db times the field of d/db sqrt(b - t), at the point or,
    within db of b, at the same angle db away (the field of a moved root is bounded there)."""
    if loads.b is None or loads.boundary_uncertainty == 0:
        return np.zeros_like(X)
    db = loads.boundary_uncertainty
    offset = X - loads.b
    distance = np.hypot(offset, y)
    scale = np.where(distance < db, db / np.maximum(distance, db * 1e-300), 1.0)
    offset = np.where(distance == 0, -db, offset * scale)
    depth = np.where(distance == 0, 0.0, y * scale)
    derivative = EdgeLoad(0.0, 0.0, 0.5 * loads.boundary_strength * db)
    shifted = _field([derivative], offset, depth, -0.5)
    largest: FloatArray = np.max(np.abs(np.stack(list(shifted.values()))), axis=0)
    return largest


def edge_amplitude(
    law: ContactLaw,
    cycle: LoadCycle,
    mu: float,
    x: ArrayLike,
    depth: ArrayLike,
    *,
    edge: Side = "right",
    accuracy: bool = True,
) -> CycleStress:
    """The amplitude (state 2 minus state 1) of the stress near one edge, from (4) and (49).

    Parameters
    ----------
    law, cycle, mu
        As for :func:`asymslip.slip_zone` (one cycle; both edges are checked).
    x, depth
        The points (broadcast together), x from the contact centre, depth >= 0.
    edge
        ``"right"`` or ``"left"``.
    accuracy
        Compute each point's stated accuracy (the default; about half the time).

    Returns
    -------
    CycleStress
        ``amplitude`` at every point, ``accuracy`` (a bound on the error of every component),
        ``near_edge`` and the warnings; no states (the asymptote gives the change over the
        cycle only: the locked-in shear of each state depends on the history).

    Examples
    --------
    >>> from asymslip import HertzLaw, LoadCycle
    >>> field = edge_amplitude(HertzLaw(1, 1), LoadCycle(100, 0, 105, 1), 0.1, [11.5], [0.02])
    >>> bool(field.near_edge[0]), round(float(field.amplitude.syy[0]), 3)
    (True, -0.584)
    """
    xs, ys = points(x, depth)
    loads = edge_loads(law, cycle, mu, edge)
    sign = 1.0 if edge == "right" else -1.0
    X = sign * xs  # outward
    distance = np.hypot(X - loads.a2, ys)
    far = distance > FARTHEST * loads.a1
    if far.any():
        index = int(np.flatnonzero(far)[0])
        raise InputError(
            "x",
            f"must lie within {FARTHEST:g} a1 = {FARTHEST * loads.a1:.6g} of the {edge} edge "
            f"(x = {sign * loads.a2:.6g}, depth 0) for the edge asymptote; the point "
            f"({xs[index]:.6g}, {ys[index]:.6g}) is {distance[index]:.6g} from it -- use the "
            "solver (source solver) away from the edges",
        )
    field = _field(loads.loads, X, ys, 0.5)
    field["sxx"] = field["sxx"] + loads.uniform
    field["sxy"] = sign * field["sxy"]  # back to the global frame
    amplitude = StressField(xs, ys, field["sxx"], field["syy"], field["sxy"])
    near = distance <= NEAR_EDGE_FRACTION * loads.length_scale
    warnings = list(loads.warnings)
    if not near.all():
        warnings.append(
            f"{int((~near).sum())} of {near.size} point(s) lie farther than "
            f"{NEAR_EDGE_FRACTION:g} x {loads.length_scale:.6g} (the length over which the "
            "edge's pressure keeps its square-root form) from the edge: near_edge is false "
            "there and the stated accuracy grows with the distance"
        )
    stated = None
    if accuracy:
        following = _field(loads.next_loads, X, ys, 1.5)
        largest = np.max(np.abs(np.stack(list(following.values()))), axis=0)
        stated = SAFETY * (largest + _boundary_error(loads, X, ys))
    return CycleStress(
        source=SOURCE,
        edge=edge,
        x=xs,
        depth=ys,
        states=(),
        labels=(),
        amplitude=amplitude,
        accuracy=stated,
        near_edge=near,
        warnings=tuple(warnings),
    )
