"""Circulants of long vectors as two-dimensional cyclic convolutions (Good-Thomas).

Used by :mod:`asymslip.solver.toeplitz` (products and preconditioners from ``CRT_MIN_LENGTH``
points on) and :mod:`asymslip.solver.halved_product`.

Examples
--------
The circulant (2 1 0 ... 0 1) of 40 = 5 x 8 points applied to (1, 0, 0) in two dimensions:

>>> import numpy as np
>>> from asymslip.solver.crt_layout import CrtLayout
>>> layout = CrtLayout(40, 3)
>>> layout.shape
(5, 8)
>>> kernel = np.zeros(40)
>>> kernel[[0, 1, 39]] = [2.0, 1.0, 1.0]
>>> product = layout.transform(np.array([1.0, 0.0, 0.0])) * layout.spectrum_of(kernel)
>>> layout.inverse(product, np.empty(3)).round(12).tolist()
[2.0, 1.0, 0.0]
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

FloatArray = NDArray[np.float64]

#: The odd factor of a two-dimensional layout is at least this (else the 2-D form gains nothing).
CRT_MIN_ODD = 5


class CrtLayout:
    """A cyclic convolution of length L = L1 L2 (L1 odd, L2 a power of 2) as a 2-D one.

    The map n -> (n mod L1, u n mod L2), u = 1/L1 modulo L2, is a group isomorphism from
    Z_L onto Z_L1 x Z_L2 (Chinese remainder theorem; L1 and L2 are coprime), so a circulant
    product of length L is a 2-D cyclic convolution of the arrays it maps to, computed by 2-D
    FFTs (real along the contiguous L2 axis, complex along the L1 axis) with no twiddle factors
    (Good 1958, Thomas 1963).  The 2-D transforms work on rows of L2 points: measured on the
    development machine at L = 2,048,000 = 125 x 16,384 (rfft, product, irfft), 32-41 ms
    against 64-71 ms for the one-dimensional transform, whose passes over 16 MB leave the
    cache; the two maps (in and out) add about 7 ms at N = 10^6.  With the factor u the
    entries n = r, r + L1, r + 2 L1, ... go to consecutive columns of row r, so each map is
    two slice copies a row.  Exact up to rounding (~1e-15 relative).

    Parameters
    ----------
    length
        L = odd * 2^a with odd >= ``CRT_MIN_ODD`` (see ``CrtLayout.split``).
    count
        How many leading entries of a length-L vector are ever nonzero, and read back.
    """

    def __init__(self, length: int, count: int) -> None:
        odd = length
        while odd % 2 == 0:
            odd //= 2
        self.shape = (odd, length // odd)
        rows, columns = self.shape
        self.length = length
        self._inverse = pow(rows, -1, columns)
        self._values = np.zeros(self.shape)
        self._spectrum = np.empty((rows, columns // 2 + 1), dtype=np.complex128)
        self._result = np.empty(self.shape)
        self._rows = self._plan(count)
        self.count = count  # the entries written last; the others' positions hold zeros

    def share_result(self, other: CrtLayout) -> None:
        """Use ``other``'s array for the inverse transforms (for layouts used one at a time)."""
        if other.shape != self.shape:
            raise ValueError("layouts of different shapes cannot share an array")
        self._result = other._result

    def share_values(self, other: CrtLayout) -> None:
        """Use ``other``'s input array: for two layouts of the same length always given vectors
        of the same count (each writes every entry the other wrote)."""
        if other.shape != self.shape or other.count != self.count:
            raise ValueError("only layouts of one shape and count can share their input array")
        self._values = other._values

    def _plan(self, count: int) -> list[tuple[int, int, int, int]]:
        """Row r holds the entries r, r + L1, r + 2 L1, ... from column u r on (wrapping once
        at most: fewer than L2 of them): two slice copies a row, no index array (measured at
        N = 10^6: 7 ms for both maps against 12 ms by fancy indexing)."""
        rows, columns = self.shape
        plan = []
        for row in range(rows):
            taken = len(range(row, count, rows))
            start = (self._inverse * row) % columns
            plan.append((row, start, min(taken, columns - start), taken))
        return plan

    @staticmethod
    def split(length: int) -> bool:
        """Whether ``length`` is odd * 2^a with odd >= ``CRT_MIN_ODD`` and a >= 1."""
        odd = length
        while odd % 2 == 0:
            odd //= 2
        return odd >= CRT_MIN_ODD and odd < length

    def positions(self, n: NDArray[np.intp]) -> NDArray[np.intp]:
        """Flat positions in the 2-D array of the entries n of the length-L vector."""
        rows, columns = self.shape
        return (n % rows) * columns + (n * self._inverse) % columns

    def transform(self, values: FloatArray) -> NDArray[np.complex128]:
        """The 2-D spectrum of a length-L vector given as its first entries (the rest zero)."""
        mapped, step = self._values, self.shape[0]
        if values.size != self.count:  # another run length
            if values.size < self.count:  # clear the longer one's entries
                mapped.fill(0.0)
            self._rows, self.count = self._plan(values.size), values.size
        for row, start, first, taken in self._rows:
            source = values[row::step]
            mapped[row, start : start + first] = source[:first]
            if taken > first:
                mapped[row, : taken - first] = source[first:]
        spectrum = np.fft.rfft(self._values, axis=-1, out=self._spectrum)
        return np.fft.fft(spectrum, axis=0, out=spectrum)

    def spectrum_of(self, vector: FloatArray) -> NDArray[np.complex128]:
        """The 2-D spectrum of a whole length-L vector (a new array)."""
        mapped = np.empty(self.shape)
        mapped.reshape(-1)[self.positions(np.arange(self.length, dtype=np.intp))] = vector
        return np.fft.fft(np.fft.rfft(mapped, axis=-1), axis=0)

    def inverse(self, spectrum: NDArray[np.complex128], out: FloatArray) -> FloatArray:
        """The entries of the inverse transform of ``spectrum`` (overwritten) that the last
        ``transform`` was given, written into ``out`` (as many)."""
        np.fft.ifft(spectrum, axis=0, out=spectrum)
        result = np.fft.irfft(spectrum, self.shape[1], axis=-1, out=self._result)
        step = self.shape[0]
        for row, start, first, taken in self._rows:
            target = out[row::step]
            target[:first] = result[row, start : start + first]
            if taken > first:
                target[first:] = result[row, : taken - first]
        return out


__all__ = ["CRT_MIN_ODD", "CrtLayout"]
