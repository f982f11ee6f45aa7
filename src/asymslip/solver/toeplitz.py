"""Symmetric Toeplitz influence matrices on a uniform grid: products by FFT, solves by PCG.

On a uniform grid of N elements with collocation at the centres, the influence of element j
on element i depends on i - j only (``asymslip_gen.solver_influence``): the N x N matrix is
Toeplitz.  Embedded in a circulant of a quick FFT length >= 2N - 1 (:func:`quick_length`), a
product costs two real FFTs, O(N log N), instead of O(N^2).  From ``CRT_MIN_LENGTH`` = 2^19
points on, where a one-dimensional transform's passes leave the cache, a circulant is applied
as a two-dimensional cyclic convolution (:class:`~asymslip.solver.crt_layout.CrtLayout`,
lengths from :func:`transform_length`); from ``HALVED_MIN_LENGTH`` on, a product is taken by
four half-size blocks (:class:`~asymslip.solver.halved_product.HalvedProduct`).

The contact problems solve with a *principal submatrix* (the stick or contact elements, one
or a few runs of consecutive elements) under one or two equality constraints (force, moment).
:func:`projected_cg` does it by projected conjugate gradients preconditioned, run by run, with
T. Chan's optimal circulant (Chan 1988) applied to the zero-padded run: a principal block of an
SPD circulant's inverse, hence SPD.  The circulant is built for a quick FFT length at least
``PRECONDITIONER_STRETCH`` = 1.1 times the run's length (the kernel continued beyond the run):
measured on a run of 3600 elements of the slip kernel, 10 iterations from zero to a relative
residual of 1e-11 against 13 with a circulant of the run's own length (1.1 times: 11; 1.25,
1.5, 2 and 3 times: 10); on the paper's Fig. 5 cycle at N = 10^5, warm-started, 535 iterations
in all at 1.1 against 534 at 1.25 and 552 at 1.0, and 1.1 makes the circulant of a
92,000-element run 102,400 points long instead of 115,200.  The iterations do not grow with N
(``tests/solver/test_linear_algebra.py``).

Memory stays O(N): the operator keeps its kernel column and one spectrum, and at most
``SPECTRUM_CACHE`` spectra of run-length circulants (least recently used dropped).
"""

from __future__ import annotations

import functools
import inspect
import math
from collections import OrderedDict
from collections.abc import Callable, Sequence
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from .crt_layout import CrtLayout
from .halved_product import HalvedProduct
from .inner_products import combination, gram, inner, norm, row_products, solve_small

FloatArray = NDArray[np.float64]
BoolArray = NDArray[np.bool_]

#: Relative residual at which the conjugate gradients stop.
CG_TOLERANCE = 1e-11
#: Iteration cap; the preconditioned iteration needs 10-15, so this means breakdown.
CG_MAX_ITERATIONS = 400
#: The preconditioner's circulant is at least this many times longer than its run.
PRECONDITIONER_STRETCH = 1.1
#: Spectra of run-length circulants kept per operator (the least recently used is dropped).
SPECTRUM_CACHE = 8
#: NumPy 2 lets an FFT write into a given array (``out=``); NumPy 1 allocates.
_FFT_OUT = "out" in inspect.signature(np.fft.rfft).parameters
#: Circulants at least this long are applied as two-dimensional transforms
#: (:class:`~asymslip.solver.crt_layout.CrtLayout`).
CRT_MIN_LENGTH = 2**19
#: Products whose circulant is at least this long are taken as four half-size blocks
#: (:class:`~asymslip.solver.halved_product.HalvedProduct`).  Measured (CPU time, best of 10,
#: one process, load average 1.6): at N = 10^6 (2,048,000 points against blocks of 1,024,000)
#: 39.4 ms a product against 44.1 ms; at N = 800,000 (1,638,400 against 819,200) 33.9 ms
#: against 30.2 ms, a loss: so only from 2,048,000 points, the quick length for N = 10^6.
HALVED_MIN_LENGTH = 2_000_000
#: Layouts of preconditioner circulants kept per operator.
CRT_LAYOUTS = 2


class SolverError(RuntimeError):
    """The numerical solver did not converge: the message says where and why.

    Raised instead of returning an answer that is not a solution.
    """


#: The odd parts 3^b 5^c (b <= 2, c <= 3) allowed in the lengths of :func:`quick_length`.
QUICK_ODD_PARTS = (1, 3, 5, 9, 15, 25, 45, 75, 125, 225, 375, 1125)


@functools.lru_cache(maxsize=4096)
def quick_length(n: int) -> int:
    """Smallest 2^a 3^b 5^c >= n with b <= 2 and c <= 3: the lengths the solver transforms.

    NumPy's FFT (pocketfft) costs least per point on lengths that are mostly a power of 2 with
    a small odd part.  Measured on the development machine (rfft and irfft, best of several
    rounds, ns a point): 102,400 = 2^12 5^2 took 7.1 and 204,800 = 2^13 5^2 8.1, against 10.1
    for 118,098 = 2 3^10 and 8.9 for 200,000 = 2^6 5^5, the smallest 5-smooth lengths the
    solver used before; at 10^6 points a pure power of 2 is slow (2^21: 20.8, 2^20: 14.2)
    where 2,048,000 = 2^14 5^3 took 16.2 and 1,024,000 = 2^13 5^3 12.4.  The padding this
    costs is at most 1/8 (the odd parts are at most 9/8 apart).
    """
    best = None
    for odd in QUICK_ODD_PARTS:
        length = odd
        while length < n:
            length *= 2
        best = length if best is None else min(best, length)
    assert best is not None
    return best


@dataclass(frozen=True)
class Runs:
    """A set of grid elements as runs of consecutive indices [start, stop)."""

    starts: tuple[int, ...]
    stops: tuple[int, ...]

    @classmethod
    def of(cls, mask: BoolArray) -> Runs:
        change = np.diff(np.concatenate(([0], mask.astype(np.int8), [0])))
        starts = np.flatnonzero(change == 1)
        stops = np.flatnonzero(change == -1)
        return cls(tuple(int(a) for a in starts), tuple(int(b) for b in stops))

    @property
    def count(self) -> int:
        """Number of elements in all runs."""
        return sum(self.lengths)

    @property
    def lengths(self) -> list[int]:
        return [b - a for a, b in zip(self.starts, self.stops, strict=True)]

    def index(self) -> NDArray[np.intp]:
        if len(self.starts) == 1:
            return np.arange(self.starts[0], self.stops[0])
        return np.concatenate(
            [np.arange(a, b) for a, b in zip(self.starts, self.stops, strict=True)]
        )

    def selector(self) -> slice | NDArray[np.intp]:
        """What picks the runs' elements out of a grid vector: a slice for one run."""
        if len(self.starts) == 1:
            return slice(self.starts[0], self.stops[0])
        return self.index()


#: The largest mapping whose release raises glibc's mmap threshold (32 MiB on 64-bit), less a
#: margin for the allocator's header and page rounding.
_THRESHOLD_RAISER_BYTES = 32 * 2**20 - 2**16


@functools.cache
def _keep_fft_scratch_on_the_heap() -> None:
    """Release one untouched 32 MiB array, once per process, so that FFT scratch stays on the heap.

    NumPy's FFT allocates a work array of about 2n doubles on every call.  glibc serves
    requests above its mmap threshold (128 KiB at start) with fresh pages from the kernel,
    zero-filled at first touch; measured at n = 204,800, 768 page faults a transform, half its
    time (the rest of a solve's system time with it).  glibc raises the threshold to the size
    of a mapping when that mapping is released (its "dynamic threshold", up to 32 MiB on
    64-bit); this does it at once, for every transform up to n = 2^21.  The array is never
    touched, so it costs no page; the process keeps up to 64 MiB of freed heap (glibc's trim
    threshold becomes twice the mmap threshold).  Elsewhere than glibc it is one allocation, and
    glibc keeps its threshold fixed when a MALLOC_* variable sets one (Dask's nanny sets
    MALLOC_TRIM_THRESHOLD_ for its workers): there the transforms take fresh pages as before.
    """
    scratch = np.empty(_THRESHOLD_RAISER_BYTES // 8)
    del scratch


def transform_length(n: int) -> int:
    """The length the solver transforms for at least ``n`` points: :func:`quick_length`, or from
    ``CRT_MIN_LENGTH`` on the smallest such length with an odd factor to lay out in two
    dimensions (2^20 has none, and its one-dimensional transform is the slowest per point)."""
    length = quick_length(n)
    if not _FFT_OUT or length < CRT_MIN_LENGTH or CrtLayout.split(length):
        return length
    candidates = []
    for odd in QUICK_ODD_PARTS[1:]:
        candidate = 2 * odd
        while candidate < n:
            candidate *= 2
        candidates.append(candidate)
    return min(candidates)


def laid_out(length: int) -> bool:
    """Whether a circulant of ``length`` is applied in two dimensions (``CRT_MIN_LENGTH`` and an
    odd factor of at least ``CRT_MIN_ODD``)."""
    return _FFT_OUT and length >= CRT_MIN_LENGTH and CrtLayout.split(length)


def crt_layout(length: int, count: int) -> CrtLayout | None:
    """The two-dimensional layout of a circulant of ``length`` when :func:`laid_out`, else None."""
    return CrtLayout(length, count) if laid_out(length) else None


def halved_product(column: FloatArray, count: int, length: int) -> HalvedProduct | None:
    """The product by half-size blocks when the circulant of ``length`` points is at least
    ``HALVED_MIN_LENGTH`` and the blocks' circulant is laid out in two dimensions, else None."""
    if length < HALVED_MIN_LENGTH or count < 2:
        return None
    block_length = transform_length(2 * -(-count // 2) - 1)
    return HalvedProduct(column, count, block_length) if laid_out(block_length) else None


class _SpectrumCache:
    """At most ``size`` spectra, the least recently used dropped first."""

    def __init__(self, size: int) -> None:
        self._size = size
        self._items: OrderedDict[int, NDArray[np.generic]] = OrderedDict()

    def get(self, key: int, build: Callable[[int], NDArray[np.generic]]) -> NDArray[np.generic]:
        """The spectrum for ``key`` (a size or an FFT length), built by ``build(key)`` if new."""
        spectrum = self._items.get(key)
        if spectrum is None:
            spectrum = build(key)
            self._items[key] = spectrum
            if len(self._items) > self._size:
                self._items.popitem(last=False)
        else:
            self._items.move_to_end(key)
        return spectrum


class ToeplitzOperator:
    """The symmetric Toeplitz matrix M_ij = c(i - j) on N elements, applied by FFT.

    The FFTs of one-dimensional products and preconditioner solves write into buffers the
    operator keeps (NumPy 2's ``out=``): a fresh array of that size is fresh pages from the
    system every time, and on the development machine that doubled the cost of an FFT of 20,000
    points (0.66 ms against 0.29 ms) and added a third at 200,000.

    Parameters
    ----------
    coefficient
        c(k) for integer arrays k >= 0 (the kernel is even in k); evaluated once, for
        k = 0 ... (the longest preconditioner circulant), so that preconditioners of any run
        can be built.
    count
        Number of elements N.
    """

    def __init__(self, coefficient: Callable[[FloatArray], FloatArray], count: int) -> None:
        _keep_fft_scratch_on_the_heap()
        self.count = count
        self._circulant_length = transform_length(2 * count - 1)
        longest = transform_length(math.ceil(PRECONDITIONER_STRETCH * count))
        self.column = np.asarray(coefficient(np.arange(longest + 1, dtype=np.float64)))
        embedded = np.zeros(self._circulant_length)
        embedded[:count] = self.column[:count]
        embedded[self._circulant_length - count + 1 :] = self.column[1:count][::-1]
        # The embedding is symmetric, so its spectrum is real (the imaginary parts are
        # rounding, dropped).  It is kept complex all the same: NumPy multiplies complex by
        # complex in place without a cast (measured: 60 us against 95 us by reals and 365 us
        # dividing by reals, for 51,201 entries).
        self._spectrum = np.fft.rfft(embedded).real.astype(np.complex128)
        # The longest products as four half-size blocks (HalvedProduct), and other long
        # circulants in two dimensions (CrtLayout): the embedding is even, so its 2-D spectrum
        # is real too.
        self._halves = halved_product(self.column, count, self._circulant_length)
        self._layout = (
            None if self._halves is not None else crt_layout(self._circulant_length, count)
        )
        self._spectrum_2d = (
            None
            if self._layout is None
            else self._layout.spectrum_of(embedded).real.astype(np.complex128)
        )
        # Reciprocal eigenvalues of preconditioner circulants, by circulant length; the length
        # each run length uses; and which circulant lengths are definite.
        self._preconditioners = _SpectrumCache(SPECTRUM_CACHE)
        # Long preconditioner circulants in two dimensions: layouts (three arrays of the
        # circulant's length each) and reciprocal eigenvalues in the layout's order.
        self._layouts: OrderedDict[int, CrtLayout] = OrderedDict()
        self._preconditioners_2d = _SpectrumCache(CRT_LAYOUTS)
        self._lengths: dict[int, int] = {}
        self._definite: dict[int, bool] = {}
        self._blocks = _SpectrumCache(SPECTRUM_CACHE)
        self._buffers = _SpectrumCache(SPECTRUM_CACHE)

    def _transform_buffer(self, length: int) -> NDArray[np.complex128]:
        """The operator's scratch for the rfft of ``length`` points (never handed out)."""
        return self._buffers.get(  # type: ignore[return-value]
            length, lambda size: np.empty(size // 2 + 1, dtype=np.complex128)
        )

    def product_buffer(self) -> FloatArray:
        """An array :meth:`apply` may write one product into (``out``)."""
        return np.empty(self._circulant_length)

    def apply(self, values: FloatArray, out: FloatArray | None = None) -> FloatArray:
        """M @ values along the last axis (any leading shape).

        ``out`` (from :meth:`product_buffer`, one-dimensional values only) receives the product
        in its first N entries, which are returned; otherwise a new array is returned.
        """
        length = self._circulant_length
        if self._halves is not None and values.ndim == 1:
            return self._halves.apply(values, out)
        if self._layout is not None and self._spectrum_2d is not None and values.ndim == 1:
            transformed = self._layout.transform(values)
            transformed *= self._spectrum_2d
            target = np.empty(self.count) if out is None else out[: self.count]
            return self._layout.inverse(transformed, target)
        if values.ndim != 1 or not _FFT_OUT:
            transformed = np.fft.rfft(values, length, axis=-1)
            transformed *= self._spectrum
            return np.fft.irfft(transformed, length, axis=-1)[..., : self.count]
        transformed = np.fft.rfft(values, length, out=self._transform_buffer(length))
        transformed *= self._spectrum
        result = np.fft.irfft(transformed, length, out=out)
        return result[: self.count]

    def diagonal(self) -> float:
        return float(self.column[0])

    def _block_spectrum(self, size: int) -> NDArray[np.complex128]:
        """Spectrum (real, kept complex) of the circulant embedding of the leading block."""

        def build(size: int) -> NDArray[np.complex128]:
            length = quick_length(2 * size - 1)
            embedded = np.zeros(length)
            embedded[:size] = self.column[:size]
            if size > 1:
                embedded[length - size + 1 :] = self.column[1:size][::-1]
            return np.fft.rfft(embedded).real.astype(np.complex128)

        return self._blocks.get(size, build)  # type: ignore[return-value]

    def block_product(self, values: FloatArray) -> FloatArray:
        """The leading block's product: for one run of consecutive elements, M_RR v."""
        size = values.shape[-1]
        length, spectrum = quick_length(2 * size - 1), self._block_spectrum(size)
        transformed = np.fft.rfft(values, length, axis=-1)
        return np.fft.irfft(transformed * spectrum, length, axis=-1)[..., :size]

    def _chan_circulant(self, length: int) -> FloatArray:
        """The first column of T. Chan's optimal circulant for the first ``length``."""
        k = np.arange(1, length)
        circulant = np.empty(length)
        circulant[0] = self.column[0]
        circulant[1:] = (
            (length - k) * self.column[1:length] + k * self.column[length - k]
        ) / length
        return circulant

    def _chan_eigenvalues(self, length: int) -> NDArray[np.float64]:
        """Eigenvalues (rfft half) of T. Chan's optimal circulant for the first ``length``."""
        return np.fft.rfft(self._chan_circulant(length)).real

    def _inverse_eigenvalues(self, length: int) -> NDArray[np.complex128]:
        """1 / the eigenvalues of a definite circulant, as complex numbers (kept: a solve
        multiplies by them, like the product by its spectrum)."""
        inverse = self._preconditioners.get(
            length, lambda n: (1.0 / self._chan_eigenvalues(n)).astype(np.complex128)
        )
        return inverse  # type: ignore[return-value]

    def _preconditioner_length(self, run_length: int) -> tuple[int, NDArray[np.complex128]]:
        """The stretched circulant for a run, or the run's own length if that is not definite,
        with its reciprocal eigenvalues.

        Which length a run uses is decided once per run length (``_lengths``), and whether a
        circulant length is definite once per length (``_definite``): a solve asks at every
        iteration, and the test is a pass over half the spectrum.
        """
        chosen = self._lengths.get(run_length)
        if chosen is not None:
            return chosen, self._inverse_eigenvalues(chosen)
        stretched = transform_length(math.ceil(PRECONDITIONER_STRETCH * run_length))
        smallest = np.inf
        for length in (stretched, transform_length(run_length)):
            if length not in self._definite:
                eigenvalues = self._chan_eigenvalues(length)
                self._definite[length] = bool(np.all(eigenvalues > 0))
                if not self._definite[length]:
                    smallest = min(smallest, float(eigenvalues.min()))
            if self._definite[length]:
                self._lengths[run_length] = length
                return length, self._inverse_eigenvalues(length)
        raise SolverError(
            "the influence matrix is not positive definite on this grid "
            f"(circulant eigenvalue {smallest:.3g}); the reference length of the "
            "logarithm must be at least a quarter of the grid's length"
        )

    def _layout_of(self, length: int) -> tuple[CrtLayout, NDArray[np.complex128]] | None:
        """The 2-D layout of a preconditioner circulant and its reciprocal eigenvalues in the
        layout's order, or None when the one-dimensional transform is used."""
        if not laid_out(length):  # (asked at every solve: builds nothing)
            return None
        layout = self._layouts.get(length)
        if layout is None:
            layout = self._layouts[length] = CrtLayout(length, 0)
            while len(self._layouts) > CRT_LAYOUTS:
                self._layouts.popitem(last=False)
        else:
            self._layouts.move_to_end(length)

        def build(n: int) -> NDArray[np.complex128]:
            eigenvalues = layout.spectrum_of(self._chan_circulant(n)).real
            return (1.0 / eigenvalues).astype(np.complex128)

        inverse: NDArray[np.complex128] = self._preconditioners_2d.get(length, build)  # type: ignore[assignment]
        return layout, inverse

    def preconditioner_buffer(self, runs: Runs) -> FloatArray | None:
        """An array :meth:`precondition` may write into for these runs (``out``), or None."""
        if len(runs.starts) != 1 or not _FFT_OUT:
            return None
        return np.empty(self._preconditioner_length(runs.count)[0])

    def precondition(
        self, runs: Runs, residual: FloatArray, out: FloatArray | None = None
    ) -> FloatArray:
        """Apply the run-by-run circulant preconditioner to packed residuals (..., count).

        ``out`` (from :meth:`preconditioner_buffer`, one-dimensional residuals only) receives
        the result in its first entries, which are returned.
        """
        if len(runs.starts) == 1:
            length, inverse = self._preconditioner_length(runs.count)
            layout = self._layout_of(length) if residual.ndim <= 2 else None
            if layout is not None and residual.ndim == 1:
                transformed = layout[0].transform(residual)
                transformed *= layout[1]
                target = np.empty(runs.count) if out is None else out[: runs.count]
                return layout[0].inverse(transformed, target)
            if layout is not None:  # a few rows (the constraints): one at a time
                solved = np.empty_like(residual)
                for row, target in zip(residual, solved, strict=True):
                    transformed = layout[0].transform(row)
                    transformed *= layout[1]
                    layout[0].inverse(transformed, target)
                return solved
            if residual.ndim == 1 and _FFT_OUT:
                transformed = np.fft.rfft(residual, length, out=self._transform_buffer(length))
                transformed *= inverse
                return np.fft.irfft(transformed, length, out=out)[: runs.count]
            transformed = np.fft.rfft(residual, length, axis=-1)
            transformed *= inverse
            return np.fft.irfft(transformed, length, axis=-1)[..., : runs.count]
        out = np.empty_like(residual)
        offset = 0
        for run_length in runs.lengths:
            length, inverse = self._preconditioner_length(run_length)
            block = residual[..., offset : offset + run_length]
            solved = np.fft.irfft(np.fft.rfft(block, length, axis=-1) * inverse, length, axis=-1)
            out[..., offset : offset + run_length] = solved[..., :run_length]
            offset += run_length
        return out


def _restricted_product(
    operator: ToeplitzOperator, runs: Runs
) -> Callable[[FloatArray], FloatArray]:
    """v -> (M_RR v) for packed vectors v of the elements in ``runs``."""
    if len(runs.starts) == 1:  # one run: its own, shorter circulant
        return operator.block_product
    index = runs.index()
    n = operator.count

    def gathered(values: FloatArray) -> FloatArray:
        full = np.zeros(values.shape[:-1] + (n,))
        full[..., index] = values
        return operator.apply(full)[..., index]

    return gathered


@dataclass(frozen=True)
class Correction:
    """What :func:`projected_cg` found: the correction, the multipliers, the iterations."""

    step: FloatArray  # e, packed over the runs
    multipliers: FloatArray  # lambda with M (y0 + e) - b + A^T lambda = 0
    iterations: int
    abandoned: bool = False  # stopped at the checkpoint: not converged


@dataclass(frozen=True)
class Checkpoint:
    """A question :func:`projected_cg` asks once, when its residual first falls to ``target``.

    ``go_on(step, multipliers)`` is given the iterate so far; if it answers False the
    iteration stops there (``Correction.abandoned``): the caller has learnt what it needed
    (for the active-set iteration: that the guessed stick/slip sets are wrong) and the
    iterations to full accuracy would be spent on a problem about to be replaced.
    """

    target: float
    go_on: Callable[[FloatArray, FloatArray], bool]


def projected_cg(
    operator: ToeplitzOperator,
    runs: Runs,
    residual: FloatArray,
    rows: FloatArray,
    *,
    target: float,
    max_iterations: int = CG_MAX_ITERATIONS,
    image: FloatArray | None = None,
    checkpoint: Checkpoint | None = None,
) -> Correction:
    """Correct a feasible start y0 to the minimiser of 1/2 y.M_RR.y - b.y subject to A y = c.

    Projected preconditioned conjugate gradients (Gould, Hribar & Nocedal 2001): every
    preconditioned residual is projected onto A e = 0 in the preconditioner's metric, so one
    conjugate-gradient run handles the m equality rows.

    Parameters
    ----------
    operator, runs
        M and the elements R (the free set).
    residual
        M y0 - b at the start, packed over the runs; the start satisfies A y0 = c.
    rows
        A (m, packed count).
    target
        Absolute 2-norm of the projected residual at which to stop.
    image
        The full-grid image M y0 (all N elements), or None.  When given, every product is
        taken on the whole grid and the image is kept up to date in place (it ends as
        M (y0 + e)), so that the caller needs no further product for the gradient on the
        elements outside R; otherwise products use the runs' own (shorter) circulants.
    checkpoint
        A question to ask once on the way (:class:`Checkpoint`), or None.

    Raises
    ------
    SolverError
        If the iteration does not reach ``target`` in ``max_iterations`` or meets a
        non-positive curvature (the matrix is not positive definite).
    """
    A = np.atleast_2d(rows)
    m = A.shape[0]
    where = runs.selector()
    if image is None:
        restricted = _restricted_product(operator, runs)

        def product(direction: FloatArray) -> tuple[FloatArray, FloatArray | None]:
            return restricted(direction), None
    else:
        spread = np.zeros(operator.count)  # the direction on the grid: zero off the runs
        buffer = operator.product_buffer()

        def product(direction: FloatArray) -> tuple[FloatArray, FloatArray | None]:
            spread[where] = direction
            full = operator.apply(spread, out=buffer)
            return full[where], full

    if m:
        Z = operator.precondition(runs, A)  # M^-1 A^T, as rows
        schur = gram(A, Z)

    scratch = operator.preconditioner_buffer(runs)

    def project(residual: FloatArray) -> tuple[FloatArray, FloatArray, FloatArray]:
        z = operator.precondition(runs, residual, out=scratch)
        if not m:
            return z, np.zeros(0), residual
        w = solve_small(schur, row_products(A, z))
        z -= combination(w, Z)
        residual -= combination(w, A)
        return z, w, residual

    step = np.zeros_like(residual)
    # The residual's component A^T w along the constraints is moved into the multiplier at
    # every step ("residual update", Gould et al., Sec. 6): left in r it grows to dominate it
    # and rounding destroys the projection.  The preconditioned residual g lives in the
    # preconditioner's buffer until the next projection; the vectors are updated in place.
    g, w, r = project(np.array(residual, dtype=np.float64))
    multiplier = w.copy()
    if norm(r) <= target:
        return Correction(step, -multiplier, 0)
    direction = -g
    scaled = np.empty_like(direction)
    rg = inner(r, g)
    for iteration in range(1, max_iterations + 1):
        packed, full = product(direction)
        curvature = inner(direction, packed)
        if not curvature > 0:
            raise SolverError(
                "conjugate gradients met a non-positive curvature: the influence matrix is "
                "not positive definite on these elements"
            )
        alpha = rg / curvature
        step += np.multiply(direction, alpha, out=scaled)
        if image is None or full is None:
            r += np.multiply(packed, alpha, out=scaled)
        else:  # scaled once, for the residual and the image
            full *= alpha
            r += full[where]
            image += full
        g, w, r = project(r)
        multiplier += w
        size = norm(r)
        if size <= target:
            return Correction(step, -multiplier, iteration)
        if checkpoint is not None and size <= checkpoint.target:
            if not checkpoint.go_on(step, -multiplier):
                return Correction(step, -multiplier, iteration, abandoned=True)
            checkpoint = None
        rg_next = inner(r, g)
        direction *= rg_next / rg
        direction -= g
        rg = rg_next
    raise SolverError(
        f"conjugate gradients did not reach a relative residual of {CG_TOLERANCE:g} in "
        f"{max_iterations} iterations on {runs.count} elements"
    )


def onto_constraints(y: FloatArray, rows: FloatArray, targets: FloatArray) -> FloatArray:
    """y moved along A^T (the least change) so that A y = c."""
    A = np.atleast_2d(rows)
    if not A.shape[0]:
        return y
    return y + combination(solve_small(gram(A, A), targets - row_products(A, y)), A)


def solve_constrained(
    operator: ToeplitzOperator,
    runs: Runs,
    rhs: FloatArray,
    rows: FloatArray,
    targets: FloatArray,
    *,
    guess: FloatArray | None = None,
    tolerance: float = CG_TOLERANCE,
    max_iterations: int = CG_MAX_ITERATIONS,
) -> tuple[FloatArray, FloatArray, int]:
    """Minimise 1/2 y.M_RR.y - b.y subject to A y = c, by projected preconditioned CG.

    All vectors are packed over the elements of ``runs``; the start is ``guess`` (or zero)
    moved onto A y = c.  The iteration stops at a residual of ``tolerance`` times the larger
    of |b| and |M_RR y0|.

    Returns
    -------
    (y, lambda, iterations), with M y - b + A^T lambda = 0 and A y = c.

    Raises
    ------
    SolverError
        As :func:`projected_cg`.
    """
    b = np.asarray(rhs, dtype=np.float64)
    A = np.atleast_2d(np.asarray(rows, dtype=np.float64))
    c = np.atleast_1d(np.asarray(targets, dtype=np.float64))
    y = np.zeros_like(b) if guess is None else np.array(guess, dtype=np.float64)
    y = onto_constraints(y, A, c)
    image = _restricted_product(operator, runs)(y)
    scale = max(norm(b), norm(image), 1e-300)
    found = projected_cg(
        operator, runs, image - b, A, target=tolerance * scale, max_iterations=max_iterations
    )
    # Remove the drift from A y = c that rounding accumulates.
    y = onto_constraints(y + found.step, A, c)
    return y, found.multipliers, found.iterations


def pack(values: FloatArray, runs: Runs) -> FloatArray:
    """The entries of ``values`` (last axis: the grid) at the elements of ``runs``."""
    return values[..., runs.selector()]


def unpack(packed: FloatArray, runs: Runs, count: int, fill: float = 0.0) -> FloatArray:
    """A grid vector with ``packed`` at the elements of ``runs`` and ``fill`` elsewhere."""
    full = np.full(packed.shape[:-1] + (count,), fill, dtype=np.float64)
    full[..., runs.selector()] = packed
    return full


__all__: Sequence[str] = (
    "CG_TOLERANCE",
    "Checkpoint",
    "CrtLayout",
    "Correction",
    "Runs",
    "SolverError",
    "ToeplitzOperator",
    "quick_length",
    "transform_length",
    "onto_constraints",
    "pack",
    "projected_cg",
    "solve_constrained",
    "unpack",
)
