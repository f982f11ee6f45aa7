"""A vectorised inverse of an increasing function, NumPy only (no SciPy at run time)."""

from __future__ import annotations

from collections.abc import Callable

import numpy as np
from numpy.typing import NDArray

FloatArray = NDArray[np.float64]

_MAX_DOUBLINGS = 2100  # enough to walk from 1 to the ends of the double range


def invert_increasing(
    function: Callable[[FloatArray], FloatArray], target: FloatArray
) -> FloatArray:
    """Solve ``function(a) = target`` for a > 0, elementwise, for an increasing ``function``.

    Brackets each root by doubling/halving from a = 1, then bisects until the bracket is two
    adjacent doubles, so the result is correctly rounded up to the accuracy of ``function``.
    """
    target = np.asarray(target, dtype=np.float64)
    low = np.ones_like(target)
    high = np.ones_like(target)
    for _ in range(_MAX_DOUBLINGS):
        too_low = function(high) < target
        if not too_low.any():
            break
        high = np.where(too_low, 2 * high, high)
    for _ in range(_MAX_DOUBLINGS):
        too_high = function(low) > target
        if not too_high.any():
            break
        low = np.where(too_high, 0.5 * low, low)
    for _ in range(2 * 64):
        middle = 0.5 * (low + high)
        unresolved = (middle > low) & (middle < high)
        if not unresolved.any():
            break
        below = function(middle) < target
        low = np.where(unresolved & below, middle, low)
        high = np.where(unresolved & ~below, middle, high)
    # Pick the closer end of the final bracket.
    return np.where(np.abs(function(low) - target) <= np.abs(function(high) - target), low, high)
