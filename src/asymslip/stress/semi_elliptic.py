"""Exact fields of semi-elliptic surface loads: Hertz's pressure, McEwen's sliding shear, and
their superpositions (Jaeger-Ciavarella).

A :class:`SemiEllipticLoad` is p(x) = p0 sqrt(1 - ((x - c)/a)^2) and q(x) = q0 sqrt(1 - ((x -
c)/a)^2) on |x - c| < a, exerted by the indenter (conventions: :mod:`asymslip.stress`).  Its
field is closed form (``derivations/stress_half_plane.py``, HP-6), finite at every point of
the body, so the exact fields of a Hertz contact -- full sliding, or the steady partial-slip
cycle of (47), a sum of three semi-ellipses -- need no discretisation.

Examples
--------
Below the centre of a Hertz contact the largest principal shear is 0.300 p0, at depth
0.786 a (Johnson, Contact Mechanics, Sec. 4.2):

>>> import numpy as np
>>> depth = np.linspace(0.0, 2.0, 2001)
>>> field = semi_elliptic_stress([SemiEllipticLoad(1.0, p0=1.0)], 0.0, depth)
>>> shear = (field.sxx - field.syy) / 2
>>> round(float(shear.max()), 3), round(float(depth[shear.argmax()]), 3)
(0.3, 0.786)
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike

from asymslip_gen.half_plane_stress import (
    semi_ellipse_pressure_sxx,
    semi_ellipse_pressure_sxy,
    semi_ellipse_pressure_syy,
    semi_ellipse_shear_sxx,
    semi_ellipse_shear_sxy,
    semi_ellipse_shear_syy,
)

from ..errors import InputError
from .field import StressField
from .half_plane import points


@dataclass(frozen=True)
class SemiEllipticLoad:
    """p0 sqrt(1 - ((x - centre)/half_width)^2) and q0 times the same, on the contact."""

    half_width: float
    p0: float = 0.0
    q0: float = 0.0
    centre: float = 0.0

    def __post_init__(self) -> None:
        if not (np.isfinite(self.half_width) and self.half_width > 0):
            raise InputError("half_width", "must be finite and > 0", self.half_width)
        for name in ("p0", "q0", "centre"):
            if not np.isfinite(getattr(self, name)):
                raise InputError(name, "must be finite", getattr(self, name))


def semi_elliptic_stress(
    loads: Sequence[SemiEllipticLoad],
    x: ArrayLike,
    depth: ArrayLike,
    *,
    bulk_tension: float = 0.0,
) -> StressField:
    """sxx, syy, sxy at (x, depth) under the sum of ``loads`` (plus a bulk tension on sxx)."""
    xs, ys = points(x, depth)
    sxx, syy, sxy = (np.zeros(xs.size) for _ in range(3))
    for load in loads:
        local = xs - load.centre
        # Each generated field is per unit amplitude of sqrt(a^2 - t^2): p0/a of it.
        for amplitude, fields in (
            (
                load.p0,
                (semi_ellipse_pressure_sxx, semi_ellipse_pressure_syy, semi_ellipse_pressure_sxy),
            ),
            (load.q0, (semi_ellipse_shear_sxx, semi_ellipse_shear_syy, semi_ellipse_shear_sxy)),
        ):
            if amplitude == 0:
                continue
            scale = amplitude / load.half_width
            for target, field in zip((sxx, syy, sxy), fields, strict=True):
                target += scale * field(local, ys, load.half_width)
    return StressField(xs, ys, sxx, syy, sxy).with_bulk(float(bulk_tension))
