"""Hypothesis strategies for the property tests whose reference is mpmath (one example at a time).

Tests whose reference is NumPy draw arrays instead (``tests/sampling.py``).
"""

from __future__ import annotations

from hypothesis import strategies as st

finite = {"allow_nan": False, "allow_infinity": False, "allow_subnormal": False}


def real(low: float, high: float) -> st.SearchStrategy[float]:
    """Finite floats in [low, high] without subnormals (they carry too few digits to compare)."""
    return st.floats(low, high, **finite)
