"""The crack-nucleation criteria, the material constants they need, and their values on planes.

Every formula is generated (``derivations/nucleation_criteria.py``): the stress and the
plane-strain strain on a plane whose normal makes the angle theta with +x towards the depth
(the plane contains the z axis), and the criteria of Ruiz, Smith-Watson-Topper, Fatemi-Socie
and Findley.  Over a cycle given by its states (the extremes of the load path), an amplitude
is half the range of the states' values and a maximum the largest of them.

Examples
--------
>>> criteria_from_names(["findley", "ruiz"])
(<Criterion.RUIZ: 'ruiz'>, <Criterion.FINDLEY: 'findley'>)
>>> Material(E=2e5, nu=0.3).require(Criterion.FINDLEY)
Traceback (most recent call last):
    ...
asymslip.errors.InputError: criteria: findley needs its constant k
"""

from __future__ import annotations

import enum
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from asymslip_gen.nucleation import (
    fatemi_socie_parameter,
    findley_parameter,
    plane_normal_strain,
    plane_normal_stress,
    plane_shear_strain,
    plane_shear_stress,
    smith_watson_topper_parameter,
)

from ..errors import InputError
from ..stress.field import FloatArray


class Criterion(enum.Enum):
    """A crack-nucleation criterion; the value is the name on the command line."""

    RUIZ = "ruiz"
    SWT = "swt"
    FATEMI_SOCIE = "fs"
    FINDLEY = "findley"

    @property
    def on_planes(self) -> bool:
        """A critical-plane criterion (searched over angles, at any depth)."""
        return self is not Criterion.RUIZ

    @property
    def title(self) -> str:
        return {
            Criterion.RUIZ: "Ruiz",
            Criterion.SWT: "Smith-Watson-Topper",
            Criterion.FATEMI_SOCIE: "Fatemi-Socie",
            Criterion.FINDLEY: "Findley",
        }[self]


@dataclass(frozen=True)
class Material:
    """The lower body's constants: E and nu (always), the yield stress and the criteria's k,
    the critical distance L (the theory of critical distances), each where it is needed."""

    E: float
    nu: float
    sigma_y: float | None = None
    k_findley: float | None = None
    k_fatemi_socie: float | None = None
    L: float | None = None

    def __post_init__(self) -> None:
        if not (np.isfinite(self.E) and self.E > 0):
            raise InputError("E", "must be a finite Young's modulus > 0", self.E)
        if not (np.isfinite(self.nu) and 0 < self.nu < 0.5):
            raise InputError("nu", "must be a Poisson's ratio with 0 < nu < 0.5", self.nu)
        for name in ("sigma_y", "k_findley", "k_fatemi_socie", "L"):
            value = getattr(self, name)
            if value is not None and not (np.isfinite(value) and value > 0):
                raise InputError(name, "must be finite and > 0", value)

    def require(self, criterion: Criterion) -> None:
        """Refuse a criterion whose constants are missing, naming them."""
        if criterion is Criterion.FATEMI_SOCIE and (
            self.sigma_y is None or self.k_fatemi_socie is None
        ):
            raise InputError("criteria", "fs (Fatemi-Socie) needs the yield stress and its k")
        if criterion is Criterion.FINDLEY and self.k_findley is None:
            raise InputError("criteria", "findley needs its constant k")


@dataclass(frozen=True)
class History:
    """The in-plane stresses of each state of the cycle at each point: arrays (states, points)."""

    sxx: FloatArray
    syy: FloatArray
    sxy: FloatArray

    @property
    def points(self) -> int:
        return int(self.sxx.shape[1])

    def take(self, index: np.ndarray | slice) -> History:
        return History(self.sxx[:, index], self.syy[:, index], self.sxy[:, index])


def on_planes(
    history: History, theta: FloatArray, criterion: Criterion, material: Material
) -> FloatArray:
    """The criterion at every point on planes ``theta`` (broadcast: points, or points x
    angles), from the states' stresses."""
    angles = (theta if theta.ndim == 2 else theta[:, None])[None]
    sxx, syy, sxy = (c[:, :, None] for c in (history.sxx, history.syy, history.sxy))
    normal = np.asarray(plane_normal_stress(sxx, syy, sxy, angles))
    largest = normal.max(axis=0)
    if criterion is Criterion.FINDLEY:
        assert material.k_findley is not None  # Material.require
        shear = np.asarray(plane_shear_stress(sxx, syy, sxy, angles))
        amplitude = 0.5 * (shear.max(axis=0) - shear.min(axis=0))
        value = findley_parameter(amplitude, largest, material.k_findley)
    elif criterion is Criterion.FATEMI_SOCIE:
        assert material.k_fatemi_socie is not None and material.sigma_y is not None
        strain = np.asarray(plane_shear_strain(sxx, syy, sxy, angles, material.E, material.nu))
        amplitude = 0.5 * (strain.max(axis=0) - strain.min(axis=0))
        value = fatemi_socie_parameter(
            amplitude, largest, material.k_fatemi_socie, material.sigma_y
        )
    elif criterion is Criterion.SWT:
        strain = np.asarray(plane_normal_strain(sxx, syy, sxy, angles, material.E, material.nu))
        amplitude = 0.5 * (strain.max(axis=0) - strain.min(axis=0))
        value = smith_watson_topper_parameter(largest, amplitude)
    else:
        raise InputError("criteria", f"{criterion.value} is not a critical-plane criterion")
    result: FloatArray = np.asarray(value, dtype=float)
    return result if theta.ndim == 2 else result[:, 0]


#: Angles of the coarse search, one degree apart over [0, 180).
COARSE = np.deg2rad(np.arange(180.0))
#: Golden-section steps after the coarse search: the bracket of two degrees shrinks to 1e-9 rad.
REFINEMENTS = 48
#: Points per chunk of the search (points x angles x states values at once).
CHUNK = 4096


def critical_plane(
    history: History, criterion: Criterion, material: Material
) -> tuple[FloatArray, FloatArray]:
    """(largest value over the planes, its normal angle in [0, pi)) at every point.

    A one-degree search, then golden-section refinement in the bracket of the best angle: the
    criteria are piecewise smooth in the angle (a maximum over states, an amplitude's absolute
    value), so the refined angle is the best one of its bracket to 1e-9 rad.
    """
    values, angles = np.empty(history.points), np.empty(history.points)
    step = COARSE[1] - COARSE[0]
    ratio = (np.sqrt(5.0) - 1) / 2
    for start in range(0, history.points, CHUNK):
        window = slice(start, min(start + CHUNK, history.points))
        part = history.take(window)
        grid = on_planes(
            part, np.broadcast_to(COARSE, (part.points, COARSE.size)), criterion, material
        )
        best = np.argmax(grid, axis=1)
        lo, hi = COARSE[best] - step, COARSE[best] + step
        c, d = hi - ratio * (hi - lo), lo + ratio * (hi - lo)
        fc, fd = on_planes(part, c, criterion, material), on_planes(part, d, criterion, material)
        for _ in range(REFINEMENTS):
            left = fc >= fd  # the maximum is in [lo, d]
            hi = np.where(left, d, hi)
            lo = np.where(left, lo, c)
            new_c, new_d = hi - ratio * (hi - lo), lo + ratio * (hi - lo)
            c, d = np.where(left, new_c, d), np.where(left, c, new_d)
            fresh = on_planes(part, np.where(left, c, d), criterion, material)
            # Left: the new d is the old c; right: the new c is the old d.
            fc, fd = np.where(left, fresh, fd), np.where(left, fc, fresh)
        middle = 0.5 * (lo + hi)
        refined = on_planes(part, middle, criterion, material)
        coarse = grid[np.arange(part.points), best]
        use = refined >= coarse
        values[window] = np.where(use, refined, coarse)
        folded = np.mod(np.where(use, middle, COARSE[best]), np.pi)
        angles[window] = np.where(np.pi - folded < 1e-9, 0.0, folded)  # pi is the plane 0
    return values, angles


def criteria_from_names(names: Sequence[str]) -> tuple[Criterion, ...]:
    """The criteria named (``ruiz,swt,fs,findley``), in that order, each once."""
    known = {criterion.value: criterion for criterion in Criterion}
    unknown = [name for name in names if name not in known]
    if unknown:
        raise InputError(
            "criteria", f"unknown criterion {unknown[0]!r}: choose from ruiz, swt, fs, findley"
        )
    if not names:
        raise InputError("criteria", "name at least one criterion")
    return tuple(criterion for criterion in Criterion if criterion.value in names)
