"""The ``math`` kernels for one value at a time (``asymslip_gen.scalar``) equal the NumPy ones.

Same records, same CSE'd bodies, printed for ``math`` instead of ``numpy``: at the points of
each function's documented domain (``domains.py``, the points the other languages use) every
value agrees with NumPy's to 1e-13 relative, the tolerance of the C, Fortran and Octave
comparisons; most are identical bits.  (Python's ``**`` and NumPy's power round differently;
two second-order coefficients, which cancel, show it at 2e-15 and 1.2e-14.)
"""

from __future__ import annotations

import inspect
import math
import re

import numpy as np
import pytest

from asymslip import HertzLaw
from asymslip_gen import scalar, scalar_programs

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


def _printed_as_before(source: str) -> str:
    """The module as the printer wrote it before it printed constants as float literals:
    integers without ``.0`` and pi as ``math.pi``."""
    source = source.replace(repr(math.pi), "math.pi")
    return re.sub(r"(?<![\w.])(\d+)\.0(?![\d\w])", r"\1", source)


@pytest.mark.parametrize("module", [scalar, scalar_programs], ids=lambda module: module.__name__)
def test_float_literals_change_no_bit_of_any_math_kernel(module, points):
    # 256.0 * x for 256 * x and a literal for math.pi make the kernels faster on CPython; the
    # values must be the same doubles.  Every kernel at its documented points, and every
    # program at a Hertzian cycle's own arguments, against the same text with the integers
    # and math.pi put back.
    source = inspect.getsource(module)
    before: dict[str, object] = {}
    exec(compile(_printed_as_before(source), "before", "exec"), before)  # noqa: S102
    assert "256.0 *" in inspect.getsource(scalar_programs)  # the literals are there to test
    if module is scalar:
        calls = [
            (name, row)
            for name in sorted(FUNCTIONS)
            for row in zip(*[c[:20].tolist() for c in points[name].values()], strict=True)
        ]
    else:
        state = HertzLaw(1.0, 1.0).cycle_state(100.0, 5.0)
        law = (state.a1, state.a2, state.da, state.L_I1, state.L_I2, state.P1, 5.0)
        slopes = (state.load_slope1, state.load_slope2, state.L_I_slope1, state.L_I_slope2)
        calls = [("hertz_cycle_state", (100.0, 5.0, 1.0, 1.0))]
        for lam, eta in ((0.2, 0.0), (-0.2, 0.1), (1.2, -0.06)):
            calls += [
                ("edge_shear", (0.1, lam, eta, state.a1, state.a2, state.L_I1, state.L_I2)),
                ("edge_estimates", (0.1, lam, eta, *law, *slopes, -1.0, 1.0, 1e-12)),
                ("both_edges", (0.1, lam, eta, *law, *slopes, 1e-12)),
            ]
    for name, row in calls:
        now, then = getattr(module, name)(*row), before[name](*row)  # type: ignore[operator]
        now_bits = [float(value).hex() for value in np.atleast_1d(now)]
        then_bits = [float(value).hex() for value in np.atleast_1d(then)]
        assert now_bits == then_bits, (name, row)
    assert len(calls) >= 10
