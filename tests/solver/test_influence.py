"""The solver's influence kernels against the Flamant relations, transcribed and integrated here.

Johnson, Contact Mechanics (2.19), (2.25): a point force F along the surface of a half-plane
strains its surface by du_x/dx = -(2 (1 - nu^2)/(pi E)) F/x, and a normal force P tilts it by
du_z/dx = -(2 (1 - nu^2)/(pi E)) P/x.  For two similar bodies, 1/E* = 2 (1 - nu^2)/E, the
relative slip s = u_x2 - u_x1 (upper body loaded by q, lower by -q) has ds/dx =
+(2/(pi E*)) int q/(x - t) dt and the gap opening w = u_z1 + u_z2 has dw/dx = -(2/(pi E*))
int p/(x - t) dt.  Integrated in x (a logarithm made definite by ell) and over one element by
mpmath quadrature, they must give the generated coefficients.
"""

from __future__ import annotations

import mpmath
import numpy as np
import pytest

from asymslip_gen.solver_influence import (
    gap_opening_influence,
    relative_slip_influence,
    tension_relative_displacement,
)

E_STAR = 2.5
WIDTH = 0.01
ELL = 3.0


def slip_by_quadrature(k: int, h: float, ell: float, E_star: float) -> float:
    """(2/(pi E*)) int over the element of ln(|x_i - t|/ell) dt, x_i - t from (k -+ 1/2) h."""
    lower, upper = (k - 0.5) * h, (k + 0.5) * h
    points = [lower, 0, upper] if lower < 0 < upper else [lower, upper]
    with mpmath.workdps(30):
        integral = mpmath.quad(lambda u: mpmath.log(abs(u) / ell), points)
    return float(2 / (mpmath.pi * E_star) * integral)


@pytest.mark.parametrize("k", [0, 1, -1, 2, 17, -250, 3999])
def test_relative_slip_influence_is_the_flamant_log_kernel_over_one_element(k):
    expected = slip_by_quadrature(k, WIDTH, ELL, E_STAR)
    got = float(relative_slip_influence(k, WIDTH, ELL, E_STAR))
    # The closed form subtracts terms of size |k| ln|k| h: rounding of about |k| eps relative.
    assert got == pytest.approx(expected, rel=1e-15 * (abs(k) + 10))


@pytest.mark.parametrize("k", [0, 3, -40])
def test_gap_opening_influence_is_the_negative_of_the_relative_slip(k):
    # Pressure opens the gap where it acts (w = -(2/(pi E*)) int p ln|x - t|), shear on the
    # upper body moves the lower body the other way relative to it (s = +(2/(pi E*)) ...).
    assert float(gap_opening_influence(k, WIDTH, ELL, E_STAR)) == pytest.approx(
        -slip_by_quadrature(k, WIDTH, ELL, E_STAR), rel=1e-12
    )


def test_slope_of_the_element_kernel_is_the_flamant_point_force_slope():
    # ds/dx between elements: central difference of S(k) over 2h against the point-force
    # slope (2/(pi E*)) / u integrated over the element, (2/(pi E*)) ln((k + 1/2)/(k - 1/2)).
    k = np.arange(5, 40)
    slope = (
        relative_slip_influence(k + 1, WIDTH, ELL, E_STAR)
        - relative_slip_influence(k - 1, WIDTH, ELL, E_STAR)
    ) / (2 * WIDTH)
    point = 2 / (np.pi * E_STAR) * np.log((k + 0.5) / (k - 0.5))
    # The central difference is second order: error ~ h^2 S'''/6 relative to the slope.
    assert np.allclose(slope, point, rtol=0.5 / k**2)


def _matrix(count: int, ell: float) -> np.ndarray:
    k = np.subtract.outer(np.arange(count), np.arange(count))
    return gap_opening_influence(k, 1.0 / count, ell, 1.0)


def test_gap_opening_matrix_is_positive_definite_when_ell_is_the_grid_length():
    np.linalg.cholesky(_matrix(150, 1.0))  # raises LinAlgError unless positive definite


def test_gap_opening_matrix_is_indefinite_when_ell_is_too_short():
    # The logarithmic capacity of an interval is a quarter of its length: with ell below it
    # the kernel -ln(|x - t|/ell) is no longer positive definite.  This is why the solver
    # takes ell = the grid's length.
    with pytest.raises(np.linalg.LinAlgError):
        np.linalg.cholesky(_matrix(150, 0.1))


def test_tension_strain_is_plane_strain_bulk_strain_difference():
    # sigma_2 in the lower body, sigma_1 in the upper: eps = (1 - nu^2) sigma/E in each
    # (plane strain, sigma_zz = 0), relative strain (1 - nu^2)(sigma_2 - sigma_1)/E.
    E, nu = 210.0, 0.3
    E_star = E / (2 * (1 - nu**2))
    sigma1, sigma2 = 40.0, 90.0
    strain = (1 - nu**2) * (sigma2 - sigma1) / E
    x = np.array([-2.0, 0.5, 3.0])
    assert np.allclose(
        tension_relative_displacement(x, sigma2 - sigma1, E_star), strain * x, rtol=1e-15
    )
