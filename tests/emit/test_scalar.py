"""The ``math`` kernels for one value at a time (``asymslip_gen.scalar``) equal the NumPy ones.

Same records, same CSE'd bodies, printed for ``math`` instead of ``numpy``: at the points of
each function's documented domain (``domains.py``, the points the other languages use) every
value agrees with NumPy's to 1e-13 relative, the tolerance of the C, Fortran and Octave
comparisons; most are identical bits.  (Python's ``**`` and NumPy's power round differently;
two second-order coefficients, which cancel, show it at 2e-15 and 1.2e-14.)
"""

from __future__ import annotations

import numpy as np
import pytest

from asymslip_gen import scalar

from .conftest import FUNCTIONS
from .toolchains import relative_difference

POINTS = 200  # of the 1,000 each language is checked at: Python calls one point at a time


def test_every_generated_function_has_a_math_twin():
    assert sorted(scalar.__all__) == sorted(FUNCTIONS)


@pytest.mark.parametrize("name", sorted(FUNCTIONS))
def test_math_kernel_equals_the_numpy_kernel_to_1e_13(name, points, numpy_values):
    function = getattr(scalar, name)
    columns = [column[:POINTS].tolist() for column in points[name].values()]
    values = np.array([function(*row) for row in zip(*columns, strict=True)])
    worst = relative_difference(values, numpy_values[name][:POINTS])
    assert np.all(np.isfinite(values)) and worst.max() <= 1e-13, (name, float(worst.max()))


def test_math_kernels_raise_where_numpy_returns_inf_so_callers_can_fall_back():
    with pytest.raises((ZeroDivisionError, ValueError, OverflowError)):
        scalar.hertz_half_width(1.0, 1.0, 0.0)  # E* = 0: a division by zero
