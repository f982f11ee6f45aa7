"""The solver's conventions, in the project's words, stated once for every output.

The CSV files (a comment line), the JSON (``conventions``), the figure's labels and the
docstrings all use these words.  The relations behind them are derived in
``derivations/solver_influence.py``: there the traction q acts on body 1 and the slip is
u_x2 - u_x1, so body 1 is the lower body and body 2 the indenter; the differential bulk
tension of that derivation, sigma_2 - sigma_1, is then the indenter's bulk tension minus the
lower body's -- the sign with which Q and sigma both raise K_II at the right edge, as in the
paper's (20) and (38).

Examples
--------
>>> from asymslip.solver.conventions import CONVENTIONS
>>> print(CONVENTIONS["slip"])  # doctest: +ELLIPSIS
slip: the change of u_x(indenter) - u_x(lower body) at x, along +x, ... sign of q2 - q1 ...
"""

from __future__ import annotations

from types import MappingProxyType

#: Quantity -> its convention, one sentence each (read-only).
CONVENTIONS = MappingProxyType(
    {
        "x": "x: position from the contact centre (the profile's origin), right edge at +a, "
        "left edge at -a; b and a are reported as distances outward from the centre",
        "q": "q: the shear traction exerted by the indenter on the lower body's surface, "
        "along +x (the integral of q dx is Q); p >= 0 the contact pressure",
        "slip": "slip: the change of u_x(indenter) - u_x(lower body) at x, along +x, since "
        "point 1 of the steady period (for the paper's cycle: from state 1 to state 2); in a "
        "slip zone it has the sign of q2 - q1 (Coulomb: the sliding body drags the other one "
        "along its own slip)",
        "sigma": "sigma: the differential bulk tension with the sign of the paper's (20) and "
        "(38), Q and sigma both raising K_II at the right edge; with q as above that is the "
        "indenter's bulk tension minus the lower body's",
        "energy": "energy: frictional energy dissipated per period per unit area of the "
        "interface, the sum over the steps of q times the slip increment (>= 0)",
    }
)


def comment_line() -> str:
    """The conventions as one line for a file's header."""
    return "conventions: " + "; ".join(CONVENTIONS.values())
