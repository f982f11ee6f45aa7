"""The half-plane field of a :class:`~asymslip.stress.tractions.SurfaceLoad`, at any points.

The field is the map HP-3 of two Cauchy integrals, P(zeta) = int p/(zeta - t) dt and Q(zeta) =
int q/(zeta - t) dt at zeta = x - i y, and their derivatives; for a piecewise-linear load each
is a sum over the nodes, sum_j c_j K(zeta - t_j) with K(v) = v log v - v (HP-4): one
logarithm per point and node.  Every formula comes from ``derivations/stress_half_plane.py``
(``asymslip_gen.half_plane_stress``); this module only decides what to sum where.

Two ways, the same numbers (to rounding; tested):

``direct``
    Every node for every point, as matrix products over chunks of points: N M logarithms.
``fast`` (default)
    The points are binned into square boxes.  Nodes within ``NEAR_FACTOR`` box radii of a
    box's centre are summed directly; the others, far from the whole box, through the Taylor
    series of K about the box's centre (HP-5), whose terms fall at least like
    (1/``NEAR_FACTOR``)^k: ``ORDER`` terms reach 1e-16 of the leading one.  The box size is
    chosen per call by a cost model (direct pairs against series terms).  A 200 x 200 grid
    near one edge of a 4,000-element load takes a fraction of a second (``make bench``).

Memory stays bounded: no array holds more than about ``CHUNK`` (point, node) pairs.

Surface points (y = 0) get the principal value: HP-2's limit from inside the body, with the
angle of a node taken from above (atan2(-0.0, u)).  A surface point exactly on a node has the
node's logarithm replaced by a finite number: every term it enters is multiplied by u or y,
both zero there.

Examples
--------
A triangular pressure and shear on (-1, 1): on the surface the body carries minus them.

>>> from asymslip.stress import SurfaceLoad
>>> load = SurfaceLoad.from_nodes([-1.0, 0.0, 1.0], [0.0, 2.0, 0.0], [0.0, 0.5, 0.0])
>>> field = half_plane_stress(load, [0.0, 0.5], [0.0, 0.0])
>>> field.syy.tolist(), field.sxy.tolist()
([-2.0, -1.0], [-0.5, -0.25])
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Literal

import numpy as np
from numpy.typing import ArrayLike, NDArray

from asymslip_gen.half_plane_stress import (
    half_plane_node_angle,
    half_plane_node_log_distance,
    half_plane_node_potential_imag,
    half_plane_node_potential_real,
    half_plane_node_series_factor,
    half_plane_node_sum_imag,
    half_plane_node_sum_real,
    half_plane_potential_sxx,
    half_plane_potential_sxy,
    half_plane_potential_syy,
)

from ..errors import InputError, as_float_array
from .field import FloatArray, StressField
from .tractions import SurfaceLoad

Method = Literal["fast", "direct"]

#: Near nodes lie within this many box radii of the box centre; the series converges like
#: (1/NEAR_FACTOR)^k on the rest.
NEAR_FACTOR = 3.0
#: Terms of the far-field series: (1/3)^34 = 6e-17.
ORDER = 34
#: Most (point, node) pairs held at once.
CHUNK = 1 << 20
#: Cost of one series term of one far node relative to one direct (point, node) pair
#: (measured: complex multiply-add against two transcendentals and four kernel calls).
SERIES_COST = 0.12


@dataclass(frozen=True)
class _Potentials:
    """Re Q, Im Q, Im P and the real and imaginary parts of Q' and P' at each point."""

    Qr: FloatArray
    Qi: FloatArray
    Pi: FloatArray
    dQr: FloatArray
    dQi: FloatArray
    dPr: FloatArray
    dPi: FloatArray

    @classmethod
    def zeros(cls, count: int) -> _Potentials:
        return cls(*(np.zeros(count) for _ in range(7)))


def half_plane_stress(
    load: SurfaceLoad,
    x: ArrayLike,
    depth: ArrayLike,
    *,
    bulk_tension: float = 0.0,
    method: Method = "fast",
) -> StressField:
    """sxx, syy, sxy of the lower half-plane at the points (x, depth) under ``load``.

    Parameters
    ----------
    load
        Pressure and shear traction exerted by the indenter (conventions:
        :mod:`asymslip.stress`).
    x, depth
        The points, broadcast together and flattened; depth >= 0 (0: the surface, as a
        principal value).
    bulk_tension
        Added to sxx everywhere: the lower body's bulk tension sigma.
    method
        ``"fast"`` (near nodes directly, far nodes by series) or ``"direct"`` (every node).

    Returns
    -------
    StressField
        Flat arrays in the order of the broadcast points.
    """
    xs, ys = points(x, depth)
    if method == "direct":
        potentials = _direct(load, xs, ys)
    elif method == "fast":
        potentials = _fast(load, xs, ys)
    else:
        raise InputError("method", "must be 'fast' or 'direct'", method)
    return _stresses(xs, ys, potentials).with_bulk(float(bulk_tension))


def points(x: ArrayLike, depth: ArrayLike) -> tuple[FloatArray, FloatArray]:
    """The points (x, depth) broadcast and flattened, checked: finite, depth >= 0."""
    xs = as_float_array("x", x)
    ys = as_float_array("depth", depth)
    if np.any(ys < 0):
        raise InputError("depth", "must be >= 0 (depth into the lower body)")
    try:
        xs, ys = np.broadcast_arrays(xs, ys)
    except ValueError:
        raise InputError("depth", "must broadcast with x (one depth per point, or one)") from None
    # +0.0 for a -0.0 depth: the surface's angles are those seen from inside the body.
    return np.ascontiguousarray(xs, dtype=float).ravel(), ys.ravel() + 0.0


def _stresses(xs: FloatArray, ys: FloatArray, w: _Potentials) -> StressField:
    args = (w.Qr, w.Qi, w.Pi, w.dQr, w.dQi, w.dPr, w.dPi, ys)
    return StressField(
        xs,
        ys,
        np.asarray(half_plane_potential_sxx(*args), dtype=float),
        np.asarray(half_plane_potential_syy(*args), dtype=float),
        np.asarray(half_plane_potential_sxy(*args), dtype=float),
    )


def _pair_sums(
    xs: FloatArray,
    ys: FloatArray,
    nodes: FloatArray,
    weights: NDArray[np.float64],
    origin: float,
) -> tuple[FloatArray, ...]:
    """The seven potential parts at the points from the given nodes, summed directly.

    ``weights`` has two columns, the shear's and the pressure's slope jumps at the nodes.
    Positions are taken from ``origin`` (near the points), so that the weighted sums of HP-4
    do not cancel: x A_L - B_L = sum c_j (x - t_j) L_j.
    """
    x = xs - origin
    t = nodes - origin
    u = x[:, None] - t[None, :]
    y = ys[:, None]
    theta = half_plane_node_angle(u, y)
    on_node = (u == 0) & (y == 0)
    log_r = half_plane_node_log_distance(np.where(on_node, 1.0, u), y)
    parts = []
    for column in (0, 1):  # shear, pressure
        c = np.ascontiguousarray(weights[:, column])
        ct = c * t
        # Matrix-vector products: OpenBLAS's threaded matrix-matrix product of these skinny
        # shapes was measured 30 times slower on a busy two-core machine.
        A_L, B_L = log_r @ c, log_r @ ct
        A_theta, B_theta = theta @ c, theta @ ct
        A_1, B_1 = float(c.sum()), float(ct.sum())
        parts.append(
            (
                half_plane_node_sum_real(x, ys, A_L, B_L, A_theta, A_1, B_1),
                half_plane_node_sum_imag(x, ys, A_theta, B_theta, A_L, A_1),
                A_L,
                A_theta,
            )
        )
    (Qr, Qi, dQr, dQi), (_, Pi, dPr, dPi) = parts
    return tuple(np.asarray(part, dtype=float) for part in (Qr, Qi, Pi, dQr, dQi, dPr, dPi))


def _accumulate(
    target: _Potentials, index: NDArray[np.intp] | slice, parts: tuple[FloatArray, ...]
) -> None:
    for name, part in zip(("Qr", "Qi", "Pi", "dQr", "dQi", "dPr", "dPi"), parts, strict=True):
        getattr(target, name)[index] += part


def _weights(load: SurfaceLoad) -> NDArray[np.float64]:
    cp, cq = load.slope_jumps()
    return np.ascontiguousarray(np.stack([cq, cp], axis=1))


def _direct(load: SurfaceLoad, xs: FloatArray, ys: FloatArray) -> _Potentials:
    weights = _weights(load)
    result = _Potentials.zeros(xs.size)
    step = max(1, CHUNK // load.nodes.size)
    for start in range(0, xs.size, step):
        window = slice(start, start + step)
        origin = float(np.median(xs[window]))
        parts = _pair_sums(xs[window], ys[window], load.nodes, weights, origin)
        _accumulate(result, window, parts)
    return result


# --- the fast sum --------------------------------------------------------------------------------
@dataclass(frozen=True)
class _Boxes:
    """Points binned into boxes: each box's points, centre, radius and near-node range."""

    order: NDArray[np.intp]  # point indices sorted by box
    starts: NDArray[np.intp]  # box b holds order[starts[b]:starts[b + 1]]
    cx: FloatArray
    cy: FloatArray
    radius: FloatArray
    near_lo: NDArray[np.intp]  # near nodes of box b: nodes[near_lo[b]:near_hi[b]]
    near_hi: NDArray[np.intp]

    @property
    def count(self) -> int:
        return int(self.cx.size)


def _bin(xs: FloatArray, ys: FloatArray, nodes: FloatArray, side: float) -> _Boxes:
    ix = np.floor((xs - xs.min()) / side).astype(np.int64)
    iy = np.floor(ys / side).astype(np.int64)
    key = ix * (int(iy.max()) + 1) + iy
    order = np.argsort(key, kind="stable")
    keys, starts = np.unique(key[order], return_index=True)
    starts = np.append(starts, xs.size)
    # Centre of each box's points (the bounding box's middle) and the radius around it.
    box_of = np.repeat(np.arange(keys.size), np.diff(starts))
    xo, yo = xs[order], ys[order]
    xmin = np.minimum.reduceat(xo, starts[:-1])
    xmax = np.maximum.reduceat(xo, starts[:-1])
    ymin = np.minimum.reduceat(yo, starts[:-1])
    ymax = np.maximum.reduceat(yo, starts[:-1])
    cx, cy = 0.5 * (xmin + xmax), 0.5 * (ymin + ymax)
    distance = np.hypot(xo - cx[box_of], yo - cy[box_of])
    # A floor on the radius keeps a box of one point (or of coincident points) off its nodes.
    radius = np.maximum(np.maximum.reduceat(distance, starts[:-1]), 0.25 * side)
    reach = NEAR_FACTOR * radius
    half = np.sqrt(np.maximum(reach**2 - cy**2, 0.0))
    near_lo = np.searchsorted(nodes, cx - half, side="left")
    near_hi = np.searchsorted(nodes, cx + half, side="right")
    near_hi = np.where(half > 0, near_hi, near_lo)
    return _Boxes(order, starts, cx, cy, radius, near_lo, near_hi)


def _cost(boxes: _Boxes, nodes: int) -> float:
    points = np.diff(boxes.starts)
    near = boxes.near_hi - boxes.near_lo
    return float(np.sum(points * near) + SERIES_COST * boxes.count * nodes * ORDER)


def _choose_boxes(xs: FloatArray, ys: FloatArray, nodes: FloatArray) -> _Boxes:
    """The box size of least modelled cost, from the finest node spacing upwards."""
    extent = max(float(np.ptp(xs)), float(np.ptp(ys)), float(np.min(np.diff(nodes))))
    side = float(np.median(np.diff(nodes)))
    best: _Boxes | None = None
    best_cost = math.inf
    while True:
        boxes = _bin(xs, ys, nodes, side)
        cost = _cost(boxes, nodes.size)
        if cost < best_cost:
            best, best_cost = boxes, cost
        if boxes.count == 1 or side > 2 * extent:
            break
        side *= 2.0
    assert best is not None
    return best


def _fast(load: SurfaceLoad, xs: FloatArray, ys: FloatArray) -> _Potentials:
    nodes = load.nodes
    weights = _weights(load)
    boxes = _choose_boxes(xs, ys, nodes)
    result = _Potentials.zeros(xs.size)
    # Near nodes, directly, box by box (a box's points in chunks if it holds very many).
    for b in range(boxes.count):
        lo, hi = int(boxes.near_lo[b]), int(boxes.near_hi[b])
        if hi <= lo:
            continue
        members = boxes.order[boxes.starts[b] : boxes.starts[b + 1]]
        step = max(1, CHUNK // (hi - lo))
        for start in range(0, members.size, step):
            index = members[start : start + step]
            origin = float(boxes.cx[b])
            parts = _pair_sums(xs[index], ys[index], nodes[lo:hi], weights[lo:hi], origin)
            _accumulate(result, index, parts)
    # Far nodes, through each box's series, boxes in chunks.
    step = max(1, CHUNK // nodes.size)
    for first in range(0, boxes.count, step):
        chunk = np.arange(first, min(first + step, boxes.count))
        _far_field(result, boxes, chunk, xs, ys, nodes, weights)
    return result


def _far_field(
    result: _Potentials,
    boxes: _Boxes,
    chunk: NDArray[np.intp],
    xs: FloatArray,
    ys: FloatArray,
    nodes: FloatArray,
    weights: NDArray[np.float64],
) -> None:
    """Add, for the boxes of ``chunk``, the far nodes' potentials through their series.

    About the centre zeta0 of a box, K(zeta0 + d - t_j) = K(v_j) + log(v_j) d + sum_{k>=2}
    factor(k) v_j^(1 - k) d^k with v_j = zeta0 - t_j (HP-5).  Each coefficient sums every
    node (a matrix product) and then takes the box's near nodes back out; each point
    evaluates the polynomial and its derivative in d = zeta - zeta0.
    """
    cx, cy = boxes.cx[chunk], boxes.cy[chunk]
    lo, hi = boxes.near_lo[chunk], boxes.near_hi[chunk]
    u0 = cx[:, None] - nodes[None, :]
    # The near nodes' columns are summed and taken back out; they are first moved to the
    # series' radius of convergence, so that a node close to a box's centre does not put
    # a huge power (or a log of zero) into the sum and cancel every digit of the far ones.
    index = np.arange(nodes.size)
    near_columns = (index[None, :] >= lo[:, None]) & (index[None, :] < hi[:, None])
    fill = NEAR_FACTOR * boxes.radius[chunk] + cy
    u0 = np.where(near_columns, fill[:, None], u0)
    y0 = np.broadcast_to(cy[:, None], u0.shape)
    log_r = np.asarray(half_plane_node_log_distance(u0, y0), dtype=float)
    theta = np.asarray(half_plane_node_angle(u0, y0), dtype=float)
    near = [(b, int(lo[b]), int(hi[b])) for b in range(chunk.size) if hi[b] > lo[b]]
    columns = [np.ascontiguousarray(weights[:, column]) for column in (0, 1)]

    def far_sum(real: FloatArray, imaginary: FloatArray) -> NDArray[np.complex128]:
        """sum over the far nodes of (real + i imaginary)(boxes x nodes) times the two weight
        columns: real matrix products, then each box's near nodes taken back out."""
        total = np.empty((real.shape[0], 2), dtype=complex)
        for column, w in enumerate(columns):  # matrix-vector products (see _pair_sums)
            total[:, column] = (real @ w) + 1j * (imaginary @ w)
            for b, first, last in near:
                part = w[first:last]
                total[b, column] -= real[b, first:last] @ part + 1j * (
                    imaginary[b, first:last] @ part
                )
        return total

    coefficients = np.empty((chunk.size, ORDER + 1, 2), dtype=complex)
    coefficients[:, 0] = far_sum(
        np.asarray(half_plane_node_potential_real(u0, y0, log_r, theta), dtype=float),
        np.asarray(half_plane_node_potential_imag(u0, y0, log_r, theta), dtype=float),
    )
    coefficients[:, 1] = far_sum(log_r, theta)
    # 1/v, v = u0 - i y0, and its powers v^(1 - k), k >= 2, in real arithmetic.
    modulus = u0 * u0 + y0 * y0
    inverse_re, inverse_im = u0 / modulus, y0 / modulus
    power_re, power_im = inverse_re.copy(), inverse_im.copy()
    scratch = np.empty_like(power_re)
    for k in range(2, ORDER + 1):
        coefficients[:, k] = float(half_plane_node_series_factor(k)) * far_sum(power_re, power_im)
        if k < ORDER:
            np.multiply(power_re, inverse_im, out=scratch)
            power_re *= inverse_re
            power_re -= power_im * inverse_im
            power_im *= inverse_re
            power_im += scratch
    # Each point of each box: the polynomial and its derivative by Horner's rule.
    counts = np.diff(boxes.starts)[chunk]
    members = np.concatenate([boxes.order[boxes.starts[b] : boxes.starts[b + 1]] for b in chunk])
    owner = np.repeat(np.arange(chunk.size), counts)
    d = ((xs[members] - cx[owner]) - 1j * (ys[members] - cy[owner]))[:, None]
    c = coefficients[owner]  # points x orders x (shear, pressure)
    value = c[:, ORDER].copy()
    slope = np.zeros_like(value)
    for k in range(ORDER - 1, -1, -1):
        slope = slope * d + value
        value = value * d + c[:, k]
    Q, P = value[:, 0], value[:, 1]
    dQ, dP = slope[:, 0], slope[:, 1]
    _accumulate(result, members, (Q.real, Q.imag, P.imag, dQ.real, dQ.imag, dP.real, dP.imag))
