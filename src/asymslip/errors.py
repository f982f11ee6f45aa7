"""The error raised for invalid physical input, and the checks that raise it.

Examples
--------
>>> from asymslip.errors import InputError, positive
>>> positive("mu", [0.3, -0.1])
Traceback (most recent call last):
    ...
asymslip.errors.InputError: mu: must be > 0 (got -0.1; at element 1)
>>> isinstance(InputError("P1", "must be finite"), ValueError)
True
"""

from __future__ import annotations

from typing import cast

import numpy as np
from numpy.typing import ArrayLike, NDArray


class InputError(ValueError):
    """Invalid input: the message names the parameter and the rule it broke."""

    def __init__(
        self, parameter: str, rule: str, value: object | None = None, where: str = ""
    ) -> None:
        self.parameter = parameter
        self.rule = rule
        self.value = value
        self.where = where
        got = [] if value is None else [f"got {value!r}"]
        notes = "; ".join([*got, *([where] if where else [])])
        super().__init__(f"{parameter}: {rule}" + (f" ({notes})" if notes else ""))


def _first_offender(values: NDArray[np.float64], bad: NDArray[np.bool_]) -> tuple[object, str]:
    """(the value to show, where it is) of the first bad element.

    A non-finite value is not shown: the rule says what is wrong with it, and a message
    should never print inf or nan as though it were a number.
    """
    index = int(np.flatnonzero(bad.ravel())[0]) if values.ndim else 0
    value = float(values.ravel()[index]) if values.ndim else float(values)
    where = f"at element {index}" if values.ndim else ""
    return (value if np.isfinite(value) else None), where


def as_numbers(parameter: str, value: object) -> NDArray[np.float64]:
    """Convert to a float64 array, refusing what is not a real number (not yet non-finite ones:
    :mod:`asymslip.rules` checks those per element).

    None is missing, not a number; a masked array's masked elements are refused (they have no
    value to compute with); an integer beyond double precision is refused as such.
    """
    if type(value) is float:  # the common case, without NumPy's checks
        return np.asarray(value)
    if value is None:
        raise InputError(parameter, "is missing (None): give a number or an array of them")
    if type(value) is int:
        return np.asarray(_integer(parameter, value))
    if isinstance(value, (str, bytes)) or np.iscomplexobj(cast(ArrayLike, value)):
        raise InputError(parameter, "must be a real number or an array of them", value)
    if isinstance(value, np.ma.MaskedArray):
        masked = np.ma.getmaskarray(value)
        if masked.any():
            index = int(np.flatnonzero(masked.ravel())[0])
            raise InputError(
                parameter,
                "has masked elements, which have no value: fill them (numpy.ma.filled) or "
                "leave them out",
                where=f"at element {index}" if masked.ndim else "",
            )
        value = np.ma.getdata(value)
    try:
        return np.asarray(value, dtype=np.float64)
    except OverflowError:
        raise InputError(parameter, _BEYOND_DOUBLE) from None
    except (TypeError, ValueError):
        raise InputError(parameter, "must be a real number or an array of them", value) from None


_BEYOND_DOUBLE = "must be finite: it is beyond double precision (about 1.8e308)"


def _integer(parameter: str, value: int) -> float:
    """A Python integer as a float, refused where it is beyond double precision."""
    try:
        return float(value)
    except OverflowError:
        raise InputError(parameter, _BEYOND_DOUBLE) from None


def as_float_array(parameter: str, value: object) -> NDArray[np.float64]:
    """Convert to a float64 array, refusing non-numbers and non-finite values."""
    array = as_numbers(parameter, value)
    finite = np.isfinite(array)
    if not finite.all():
        raise InputError(
            parameter, "must be finite (not inf or nan)", *_first_offender(array, ~finite)
        )
    return array


def positive(parameter: str, value: ArrayLike) -> NDArray[np.float64]:
    """A finite array whose every element is > 0."""
    array = as_float_array(parameter, value)
    bad = ~(array > 0)
    if bad.any():
        raise InputError(parameter, "must be > 0", *_first_offender(array, bad))
    return array


def require(
    condition: NDArray[np.bool_] | bool,
    parameter: str,
    rule: str,
    shown: NDArray[np.float64] | float | None = None,
) -> None:
    """Raise :class:`InputError` unless ``condition`` holds everywhere."""
    condition = np.asarray(condition)
    if not condition.all():
        value, where = None, ""
        if shown is not None:
            value, where = _first_offender(
                np.broadcast_to(np.asarray(shown, dtype=float), condition.shape), ~condition
            )
        raise InputError(parameter, rule, value, where)
