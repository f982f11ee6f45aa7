"""Finite-element-like pressure traces of known contacts, and references to test against.

* :data:`LAWS`: every built-in law with its closed-form pressure ``law.pressure(x, P)``,
  scaled so that the contact half-width is 11-29 at P = 100 (the rounded flat's flat face is
  about half of its contact there, c/a = 0.53).
* :func:`mesh`: FE-like node positions: ``uniform`` (even spacing, random offset) or ``graded``
  (spacing growing smoothly by a factor 2.5 from the middle outwards, with +-15 % jitter), with
  a given number of nodes across the contact at the reference load.
* :func:`sampled_traces`: the nodal pressures of one mesh at several loads (an FE model's
  mesh does not move with the load), optionally with noise: Gaussian, standard deviation a
  given fraction of each load's peak pressure, on the nodes in contact.
* :class:`CubicProfile`: an asymmetric punch h(x) = x^2/(2R) + k x^3 pressed with a moment;
  its pressure, edges and rotation are transcribed by hand from the bounded inversion of the
  half-plane equation (see the class), independently of ``derivations/``.
* :func:`stick_boundary_of_edge`: b of (17) at one edge, with the slip direction decided as
  the core decides it (``derivations/edge_symmetry.py``), from any edge law with the methods
  of the edge contract (the calibrated edges, until the core takes them).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from asymslip import FlatRoundedLaw, HertzLaw, PowerLaw
from asymslip.calibration import Traces
from asymslip_gen.corrective_slip import stick_boundary

LAWS = {
    "hertz": HertzLaw(R=1.0, E_star=1.0),
    "flat-rounded": FlatRoundedLaw(c=10.0, R=10.0, E_star=10.0),
    "power-1.5": PowerLaw(A=0.5, n=1.5, E_star=1.0),
    "power-3": PowerLaw(A=0.01, n=3.0, E_star=1.0),
}
REFERENCE_LOAD = 100.0


def mesh(
    kind: str, half_width: float, nodes: int, rng: np.random.Generator, reach: float = 1.6
) -> np.ndarray:
    """Node positions over (-reach, reach) * half_width with ``nodes`` across 2 * half_width."""
    spacing = 2 * half_width / nodes
    if kind == "uniform":
        return np.arange(-reach * half_width, reach * half_width, spacing) + rng.uniform(0, spacing)
    # graded: x = L sinh(beta s)/sinh(beta) on even s; beta = 1.2 makes the spacing at the
    # ends of the mesh cosh(1.2) = 1.8 times that in the middle (2.5 at reach 1.6 a).
    beta, length = 1.2, reach * half_width
    middle_spacing = spacing * 0.8
    count = int(2 * length * beta / (math.sinh(beta) * middle_spacing)) + 1
    s = np.linspace(-1.0, 1.0, count)
    x = length * np.sinh(beta * s) / math.sinh(beta) + rng.uniform(-0.5, 0.5) * middle_spacing
    x += 0.3 * middle_spacing * rng.uniform(-0.5, 0.5, x.size)
    return np.sort(x)


def noisy(
    p: np.ndarray, noise: float, rng: np.random.Generator, kind: str = "relative"
) -> np.ndarray:
    """p with Gaussian noise on the nodes in contact.

    ``relative``: standard deviation noise * p at each node (an FE result's error is a fraction
    of the local pressure); ``absolute``: noise * max(p) everywhere in contact (harsher near
    the edge, where p is small).
    """
    if noise == 0:
        return p
    scale = noise * (p if kind == "relative" else p.max())
    return np.where(p > 0, p + scale * rng.standard_normal(p.size), 0.0)


def sampled_traces(
    pressure, loads, x: np.ndarray, noise: float, rng: np.random.Generator, kind: str = "relative"
) -> Traces:
    """Long-format traces of ``pressure(x, P)`` at each load on the fixed mesh x."""
    P = np.repeat(np.asarray(loads, dtype=float), x.size)
    p = np.concatenate([noisy(pressure(x, load), noise, rng, kind) for load in loads])
    return Traces.from_arrays(P, np.tile(x, len(loads)), p)


def stick_boundary_of_edge(
    edge, P1: float, P2: float, lam: float, eta: float, mu: float, side: str
) -> float:
    """b of (17) at one edge from its law: a, L_I and the edge's own L_II.

    The left edge sees lam -> -lam; the slip direction follows from L_II2 against mu L_I2 and
    backward slip is forward slip with (lam, eta) -> (-lam, -eta), as in the core.
    """
    lam_side = lam if side == "right" else -lam
    a1 = float(edge.half_width(P1))
    a2 = a1 + float(edge.half_width_growth(P1, P2 - P1))
    L_I1, L_I2 = float(edge.normal_multiplier(P1)), float(edge.normal_multiplier(P2))
    L_II2 = float(edge.shear_multiplier(P2, lam_side, eta))
    direction = 1.0 if L_II2 > mu * L_I2 else -1.0 if L_II2 < -mu * L_I2 else 0.0
    if direction == 0.0:
        return a1
    lam_o, eta_o = direction * lam_side, direction * eta
    L_II1 = float(edge.shear_multiplier(P1, lam_o, eta_o))
    L_II2 = float(edge.shear_multiplier(P2, lam_o, eta_o))
    return float(stick_boundary(mu, a1, a2, L_I1, L_I2, L_II1, L_II2))


@dataclass(frozen=True)
class CubicProfile:
    """The punch h(x) = x^2/(2R) + k x^3, rigid, on an elastically similar half-plane (E*).

    Transcribed by hand.  With contact (m - h, m + h) and rotation theta the half-plane
    equation (1/pi) PV int p(t)/(x - t) dt = (E*/2)(h'(x) - theta) has the solution bounded at
    both ends
        p(x) = (E*/(2 pi)) sqrt(h^2 - (x - m)^2) PV int G(t)/(sqrt(h^2 - (t - m)^2)(t - x)) dt
    with G = h' - theta = t/R + 3k t^2 - theta; the consistency condition
    int G / sqrt(h^2 - (t - m)^2) dt = 0 gives theta = m/R + 3k (m^2 + h^2/2).  Since
    G(t) - G(x) = (t - x)(1/R + 3k (t + x)) and PV int dt/(sqrt(...)(t - x)) = 0,
        p(x) = (E*/2) sqrt(h^2 - (x - m)^2) (1/R + 6 k m + 3 k (x - m)),
        P = int p = pi E* h^2 (1/R + 6 k m)/4,
        M = int p x = m P + 3 pi k E* h^4/16   (about x = 0),
    and the edge multipliers, p ~ L_I sqrt(distance to the edge),
        L_I,right = (E*/2) sqrt(2h) (1/R + 6 k m + 3 k h),
        L_I,left  = (E*/2) sqrt(2h) (1/R + 6 k m - 3 k h).
    """

    R: float
    k: float
    E_star: float

    def load(self, m: float, h: float) -> float:
        return math.pi * self.E_star * h**2 * (1 / self.R + 6 * self.k * m) / 4

    def moment(self, m: float, h: float) -> float:
        return m * self.load(m, h) + 3 * math.pi * self.k * self.E_star * h**4 / 16

    def rotation(self, m: float, h: float) -> float:
        return m / self.R + 3 * self.k * (m**2 + h**2 / 2)

    def pressure_of(self, m: float, h: float, x: np.ndarray) -> np.ndarray:
        inside = np.clip(h**2 - (x - m) ** 2, 0.0, None)
        return (
            0.5
            * self.E_star
            * np.sqrt(inside)
            * (1 / self.R + 6 * self.k * m + 3 * self.k * (x - m))
        )

    def multipliers(self, m: float, h: float) -> tuple[float, float]:
        """(L_I right, L_I left)."""
        base = 0.5 * self.E_star * math.sqrt(2 * h)
        return (
            base * (1 / self.R + 6 * self.k * m + 3 * self.k * h),
            base * (1 / self.R + 6 * self.k * m - 3 * self.k * h),
        )

    def contact(self, P: float, M: float) -> tuple[float, float]:
        """(m, h) carrying load P and moment M (about x = 0): Newton from the Hertz contact."""
        h = math.sqrt(4 * self.R * P / (math.pi * self.E_star))
        m = 0.0
        return _newton2(lambda m, h: (self.load(m, h) - P, self.moment(m, h) - M), m, h)

    def contact_at_rotation(
        self, P: float, theta: float, start: tuple[float, float]
    ) -> tuple[float, float]:
        """(m, h) carrying load P at rotation theta."""
        return _newton2(lambda m, h: (self.load(m, h) - P, self.rotation(m, h) - theta), *start)


def _newton2(residual, m: float, h: float) -> tuple[float, float]:
    """Newton's method on two equations in (m, h), with a finite-difference Jacobian."""
    for _ in range(60):
        f = np.array(residual(m, h))
        step_m, step_h = 1e-7 * max(abs(h), 1.0), 1e-7 * max(abs(h), 1.0)
        jac = np.column_stack(
            [
                (np.array(residual(m + step_m, h)) - f) / step_m,
                (np.array(residual(m, h + step_h)) - f) / step_h,
            ]
        )
        dm, dh = np.linalg.solve(jac, -f)
        m, h = m + dm, h + dh
        if abs(dm) + abs(dh) < 1e-14 * abs(h):
            break
    return float(m), float(h)
