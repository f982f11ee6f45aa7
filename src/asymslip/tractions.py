"""Shear-traction difference q_diff = q2 - q1 and slip displacement near an edge (Section 3.4).

The asymptotic (49) is evaluated in closed form (no quadrature); the exact (47) needs the
law's pressure distribution and exists for a symmetric law without bulk tension (eta = 0).

(49) is an *edge* asymptote: it rests on the first terms (4)-(5) of the edge expansions of the
pressure and the shear traction, whose first neglected terms are of relative size (a - x)/a
(for Hertz, p = L_I sqrt(a - x) sqrt(1 - (a - x)/(2a)): relative error (a - x)/(4a)).  So each
value is reported with ``near_edge``: True where the distance from the state-2 edge is at most
:data:`NEAR_EDGE_FRACTION` of the half-width a2 (the paper's own "10 % of the distance in from
the contact edge"), where the neglected terms are at most about a tenth of the leading one.
Measured on the paper's Fig. 5: the error of (49) against (47) is 5.7 % at that limit
(x = 0.9 a2) and 40 % at the centre.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Literal

import numpy as np
from numpy.typing import ArrayLike, NDArray

from asymslip_gen.slip_displacement import slip_on_loading
from asymslip_gen.tractions import jaeger_ciavarella_traction_difference, shear_traction_difference

from .core.edge_state import EdgeState
from .core.evaluation import Evaluation, evaluate
from .core.flags import warning_texts
from .cycle import LoadCycle
from .edge import Edge
from .errors import InputError, as_float_array, positive, require
from .laws.base import ContactLaw, modulus_of

StickBoundaryChoice = Literal["headline", "consistent", "exact"]
Side = Literal["right", "left"]

#: The slip sign convention, stated once (help texts, docstrings and the README quote it):
#: the paper's (38) as the project fixes it -- q is the shear traction on the indenter, so
#: friction on the indenter opposes the indenter's slip relative to the lower body.
SLIP_CONVENTION = (
    "delta = the change from state 1 to state 2 of u_x(indenter) - u_x(lower body) at x, "
    "along +x; q being the traction on the indenter, Coulomb friction opposes the indenter's "
    "slip, so in a slip zone delta has the sign opposite to q2 - q1"
)

#: Points within this fraction of a2 from the state-2 edge are "near the edge" (see above).
NEAR_EDGE_FRACTION = 0.1


@dataclass(frozen=True)
class TractionResult:
    """Shear-traction difference at the requested points; field names are the JSON keys.

    ``x`` is measured from the contact centre and ``q_diff`` is the traction component along
    +x (the global frame, for either edge).  ``near_edge`` says,
    for each point, whether it lies in the region where the edge asymptote (49) is meant to
    hold: ``near_edge_from`` <= x (right edge) or x <= -``near_edge_from`` (left edge).
    """

    edge: str
    x: list[float]
    q_diff: list[float]
    q_diff_exact: list[float | None] | None
    near_edge: list[bool]
    near_edge_from: float
    b: float
    stick_boundary: str
    warnings: list[str]

    def to_dict(self) -> dict[str, object]:
        return dict(self.__dict__)


@dataclass(frozen=True)
class SlipResult:
    """Slip displacement on loading at the requested points; field names are the JSON keys."""

    edge: str
    x: list[float]
    slip: list[float]
    b: float
    stick_boundary: str
    warnings: list[str]

    def to_dict(self) -> dict[str, object]:
        return dict(self.__dict__)


def _one_cycle(law: ContactLaw, cycle: LoadCycle, mu: float) -> Evaluation:
    evaluation = evaluate(law, cycle, mu)
    if evaluation.shape != ():
        raise InputError("cycle", "tractions are computed for one cycle at a time")
    evaluation.verdict.raise_first()
    return evaluation


def _edge_values(evaluation: Evaluation, edge: Edge) -> EdgeState:
    values = evaluation.edges[edge]
    if values.slip_direction == 0:
        raise InputError(
            "cycle",
            f"the {edge} edge does not slip (|lam + pi eta a2/4| <= mu): "
            "the traction difference is that of full stick, not (49)",
        )
    return values


def _positions(x: ArrayLike, edge: str, a2: float) -> tuple[np.ndarray, np.ndarray]:
    """(the points as given, the points measured along the edge's outward direction)."""
    points = as_float_array("x", x).ravel()
    outward = points if edge == "right" else -points
    edge_rule, far_rule = (
        (f"must be < a2 = {a2:.12g}", f"must be > -a2 = {-a2:.12g}")
        if edge == "right"
        else (f"must be > -a2 = {-a2:.12g}", f"must be < a2 = {a2:.12g}")
    )
    require(
        outward < a2, "x", f"{edge_rule} (the {edge} state-2 edge: (49) is singular there)", points
    )
    require(outward > -a2, "x", f"{far_rule} (inside the contact)", points)
    return points, outward


def _other_half(points: NDArray[np.float64], outward: NDArray[np.float64], edge: Edge) -> list[str]:
    """A warning for points on the other edge's half of the contact (outward coordinate < 0):
    an edge asymptote says nothing there, and a 0 or a value must not pass for an answer."""
    other = outward < 0
    if not other.any():
        return []
    shown = ", ".join(f"{value:.6g}" for value in points[other][:3].tolist())
    more = "" if int(other.sum()) <= 3 else f" and {int(other.sum()) - 3} more"
    return [
        f"x = {shown}{more} lie(s) on the {edge.other} half of the contact: they belong to the "
        f"{edge.other} edge, which this {edge} edge's asymptote does not describe (ask for "
        f"edge={edge.other.value!r}); the values given there are no answer"
    ]


def _stick_boundary(q: EdgeState, choice: StickBoundaryChoice) -> float:
    """The stick boundary b of one edge for ``stick_boundary`` (see traction_difference)."""
    if choice == "headline":
        return float(q.b)
    if choice == "consistent":
        return float(q.b_consistent)  # (17)/(22): the b for which the density (15) solves (12)
    if choice == "exact":
        if np.isnan(float(q.b_exact)):
            raise InputError(
                "b",
                "the exact stick boundary a(P_K) does not exist for this "
                "cycle (it needs a symmetric law and eta = 0)",
            )
        return float(q.b_exact)
    raise InputError("b", "must be 'headline', 'consistent' or 'exact'", choice)


def traction_difference(
    law: ContactLaw,
    cycle: LoadCycle,
    mu: float,
    x: ArrayLike,
    *,
    stick_boundary: StickBoundaryChoice = "headline",
    edge: Side = "right",
) -> TractionResult:
    """q2 - q1 near one edge: asymptotic (49) and, where it exists, exact (47).

    Parameters
    ----------
    law, cycle, mu
        As for :func:`asymslip.slip_zone` (one cycle).
    x
        Positions measured from the contact centre, inside the contact.
    stick_boundary
        ``"headline"`` (default): the headline b of :func:`asymslip.slip_zone` (b2, second
        order with both edges and bulk tension); ``"consistent"``: b from (17)/(22), for which
        the density (15) solves (12); ``"exact"``: b = a(P_K), the paper's choice for Fig. 5
        (needs eta = 0).  A b other than (17)'s adds the edge-singular term
        K (b - b17) / (2 sqrt(a2 - x)) to (49).
    edge
        ``"right"`` (the paper's) or ``"left"``.

    Returns
    -------
    TractionResult
        The values, whether each point is near the edge (where (49) is meant to hold), and
        the cycle's warnings at that edge.

    Examples
    --------
    >>> from asymslip import HertzLaw, LoadCycle
    >>> result = traction_difference(HertzLaw(1, 1), LoadCycle(100, 0, 105, 1), 0.1, [0.0])
    >>> round(result.q_diff_exact[0], 4)
    0.0281
    """
    side = Edge.named(edge)
    evaluation = _one_cycle(law, cycle, mu)
    q = _edge_values(evaluation, side)
    points, outward = _positions(x, edge, float(q.a2))
    b = _stick_boundary(q, stick_boundary)
    # Backward slip is forward slip of the reversed loads, with q_diff negated (edge_symmetry).
    direction = float(q.slip_direction)
    asymptotic = direction * shear_traction_difference(
        outward,
        b,
        float(q.a1),
        float(q.a2),
        mu,
        float(q.L_I1),
        float(q.L_I2),
        direction * float(q.L_II1),
        direction * float(q.L_II2),
    )
    exact = None
    if not np.isnan(float(q.b_exact)):
        # The wedge's pressure is infinite at its apex, so (47) is inf - inf there; a pressure
        # can also overflow (a huge contact).  Such points are left out below, not warned.
        with np.errstate(all="ignore"):
            try:
                pressures = [
                    law.pressure(points, P)
                    for P in (float(cycle.P2), float(cycle.P1), float(q.P_K))
                ]
            except NotImplementedError:
                pressures = None
            if pressures is not None:
                at_P2, at_P1, at_P_K = pressures
                exact = direction * jaeger_ciavarella_traction_difference(at_P2, at_P1, at_P_K, mu)
    near_from = float(q.a2) * (1 - NEAR_EDGE_FRACTION)
    flags = int(q.flags)
    warnings = warning_texts(flags, law.for_edge(side)) + _other_half(points, outward, side)
    exact_values = None
    if exact is not None:
        exact = np.asarray(exact, dtype=float) * np.ones(points.shape)
        defined = np.isfinite(exact)
        exact_values = [
            float(value) if ok else None
            for value, ok in zip(exact.tolist(), defined.tolist(), strict=True)
        ]
        if not defined.all():
            warnings.append(
                f"q_diff_exact (47) is left out (null) at {int((~defined).sum())} "
                "point(s) where it is not a finite double: the law's pressure is "
                "infinite there (the apex x = 0 of a wedge) or overflows"
            )
    # The left edge is the right edge of the mirrored cycle: back in the global frame a
    # traction along x changes sign.
    global_sign = side.sign
    return TractionResult(
        edge=side.value,
        x=points.tolist(),
        q_diff=(global_sign * np.asarray(asymptotic, dtype=float)).tolist(),
        q_diff_exact=None
        if exact_values is None
        else [None if value is None else global_sign * value for value in exact_values],
        near_edge=(outward >= near_from).tolist(),
        near_edge_from=near_from,
        b=float(b),
        stick_boundary=stick_boundary,
        warnings=warnings,
    )


def slip_displacement(
    law: ContactLaw,
    cycle: LoadCycle,
    mu: float,
    x: ArrayLike,
    *,
    E_star: float | None = None,
    stick_boundary: StickBoundaryChoice = "headline",
    edge: Side = "right",
) -> SlipResult:
    """Slip displacement accumulated on loading 1 -> 2 near one edge, from the density (15).

    Sign convention (:data:`SLIP_CONVENTION`, the one every command, file and docstring uses):
    delta(x) is the change from state 1 to state 2 of u_x(indenter) - u_x(lower body) at x,
    along +x in the global frame.  q is the traction the lower body exerts on the indenter
    (the paper's (38)), and Coulomb friction on the indenter opposes the indenter's slip
    relative to the lower body, so in a slip zone delta has the sign opposite to q2 - q1:
    forward slip at the right edge (q2 - q1 = mu (p2 + p1) > 0) gives delta < 0.  delta = 0
    in the stick zone; unloading takes the same slip back, so |delta| is the slip amplitude
    of the steady cycle (peak to peak).

    Parameters
    ----------
    law, cycle, mu, edge
        As for :func:`traction_difference`.
    x
        Positions measured from the contact centre, inside the contact.
    E_star
        Plane-strain modulus E* (the slip scales as 1/E*), for a law that does not define it
        (a table or module law); a law with its own E* is refused another.
    stick_boundary
        Where the slip starts: ``"headline"`` (default), the headline b of
        :func:`asymslip.slip_zone` (b2); ``"consistent"``, (17)/(22)'s b, for which (15)
        solves (12) exactly; ``"exact"``, a(P_K) (a symmetric law without tension).

    Notes
    -----
    Accuracy of the default.  (15) solves the integral equation (12) exactly only for the b of
    (17); evaluated with b = b2 its slip vanishes at the headline stick boundary (stated
    accuracy (da/a1)^2 |a1 - b|) and differs from (15) with (17)'s b by the shift of the
    stick boundary alone.  delta grows as (x - b)^(3/2) from b, so the shift changes the slip
    near the edge by a relative (3/2) |b2 - b17| / (x - b): without bulk tension
    |b2 - b17| is of second order, the order of b2's own correction, and so is the change
    ((3/2) (da/a1)^2 at most); with bulk tension (17) is right to first order only (erratum
    22-T) and the headline b is the better boundary.  Against the reference solver
    (``tests/test_slip_displacement.py``, N = 2000, b < x < a1): on Fig. 5's cycle within
    0.2 % of the largest slip; with tension (sigma2 = 0.2 on Fig. 5's loads) within 5.4 %
    (5.9 % with (17)'s b), the edge asymptote's own first-order error, and zero where the
    solver's slip is zero, where (17)'s b gives 0.7 % of the largest slip.
    """
    side = Edge.named(edge)
    evaluation = _one_cycle(law, cycle, mu)
    q = _edge_values(evaluation, side)
    own = modulus_of(law.for_edge(side))
    if E_star is not None and own is not None and float(E_star) != own:
        raise InputError(
            "E_star",
            f"the {law.name} law already has its modulus E* = {own:.6g}: give E_star only for a "
            "law that does not define one (a table or module law)",
            E_star,
        )
    if E_star is None:
        E_star = own
        if E_star is None:
            raise InputError(
                "E_star",
                f"is required for the slip displacement: the {law.name} "
                "law does not define the modulus E*",
            )
    E_star = float(positive("E_star", E_star))
    points, outward = _positions(x, edge, float(q.a2))
    b = _stick_boundary(q, stick_boundary)
    direction = float(q.slip_direction)
    # Along the edge's outward direction, then back to the global x (the left edge's outward
    # direction is -x, which flips the sign of a displacement measured along x).
    with np.errstate(all="ignore"):  # an overflow is refused below, not warned
        along = direction * slip_on_loading(
            outward,
            b,
            float(q.a1),
            mu,
            float(q.L_I1),
            float(q.L_I2),
            direction * float(q.L_II1),
            direction * float(q.L_II2),
            E_star,
        )
        # The integral of (15) is delta itself in the edge's outward frame: for a forward
        # slipping edge it is < 0 where q2 - q1 > 0, as Coulomb's law on the indenter wants
        # (and as the reference solver's own displacements give, tests/test_slip_displacement.py).
        slip = side.sign * np.asarray(along, dtype=float) + 0.0  # + 0.0: no -0 printed
        inverse_modulus = np.float64(1.0) / np.float64(E_star)
    if not np.isfinite(slip).all():
        if not np.isfinite(inverse_modulus):
            raise InputError(
                "E_star",
                "is too small: the slip displacement scales as 1/E*, "
                "which overflows double precision",
                E_star,
            )
        raise InputError(
            "cycle", "the slip displacement overflows double precision at these positions"
        )
    warnings = warning_texts(int(q.flags), law.for_edge(side)) + _other_half(points, outward, side)
    if b != float(q.b):
        warnings.append(
            f"the slip starts at the {stick_boundary} stick boundary b = {b:.12g}, not at the "
            f"headline b = {float(q.b):.12g}"
        )
    return SlipResult(
        edge=side.value,
        x=points.tolist(),
        slip=slip.tolist(),
        b=b,
        stick_boundary=stick_boundary,
        warnings=warnings,
    )
