"""The half-plane field of surface tractions against McEwen's closed form and Flamant quadrature.

References: :mod:`tests.stress.references` (McEwen by hand from Johnson, Sec. 7.2, itself
checked here against mpmath quadrature of Flamant's point-force fields).
"""

from __future__ import annotations

import functools

import mpmath
import numpy as np
import pytest

from asymslip.errors import InputError
from asymslip.stress import (
    SemiEllipticLoad,
    SurfaceLoad,
    half_plane_stress,
    semi_elliptic_stress,
)
from tests.stress.references import flamant_quadrature, mcewen

A, P0, MU = 1.3, 2.0, 0.3


def _grid() -> tuple[np.ndarray, np.ndarray]:
    """|x| <= 2a, 0 <= depth <= 2a; 40 columns, so no point sits on an edge (+-a, 0), where
    McEwen's m, n form is 0/0."""
    return np.meshgrid(np.linspace(-2 * A, 2 * A, 40), np.linspace(0, 2 * A, 21))


def _largest_difference(field, reference) -> float:
    return max(
        float(np.max(np.abs(getattr(field, name) - values)))
        for name, values in zip(("sxx", "syy", "sxy"), reference, strict=True)
    )


def _semi_ellipse(t) -> mpmath.mpf:
    return mpmath.sqrt(max(mpmath.mpf(0), 1 - (t / A) ** 2))


@pytest.mark.parametrize("x, z", [(0.3, 0.2), (-1.7, 0.9), (1.25, 0.01), (2.2, 1.5)])
def test_mcewen_transcription_matches_flamant_quadrature(x, z):
    expected = flamant_quadrature(
        lambda t: P0 * _semi_ellipse(t), lambda t: MU * P0 * _semi_ellipse(t), (-A, A), x, z
    )
    got = mcewen(np.array([x]), np.array([z]), A, P0, MU * P0)
    assert max(abs(float(e) - float(g[0])) for e, g in zip(expected, got, strict=True)) < 1e-12 * P0


def test_hertz_sliding_field_matches_mcewen_to_1e_10():
    """Full sliding q = mu p on a Hertz contact, from the exact (semi-elliptic) tractions."""
    x, z = _grid()
    field = semi_elliptic_stress([SemiEllipticLoad(A, p0=P0, q0=MU * P0)], x, z)
    reference = mcewen(x.ravel(), z.ravel(), A, P0, MU * P0)
    assert _largest_difference(field, reference) <= 1e-10 * P0


def test_shifted_semi_ellipses_superpose():
    """A load centred elsewhere is McEwen's field moved there (sum of two loads)."""
    x, z = _grid()
    loads = [SemiEllipticLoad(A, p0=P0), SemiEllipticLoad(0.5, q0=-0.7, centre=0.9)]
    field = semi_elliptic_stress(loads, x, z, bulk_tension=3.0)
    first = mcewen(x.ravel(), z.ravel(), A, P0, 0.0)
    second = mcewen(x.ravel() - 0.9, z.ravel(), 0.5, 0.0, -0.7)
    reference = [f + s for f, s in zip(first, second, strict=True)]
    reference[0] = reference[0] + 3.0
    assert _largest_difference(field, reference) <= 1e-10 * P0


# A piecewise-linear load that is neither symmetric nor smooth: 13 nodes, p and q unrelated.
NODES = np.array([-1.0, -0.8, -0.55, -0.4, -0.1, 0.0, 0.15, 0.3, 0.5, 0.55, 0.8, 1.1, 1.2])
PRESSURE = np.array([0, 0.4, 0.9, 1.0, 1.3, 1.2, 1.25, 1.0, 0.7, 0.75, 0.4, 0.2, 0])
SHEAR = np.array([0, -0.1, 0.2, 0.35, 0.3, -0.2, -0.4, 0.1, 0.25, 0.3, 0.2, -0.05, 0])


def _linear(values):
    def load(t):
        return mpmath.mpf(np.interp(float(t), NODES, values)) if NODES[0] < t < NODES[-1] else 0

    return load


@functools.cache
def _piecewise_quadrature(x: float, z: float) -> tuple[float, float, float]:
    """Flamant quadrature element by element (the kinks are break points)."""
    total = [mpmath.mpf(0)] * 3
    for lo, hi, p_lo, p_hi, q_lo, q_hi in zip(
        NODES[:-1], NODES[1:], PRESSURE[:-1], PRESSURE[1:], SHEAR[:-1], SHEAR[1:], strict=True
    ):

        def p(t, lo=lo, hi=hi, a=p_lo, b=p_hi):
            return a + (b - a) * (t - lo) / (hi - lo)

        def q(t, lo=lo, hi=hi, a=q_lo, b=q_hi):
            return a + (b - a) * (t - lo) / (hi - lo)

        part = flamant_quadrature(p, q, (lo, hi), x, z, digits=20)
        total = [s + v for s, v in zip(total, part, strict=True)]
    return tuple(float(v) for v in total)


@pytest.mark.parametrize(
    "x, z",
    [(0.2, 0.3), (-0.55, 0.05), (0.55, 1e-4), (1.6, 0.4), (-2.5, 2.0), (0.0, 0.7)],
)
@pytest.mark.parametrize("method", ["fast", "direct"])
def test_piecewise_linear_field_matches_flamant_quadrature(x, z, method):
    load = SurfaceLoad.from_nodes(NODES, PRESSURE, SHEAR)
    field = half_plane_stress(load, [x], [z], method=method)
    expected = _piecewise_quadrature(x, z)
    got = (field.sxx[0], field.syy[0], field.sxy[0])
    assert max(abs(e - g) for e, g in zip(expected, got, strict=True)) < 1e-12


def test_surface_values_are_minus_the_tractions_everywhere_including_nodes():
    load = SurfaceLoad.from_nodes(NODES, PRESSURE, SHEAR)
    x = np.concatenate([NODES, np.linspace(-1.5, 1.5, 61)])
    field = half_plane_stress(load, x, 0.0)
    assert np.max(np.abs(field.syy + np.interp(x, NODES, PRESSURE))) < 1e-14
    assert np.max(np.abs(field.sxy + np.interp(x, NODES, SHEAR))) < 1e-14
    assert np.all(np.isfinite(field.sxx))


def test_surface_sxx_is_the_principal_value_of_the_shear():
    """sxx(x, 0) = -p(x) - (2/pi) PV int q(t)/(x - t) dt, against mpmath's principal value."""
    load = SurfaceLoad.from_nodes(NODES, PRESSURE, SHEAR)
    x = 0.37
    field = half_plane_stress(load, [x], [0.0])
    shear = _linear(SHEAR)
    # The symmetric principal value, cut at x -+ e: the cut changes it by O(e q'); the
    # load's kinks are break points of the quadrature.
    e = mpmath.mpf("1e-12")
    below = [mpmath.mpf(t) for t in NODES if t < x] + [x - e]
    above = [x + e] + [mpmath.mpf(t) for t in NODES if t > x]
    pv = mpmath.quad(lambda t: shear(t) / (x - t), below) + mpmath.quad(
        lambda t: shear(t) / (x - t), above
    )
    expected = -np.interp(x, NODES, PRESSURE) - 2 / np.pi * float(pv)
    assert abs(field.sxx[0] - expected) < 1e-9


def test_fast_sum_equals_direct_sum_at_random_points():
    rng = np.random.default_rng(7)
    t = np.linspace(-1.1, 1.1, 2001)
    p = np.sqrt(np.maximum(0, 1 - t**2))
    q = 0.3 * p * np.tanh(4 * t)
    load = SurfaceLoad.from_nodes(t, p, q)
    x = rng.uniform(-1.6, 1.6, 3000)
    z = rng.uniform(0, 0.6, 3000) ** 2
    z[:300] = 0.0
    x[:60] = t[rng.integers(0, t.size, 60)]  # surface points on nodes
    fast = half_plane_stress(load, x, z)
    direct = half_plane_stress(load, x, z, method="direct")
    for name in ("sxx", "syy", "sxy"):
        assert np.max(np.abs(getattr(fast, name) - getattr(direct, name))) < 1e-11


def test_interpolated_hertz_tractions_converge_to_mcewen():
    """The exact sliding tractions sampled at 4001 nodes: measured 2.6e-5 p0 off McEwen (the
    linear interpolation of the square root at the edges; 8.0e-5 at 2001 nodes)."""
    x, z = _grid()
    reference = mcewen(x.ravel(), z.ravel(), A, P0, MU * P0)
    errors = []
    for count in (2001, 4001):
        t = np.linspace(-A, A, count)
        p = P0 * np.sqrt(np.maximum(0, 1 - (t / A) ** 2))
        field = half_plane_stress(SurfaceLoad.from_nodes(t, p, MU * p), x, z)
        errors.append(_largest_difference(field, reference))
    assert errors[1] < 4e-5 * P0
    assert errors[1] < errors[0] / 2.5  # at least N^-1.3


def test_bulk_tension_adds_to_sxx_only():
    load = SurfaceLoad.from_nodes(NODES, PRESSURE, SHEAR)
    plain = half_plane_stress(load, [0.1, 2.0], [0.2, 0.0])
    pulled = half_plane_stress(load, [0.1, 2.0], [0.2, 0.0], bulk_tension=0.25)
    assert np.allclose(pulled.sxx - plain.sxx, 0.25, rtol=0, atol=1e-15)
    assert np.array_equal(pulled.syy, plain.syy) and np.array_equal(pulled.sxy, plain.sxy)


@pytest.mark.parametrize(
    "nodes, pressure, shear, parameter",
    [
        ([0, 1, 0.5], [0, 1, 0], [0, 0, 0], "nodes"),
        ([0, 1, 2], [1, 1, 0], [0, 0, 0], "pressure"),
        ([0, 1, 2], [0, 1, 0], [0, 0, 0.1], "shear"),
        ([0, 1], [0, 0], [0, 0], "nodes"),
        ([0, 1, 2], [0, np.nan, 0], [0, 0, 0], "pressure"),
    ],
)
def test_a_malformed_load_is_refused_naming_it(nodes, pressure, shear, parameter):
    with pytest.raises(InputError) as caught:
        SurfaceLoad.from_nodes(nodes, pressure, shear)
    assert caught.value.parameter == parameter


def test_a_point_above_the_surface_is_refused():
    load = SurfaceLoad.from_nodes(NODES, PRESSURE, SHEAR)
    with pytest.raises(InputError, match="depth"):
        half_plane_stress(load, [0.0], [-1e-9])
