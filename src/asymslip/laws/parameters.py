"""The numbers that define a contact law (R, E*, c, A, n, a module's parameters), checked once.

A law has one value of each parameter: arrays broadcast over *cycles*, never over laws, so an
array, a missing value (``None``), text, a complex number or a boolean is refused with an
:class:`~asymslip.errors.InputError` naming the parameter and the rule, never a TypeError
from NumPy.

Examples
--------
>>> import numpy as np
>>> from asymslip.laws.parameters import law_parameter
>>> law_parameter("R", np.float64(2.5))
2.5
>>> law_parameter("R", np.array([1.0, 2.0]))  # doctest: +ELLIPSIS
Traceback (most recent call last):
    ...
asymslip.errors.InputError: R: must be one number, not an array of 2 (a law has one value ...
>>> law_parameter("E_star", None)
Traceback (most recent call last):
    ...
asymslip.errors.InputError: E_star: is missing: a law needs a value of each of its parameters
"""

from __future__ import annotations

import numpy as np

from ..errors import InputError, as_float_array, positive


def law_parameter(name: str, value: object) -> float:
    """``value`` as a finite float, or an :class:`InputError` naming ``name``.

    Raises
    ------
    InputError
        ``None`` (missing), a boolean, text, a complex number, an array or sequence (even of one
        element), or a value that is not finite.
    """
    if value is None:
        raise InputError(name, "is missing: a law needs a value of each of its parameters")
    if isinstance(value, bool | np.bool_):
        raise InputError(name, "must be a number, not True or False", value)
    if isinstance(value, str | bytes | complex | np.complexfloating):
        raise InputError(name, "must be a real number", value)
    if isinstance(value, np.ndarray | list | tuple) and np.shape(value):
        array = np.asarray(value)
        if np.iscomplexobj(array):
            raise InputError(name, "must be a real number", value)
        shape = array.shape
        shown = array.tolist() if array.size <= 4 else None
        raise InputError(
            name,
            f"must be one number, not an array of {int(np.prod(shape))} (a law has one value "
            "of each parameter: make one law per value)",
            shown,
        )
    return float(as_float_array(name, value))


def positive_parameter(name: str, value: object) -> float:
    """:func:`law_parameter` that must also be > 0."""
    return float(positive(name, law_parameter(name, value)))
