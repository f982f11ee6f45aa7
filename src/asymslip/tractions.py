"""Shear-traction difference q_diff = q2 - q1 near the right-hand edge (Section 3.4).

The asymptotic (49) is evaluated in closed form (no quadrature); the exact (47) needs the
law's pressure distribution and exists for eta = 0 and 0 < P_K.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Literal

import numpy as np
from numpy.typing import ArrayLike

from asymslip_gen.tractions import shear_traction_difference

from .cycle import LoadCycle
from .edge_solution import edge_quantities, slip_zone
from .errors import InputError, as_float_array, require
from .laws.base import ContactLaw

StickBoundaryChoice = Literal["consistent", "exact"]


@dataclass(frozen=True)
class TractionResult:
    """Shear-traction difference at the requested points; field names are the JSON keys."""

    x: list[float]
    q_diff: list[float]
    q_diff_exact: list[float] | None
    b: float
    stick_boundary: str

    def to_dict(self) -> dict[str, object]:
        return {
            "x": self.x,
            "q_diff": self.q_diff,
            "q_diff_exact": self.q_diff_exact,
            "b": self.b,
            "stick_boundary": self.stick_boundary,
        }


def exact_traction_difference(
    law: ContactLaw, cycle: LoadCycle, mu: float, x: np.ndarray, P_K: float, direction: float
) -> np.ndarray | None:
    """(47): +-mu (p(x, P2) + p(x, P1) - 2 p(x, P_K)), or None where no exact solution exists.

    The sign is the direction of slip on loading (the reversal symmetry of edge_symmetry.py).
    """
    if float(cycle.eta) != 0.0 or P_K <= 0:
        return None
    try:
        pressures = [law.pressure(x, P) for P in (cycle.P2, cycle.P1, P_K)]
    except NotImplementedError:
        return None
    return direction * mu * (pressures[0] + pressures[1] - 2 * pressures[2])


def traction_difference(
    law: ContactLaw,
    cycle: LoadCycle,
    mu: float,
    x: ArrayLike,
    *,
    stick_boundary: StickBoundaryChoice = "consistent",
) -> TractionResult:
    """q2 - q1 at the right-hand edge, asymptotic (49) and exact (47).

    Parameters
    ----------
    law, cycle, mu
        As for :func:`asymslip.slip_zone`.
    x
        Positions measured from the contact centre, -a2 < x < a2.
    stick_boundary
        ``"consistent"``: b from (17)/(22), for which the density (15) solves (12);
        ``"exact"``: b = a(P_K), the paper's choice for Fig. 5 (needs eta = 0), which adds the
        edge-singular term K (b - b17) / (2 sqrt(a2 - x)) to (49).

    Examples
    --------
    >>> from asymslip import HertzLaw, LoadCycle
    >>> result = traction_difference(HertzLaw(1, 1), LoadCycle(100, 0, 105, 1), 0.1, [0.0])
    >>> round(result.q_diff_exact[0], 4)
    0.0281
    """
    summary = slip_zone(law, cycle, mu, edge="right")
    points = as_float_array("x", x).ravel()
    require(points < summary.a2, "x", "must be < a2 (the state-2 contact edge): (49) is "
            f"singular at x = a2 = {summary.a2:.12g}", points)  # fmt: skip
    require(points > -summary.a2, "x", f"must be > -a2 = {-summary.a2:.12g} (inside the contact)",
            points)  # fmt: skip
    if stick_boundary == "consistent":
        b = summary.b
    elif stick_boundary == "exact":
        if summary.b_exact is None:
            raise InputError("b", "the exact stick boundary a(P_K) does not exist for this "
                             "cycle (it needs eta = 0 and P_K > 0)")  # fmt: skip
        b = summary.b_exact
    else:
        raise InputError("b", "must be 'consistent' or 'exact'", stick_boundary)
    q = {key: float(value) for key, value in edge_quantities(law, cycle, mu).items()}
    direction = q["direction"]
    if direction == 0:
        raise InputError("b", "this edge does not slip (|lam + pi eta a2/4| <= mu): the "
                         "traction difference is that of full stick, not (49)")  # fmt: skip
    # Backward slip is forward slip of the reversed loads, with q_diff negated (edge_symmetry).
    asymptotic = direction * shear_traction_difference(
        points, b, q["a1"], q["a2"], mu, q["L_I1"], q["L_I2"], direction * q["L_II1"],
        direction * q["L_II2"],
    )  # fmt: skip
    exact = exact_traction_difference(law, cycle, mu, points, q["permanent_stick_load"],
                                      direction)  # fmt: skip
    return TractionResult(
        x=points.tolist(),
        q_diff=np.asarray(asymptotic, dtype=float).tolist(),
        q_diff_exact=None if exact is None else np.asarray(exact, dtype=float).tolist(),
        b=float(b),
        stick_boundary=stick_boundary,
    )
