"""The product of a long symmetric Toeplitz matrix as four half-size blocks.

At N = 10^6 the circulant embedding of the N x N matrix M_ij = c(|i - j|) has 2,048,000 points,
and its two-dimensional transforms
(:class:`~asymslip.solver.crt_layout.CrtLayout`, 125 x 16,384) work on arrays of 16 MB, half
the shared 32 MB cache of the development machine.  Measured there (CPU time, best of 10, one
process, load average 1.6), a product took 44.1 ms so, and 39.4 ms by half-size blocks of
1,024,000 points (125 x 8,192), whose arrays are half as large.

So the vector is split into its halves x1 (n1 = ceil(N/2) entries) and x2 (n2 = N - n1), and

    y1 = T0 x1 + T12 x2,    y2 = T21 x1 + T0' x2,

with T0 = the leading n1 x n1 block (T0' its leading n2 x n2 block, the same circulant applied
to a shorter vector), T12_ij = c(|i - j - n1|) and T21 = T12^T.  Each block is a Toeplitz
matrix embedded in a circulant of the same length L' >= 2 n1 - 1 (about N): T21's embedding is
the transpose of T12's, so its spectrum is the complex conjugate of T12's.  Two forward and two
inverse transforms of L' points and four spectrum products replace two transforms of 2 L'
points.  Exact up to rounding, like any circulant product.

Examples
--------
A 6 x 6 Toeplitz matrix c(|i - j|) by blocks in circulants of 10 = 5 x 2 points:

>>> import numpy as np
>>> from asymslip.solver.halved_product import HalvedProduct
>>> column = 1.0 / (1.0 + np.arange(8.0))
>>> x = np.arange(6.0)
>>> dense = column[np.abs(np.subtract.outer(np.arange(6), np.arange(6)))]
>>> bool(np.allclose(HalvedProduct(column, 6, 10).apply(x), (dense * x).sum(axis=1)))
True
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

from .crt_layout import CrtLayout

FloatArray = NDArray[np.float64]
ComplexArray = NDArray[np.complex128]


def block_columns(column: FloatArray, count: int, length: int) -> tuple[FloatArray, FloatArray]:
    """The circulant columns (length L') of T0 and T12 for N = ``count``, from c(0 ... N).

    T0 (n1 x n1): e[k] = c(k) and e[L' - k] = c(k) for 0 < k < n1.  T12 (n1 x n2), entry
    (i, j) = c(|i - j - n1|) = t(i - j) for i - j in [-(n2 - 1), n1 - 1]: e[d mod L'] = t(d), so
    e[d] = c(n1 - d) for 0 <= d < n1 and e[L' - j] = c(n1 + j) for 0 < j < n2.
    """
    first = -(-count // 2)
    second = count - first
    if length < 2 * first - 1 or column.size < count:
        raise ValueError("the block circulants need L' >= 2 ceil(N/2) - 1 and c(0 ... N - 1)")
    diagonal = np.zeros(length)
    diagonal[:first] = column[:first]
    diagonal[length - first + 1 :] = column[1:first][::-1]
    coupling = np.zeros(length)
    coupling[:first] = column[first:0:-1]
    if second > 1:
        coupling[length - second + 1 :] = column[first + 1 : first + second][::-1]
    return diagonal, coupling


class HalvedProduct:
    """M x for the N x N symmetric Toeplitz matrix of ``column`` by four half-size blocks.

    Parameters
    ----------
    column
        c(k) for k = 0 ... at least N - 1.
    count
        N (at least 2).
    length
        L' >= 2 ceil(N/2) - 1, a length that
        :class:`~asymslip.solver.crt_layout.CrtLayout` can lay out.
    """

    def __init__(self, column: FloatArray, count: int, length: int) -> None:
        self.count = count
        self.first = -(-count // 2)
        second = count - self.first
        self._layouts = (CrtLayout(length, self.first), CrtLayout(length, second))
        # Fewer arrays, fewer cache misses: the inverse transforms run one after the other, so
        # they share one result array; halves of equal length (N even) fill the same entries
        # of their layouts, so they share the input array too (each is transformed out of it
        # before the next is written).
        self._layouts[1].share_result(self._layouts[0])
        if second == self.first:
            self._layouts[1].share_values(self._layouts[0])
        diagonal, coupling = block_columns(column, count, length)
        layout = self._layouts[0]
        # T0 is symmetric: its spectrum is real (kept complex for the in-place products).
        self._diagonal = layout.spectrum_of(diagonal).real.astype(np.complex128)
        self._upper = layout.spectrum_of(coupling)
        self._lower = np.conj(self._upper)  # T21 = T12^T: the conjugate spectrum
        self._scratch = (np.empty_like(self._upper), np.empty_like(self._upper))

    def apply(self, values: FloatArray, out: FloatArray | None = None) -> FloatArray:
        """M @ values for one vector of N entries, into ``out[:N]`` if given."""
        top, bottom = self._layouts
        upper_part, lower_part = self._scratch
        x1 = top.transform(values[: self.first])
        x2 = bottom.transform(values[self.first :])
        np.multiply(self._upper, x2, out=upper_part)  # T12 x2
        np.multiply(self._lower, x1, out=lower_part)  # T21 x1
        x1 *= self._diagonal
        x1 += upper_part
        x2 *= self._diagonal
        x2 += lower_part
        target = np.empty(self.count) if out is None else out[: self.count]
        top.inverse(x1, target[: self.first])
        bottom.inverse(x2, target[self.first :])
        return target


__all__ = ["HalvedProduct", "block_columns"]
