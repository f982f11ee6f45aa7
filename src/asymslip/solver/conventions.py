"""The solver's conventions, in the project's words, stated once for every output.

The CSV files (a comment line), the JSON (``conventions``), the figure's labels and the
docstrings all use these words: the paper's (38) as the project fixes it.  q is the shear
traction the lower body exerts on the indenter and Q = int q dx the shear force on the
indenter (what a load cell on the pad holder reads); sigma is the lower body's bulk tension
minus the indenter's; Q > 0 and sigma > 0 both raise K_II at the right edge.  The slip delta is
the change of u_x(indenter) - u_x(lower body); Coulomb friction on the indenter opposes the
indenter's slip, so in a slip zone delta has the sign opposite to q2 - q1.

The relations behind them are derived in ``derivations/solver_influence.py`` for a body 1
carrying the traction q and a body 2 carrying -q, with the relative displacement
s = u_x2 - u_x1 and the differential tension sigma_2 - sigma_1.  The two bodies being
elastically similar half-planes, those relations do not depend on which body is which; the
solver takes body 1 to be the indenter.  Then q is the traction on the indenter, sigma_2 -
sigma_1 the lower body's tension minus the indenter's (the sign of (38)), and the slip it
reports is delta = u_x(indenter) - u_x(lower body) = -s (:mod:`asymslip.solver.steady`).

Examples
--------
>>> from asymslip.solver.conventions import CONVENTIONS
>>> print(CONVENTIONS["slip"])  # doctest: +ELLIPSIS
slip: the change of u_x(indenter) - u_x(lower body) at x, along +x, ... opposite to q2 - q1 ...
"""

from __future__ import annotations

from types import MappingProxyType

#: Quantity -> its convention, one sentence each (read-only).
CONVENTIONS = MappingProxyType(
    {
        "x": "x: position from the contact centre (the profile's origin), right edge at +a, "
        "left edge at -a; b and a are reported as distances outward from the centre",
        "q": "q: the shear traction exerted on the indenter by the lower body, along +x (the "
        "integral of q dx is Q, the shear force on the indenter); the lower body's surface "
        "carries -q; p >= 0 the contact pressure",
        "slip": "slip: the change of u_x(indenter) - u_x(lower body) at x, along +x, since "
        "point 1 of the steady period (for the paper's cycle: from state 1 to state 2); in a "
        "slip zone it has the sign opposite to q2 - q1 (Coulomb: friction on the indenter "
        "opposes its slip)",
        "sigma": "sigma: the differential bulk tension with the sign of the paper's (20) and "
        "(38), Q and sigma both raising K_II at the right edge: the lower body's bulk tension "
        "minus the indenter's",
        "energy": "energy: frictional energy dissipated per period per unit area of the "
        "interface, the sum over the steps of -q times the slip increment (>= 0)",
    }
)


def comment_line() -> str:
    """The conventions as one line for a file's header."""
    return "conventions: " + "; ".join(CONVENTIONS.values())
