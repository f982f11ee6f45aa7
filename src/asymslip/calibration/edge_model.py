"""The edge expansion fitted by least squares: p = L_I sqrt(d) + c d^(3/2) [+ e d^(5/2)].

Near a contact edge a at distance d = a - x the pressure of an incomplete contact has the
expansion p = L_I sqrt(d) + c d^(3/2) + e d^(5/2) + ..., whose first term is the paper's (4).
At a fixed trial edge the model is linear in its coefficients, so the residual sum of squares
RSS(a) of the two-term fit (or of the three-term one, for the truncation check of
:mod:`.edge_errors`) is found in closed form for many trial edges at once, and a is the trial
edge of least RSS (:func:`minimise`).

Nodes beyond a trial edge are kept with the model value 0 (the clamped distance
max(a - x, 0)): the first node out of contact penalises an edge placed beyond it.  The
residual sum of squares is summed from the residuals themselves, not as sum(p^2) minus the
fitted part: near an exact fit that difference loses all its digits, and RSS(a) would stop
resolving a long before the fit does (a to about 1e-8 of the spacing instead of 1e-15).

Runtime needs NumPy only.

Examples
--------
>>> import numpy as np
>>> x = np.array([0.0, 1.0, 2.0, 3.0, 4.0, 5.0])
>>> p = 2.0 * np.sqrt(np.maximum(4.5 - x, 0.0))
>>> X, P = padded(x, p, [np.arange(6)])
>>> round(float(minimise(X, P, 3.0, 5.0)[0]), 5)  # within the resolution of the grid
4.5
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

FloatArray = NDArray[np.float64]

#: Trial edges per round of :func:`minimise`, and its rounds of refinement.  Five rounds put
#: the resolution at 7e-8 of the bracket (four: 1.6e-6, which on exact traces of 100-200
#: nodes was most of the reported error of a, 1e-6 against true errors of 1e-7: with five,
#: a's reported error is within three times the true one in 216 of the census's 240 fits
#: instead of 211); the fifth costs no measurable time (the census's exact traces take 14.2 s
#: of CPU either way: the bootstrap's fits dominate).
GRID = 48
ROUNDS = 5


def resolution(low: float, high: float) -> float:
    """How far :func:`minimise`'s answer may lie from the true least-squares edge in [low, high].

    Each round narrows the bracket to two grid steps around its best point; the answer is the
    middle of the last bracket, within one last grid step of the minimum.
    """
    return float((high - low) * 2.0 ** (ROUNDS - 1) / (GRID - 1) ** ROUNDS)


def two_term(D: FloatArray, p: FloatArray) -> tuple[FloatArray, FloatArray, FloatArray, FloatArray]:
    """(L_I, c, RSS, var factor of L_I) for clamped distances D = max(a - x, 0), last axis nodes.

    Nodes padded with D = 0 and p = 0 add nothing.  Where the 2x2 normal matrix is singular
    (fewer than two nodes inside the trial edge) RSS is +inf.
    """
    b1 = np.sqrt(D)
    b2 = D * b1
    g11 = np.einsum("...i,...i->...", b1, b1)
    g12 = np.einsum("...i,...i->...", b1, b2)
    g22 = np.einsum("...i,...i->...", b2, b2)
    r1 = np.einsum("...i,...i->...", b1, p)
    r2 = np.einsum("...i,...i->...", b2, p)
    det = g11 * g22 - g12 * g12
    regular = det > 1e-12 * g11 * g22
    safe = np.where(regular, det, 1.0)
    L = np.where(regular, (g22 * r1 - g12 * r2) / safe, 0.0)
    c = np.where(regular, (g11 * r2 - g12 * r1) / safe, 0.0)
    residual = p - L[..., None] * b1 - c[..., None] * b2
    rss = np.einsum("...i,...i->...", residual, residual)
    # A pressure: the model sqrt(d) (L + c d) must stay >= 0 over the nodes it fits, else a
    # trial edge far beyond the contact can pass through the zero nodes (a spurious minimum).
    positive = (L > 0) & (L + c * D.max(axis=-1) >= 0)
    rss = np.where(regular & positive, rss, np.inf)
    var_L = np.where(regular, g22 / safe, np.inf)
    return L, c, rss, var_L


def three_term(
    D: FloatArray, p: FloatArray
) -> tuple[FloatArray, FloatArray, FloatArray, FloatArray]:
    """(L_I, c, e, RSS) of the fit that carries one more term, e (a - x)^(5/2).

    The symmetric 3x3 normal equations are solved by cofactors, elementwise, after scaling
    each basis function to unit norm; RSS is +inf where they are singular (fewer than three
    nodes inside the trial edge).
    """
    root = np.sqrt(D)
    basis = (root, D * root, D * D * root)
    norm = [np.sqrt(np.einsum("...i,...i->...", f, f)) for f in basis]
    norm = [np.where(n > 0, n, 1.0) for n in norm]
    g = [
        [np.einsum("...i,...i->...", basis[i], basis[j]) / (norm[i] * norm[j]) for j in range(3)]
        for i in range(3)
    ]
    r = [np.einsum("...i,...i->...", basis[i], p) / norm[i] for i in range(3)]
    c00 = g[1][1] * g[2][2] - g[1][2] * g[1][2]
    c01 = g[0][2] * g[1][2] - g[0][1] * g[2][2]
    c02 = g[0][1] * g[1][2] - g[0][2] * g[1][1]
    c11 = g[0][0] * g[2][2] - g[0][2] * g[0][2]
    c12 = g[0][2] * g[0][1] - g[0][0] * g[1][2]
    c22 = g[0][0] * g[1][1] - g[0][1] * g[0][1]
    det = g[0][0] * c00 + g[0][1] * c01 + g[0][2] * c02
    regular = det > 1e-13
    safe = np.where(regular, det, 1.0)
    L = np.where(regular, (c00 * r[0] + c01 * r[1] + c02 * r[2]) / safe / norm[0], 0.0)
    c = np.where(regular, (c01 * r[0] + c11 * r[1] + c12 * r[2]) / safe / norm[1], 0.0)
    e = np.where(regular, (c02 * r[0] + c12 * r[1] + c22 * r[2]) / safe / norm[2], 0.0)
    residual = p - L[..., None] * basis[0] - c[..., None] * basis[1] - e[..., None] * basis[2]
    rss = np.einsum("...i,...i->...", residual, residual)
    # As for the two-term fit: a pressure, >= 0 at the far end of the window.
    far = D.max(axis=-1)
    positive = (L > 0) & (L + c * far + e * far**2 >= 0)
    return L, c, e, np.where(regular & positive, rss, np.inf)


def profile(
    x: FloatArray, p: FloatArray, trial: FloatArray, next_term: bool = False
) -> tuple[FloatArray, ...]:
    """The fit at each trial edge (trial: (..., m); x, p: (..., n)).

    :func:`two_term`'s (L_I, c, RSS, var factor), or with ``next_term`` :func:`three_term`'s
    (L_I, c, e, RSS).
    """
    D = np.maximum(trial[..., :, None] - x[..., None, :], 0.0)
    if next_term:
        return three_term(D, p[..., None, :])
    return two_term(D, p[..., None, :])


def minimise(
    x: FloatArray, p: FloatArray, low: float, high: float, next_term: bool = False
) -> FloatArray:
    """The trial edge of least RSS for each row of x, p (padded rows), by refined grids."""
    rows = x.shape[0]
    lo = np.full(rows, low)
    hi = np.full(rows, high)
    fractions = np.linspace(0.0, 1.0, GRID)
    for _ in range(ROUNDS):
        trial = lo[:, None] + (hi - lo)[:, None] * fractions
        rss = profile(x, p, trial, next_term)[3 if next_term else 2]
        best = trial[np.arange(rows), np.argmin(rss, axis=1)]
        step = (hi - lo) / (GRID - 1)
        lo, hi = np.maximum(best - step, low), np.minimum(best + step, high)
    middle: FloatArray = 0.5 * (lo + hi)
    return middle


def padded(
    x: FloatArray, p: FloatArray, rows: list[NDArray[np.intp]]
) -> tuple[FloatArray, FloatArray]:
    """Stack ragged node sets; padding nodes sit at +inf with p = 0 (D = 0: no weight)."""
    width = max(index.size for index in rows)
    X = np.full((len(rows), width), np.inf)
    Pv = np.zeros((len(rows), width))
    for row, index in enumerate(rows):
        X[row, : index.size] = x[index]
        Pv[row, : index.size] = p[index]
    return X, Pv
