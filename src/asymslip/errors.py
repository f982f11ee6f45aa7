"""The error raised for invalid physical input, and the checks that raise it."""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray


class InputError(ValueError):
    """Invalid input: the message names the parameter and the rule it broke."""

    def __init__(self, parameter: str, rule: str, value: object | None = None) -> None:
        self.parameter = parameter
        self.rule = rule
        shown = "" if value is None else f" (got {value!r})"
        super().__init__(f"{parameter}: {rule}{shown}")


def _first_offender(values: NDArray[np.float64], bad: NDArray[np.bool_]) -> object:
    if values.ndim == 0:
        return float(values)
    index = int(np.flatnonzero(bad.ravel())[0])
    return f"{float(values.ravel()[index])!r} at index {index}"


def as_float_array(parameter: str, value: ArrayLike) -> NDArray[np.float64]:
    """Convert to a float64 array, refusing non-numbers and non-finite values."""
    try:
        array = np.asarray(value, dtype=np.float64)
    except (TypeError, ValueError):
        raise InputError(parameter, "must be a real number or an array of them", value) from None
    finite = np.isfinite(array)
    if not finite.all():
        raise InputError(parameter, "must be finite", _first_offender(array, ~finite))
    return array


def positive(parameter: str, value: ArrayLike) -> NDArray[np.float64]:
    """A finite array whose every element is > 0."""
    array = as_float_array(parameter, value)
    bad = ~(array > 0)
    if bad.any():
        raise InputError(parameter, "must be > 0", _first_offender(array, bad))
    return array


def require(condition: NDArray[np.bool_] | bool, parameter: str, rule: str,
            shown: NDArray[np.float64] | float | None = None) -> None:
    """Raise :class:`InputError` unless ``condition`` holds everywhere."""
    condition = np.asarray(condition)
    if not condition.all():
        value = None
        if shown is not None:
            value = _first_offender(np.broadcast_to(np.asarray(shown, dtype=float),
                                                    condition.shape), ~condition)
        raise InputError(parameter, rule, value)
