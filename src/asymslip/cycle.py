"""The steady-state load cycle of the paper's Fig. 3: a straight line between states 1 and 2."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .errors import as_float_array, positive, require

FloatArray = NDArray[np.float64]


@dataclass(frozen=True, init=False)
class LoadCycle:
    """Load states (P1, Q1, sigma1) and (P2, Q2, sigma2) joined by a straight line (2)-(3).

    Attributes may be arrays (broadcast together) to describe many cycles at once.

    Parameters
    ----------
    P1, P2
        Normal loads per unit length at the two ends, 0 < P1 < P2.  The paper takes state 2 as
        the one with the larger normal load; a cycle given the other way round must be entered
        with its states swapped (the steady state does not depend on the direction of travel).
    Q1, Q2
        Shear forces per unit length at the two ends.
    sigma1, sigma2
        Differential bulk tensions at the two ends (default 0).

    Examples
    --------
    >>> cycle = LoadCycle(P1=100, Q1=0, P2=105, Q2=1)
    >>> float(cycle.lam), float(cycle.eta)
    (0.2, 0.0)
    """

    P1: FloatArray
    Q1: FloatArray
    P2: FloatArray
    Q2: FloatArray
    sigma1: FloatArray
    sigma2: FloatArray

    def __init__(self, P1: ArrayLike, Q1: ArrayLike, P2: ArrayLike, Q2: ArrayLike,
                 sigma1: ArrayLike = 0.0, sigma2: ArrayLike = 0.0) -> None:
        values = {
            "P1": positive("P1", P1),
            "Q1": as_float_array("Q1", Q1),
            "P2": positive("P2", P2),
            "Q2": as_float_array("Q2", Q2),
            "sigma1": as_float_array("sigma1", sigma1),
            "sigma2": as_float_array("sigma2", sigma2),
        }
        require(values["P2"] > values["P1"], "P2",
                "must exceed P1: state 2 is the state with the larger normal load "
                "(swap the two states; for P2 == P1 the paper's analysis does not apply)",
                values["P2"])
        for name, value in values.items():
            object.__setattr__(self, name, value)

    @property
    def dP(self) -> FloatArray:
        """Normal-load change P2 - P1 > 0 (3)."""
        return self.P2 - self.P1

    @property
    def dQ(self) -> FloatArray:
        """Shear-force change Q2 - Q1 (3)."""
        return self.Q2 - self.Q1

    @property
    def dsigma(self) -> FloatArray:
        """Bulk-tension change sigma2 - sigma1 (3)."""
        return self.sigma2 - self.sigma1

    @property
    def lam(self) -> FloatArray:
        """lambda = dQ/dP (18)."""
        return self.dQ / self.dP

    @property
    def eta(self) -> FloatArray:
        """eta = dsigma/dP (18)."""
        return self.dsigma / self.dP
