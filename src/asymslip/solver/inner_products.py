"""Inner products of the solver's inner loop, computed without the BLAS.

``a @ b``, ``numpy.dot`` and ``numpy.linalg.norm`` hand long vectors to the BLAS, and OpenBLAS
runs a dot product on every core once it is longer than 10,000 elements.  On a machine whose
cores are busy with other work those threads wait for each other at every call: measured on the
2-core development machine under load, 300 dot products of 2 x 10^6 elements took 8.8 s with
OpenBLAS's default threads against 1.6 s with one (issue 17: the solver 4-8 times slower at
N >= 16,000).  ``numpy.einsum`` without ``optimize`` sums with NumPy's own single-threaded
loops: 2.0-2.2 s either way.  So every reduction of the conjugate gradients and the active-set
iterations goes through these functions, and a solve uses one thread whatever the BLAS is
configured to do (``tests/solver/test_threads.py`` keeps the inner-loop modules free of ``@``,
``dot`` and ``linalg.norm``).

Examples
--------
>>> import numpy as np
>>> from asymslip.solver.inner_products import inner, norm, solve_small
>>> inner(np.array([1.0, 2.0]), np.array([3.0, 4.0])), norm(np.array([3.0, 4.0]))
(11.0, 5.0)
>>> solve_small(np.array([[2.0, 1.0], [1.0, 3.0]]), np.array([3.0, 5.0])).tolist()
[0.8, 1.4]
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import NDArray

FloatArray = NDArray[np.float64]


def inner(a: FloatArray, b: FloatArray) -> float:
    """sum_i a_i b_i of two vectors."""
    return float(np.einsum("i,i->", a, b))


def norm(a: FloatArray) -> float:
    """The Euclidean norm of a vector."""
    return math.sqrt(inner(a, a))


def row_products(rows: FloatArray, vector: FloatArray) -> FloatArray:
    """A v for a few rows A (m, n) and a vector v (n,): the m inner products."""
    return np.asarray(np.einsum("ij,j->i", rows, vector), dtype=np.float64)


def combination(weights: FloatArray, rows: FloatArray) -> FloatArray:
    """A^T w: the rows (m, n) weighted by w (m,) and summed."""
    return np.asarray(np.einsum("i,ij->j", weights, rows), dtype=np.float64)


def gram(rows: FloatArray, others: FloatArray) -> FloatArray:
    """The m x m matrix of inner products A B^T of two sets of m rows."""
    return np.asarray(np.einsum("ik,jk->ij", rows, others), dtype=np.float64)


def solve_small(matrix: FloatArray, vector: FloatArray) -> FloatArray:
    """x with M x = v for the 1 x 1 or 2 x 2 systems of one or two equality rows.

    Written out (Cramer's rule) rather than passed to LAPACK; larger systems, which the
    solver never forms, go to ``numpy.linalg.solve``.
    """
    size = matrix.shape[0]
    if size == 0:
        return np.zeros(0)
    if size == 1:
        return np.array([vector[0] / matrix[0, 0]])
    if size == 2:
        (a, b), (c, d) = matrix
        determinant = a * d - b * c
        return np.array(
            [
                (d * vector[0] - b * vector[1]) / determinant,
                (a * vector[1] - c * vector[0]) / determinant,
            ]
        )
    return np.asarray(np.linalg.solve(matrix, vector), dtype=np.float64)
