"""Crack-nucleation parameters: stresses and strains on a plane, and the criteria (issue 18).

Conventions: those of ``stress_half_plane`` (x along the surface, depth y into the lower body,
tension positive, plane strain).  A plane through the point contains the z axis (the usual
planes of a plane problem); its normal n = (cos theta, sin theta) makes the angle theta with
+x, towards +y (into the body), and its shear direction is t = (-sin theta, cos theta).

NC-1  The traction on the plane by rotation: sigma_n = n.s.n, tau = t.s.n (checked: the sum
      over two perpendicular planes is the trace; tau = (1/2) d sigma_n / d theta).
NC-2  Plane-strain strains on it: szz = nu (sxx + syy), eps = ((1 + nu) s - nu tr(s) I)/E in
      three dimensions, eps_n = n.eps.n and the engineering shear strain gamma = 2 t.eps.n =
      tau/G, G = E/(2 (1 + nu)) (checked).
NC-3  The criteria as their authors define them (starting points, not derived):
      Ruiz, Boddington and Chen (1984): the frictional work tau delta and the product
      sigma_T tau delta with the surface-parallel stress sigma_T (its tensile part);
      Smith, Watson and Topper (1970): sigma_n,max eps_a on the plane;
      Fatemi and Socie (1988): gamma_a (1 + k sigma_n,max / sigma_y) on the plane;
      Findley (1959): tau_a + k sigma_n,max on the plane;
      amplitudes are half the range over the cycle, maxima the largest value over it.
"""

from __future__ import annotations

import functools

import sympy

from asymslip.codegen import Argument, Derivation

from .solver_influence import _hooke

sxx, syy, sxy = sympy.symbols("sxx syy sxy", real=True)
theta = sympy.Symbol("theta", real=True)
E, nu = sympy.symbols("E nu", positive=True)
k, sigma_y = sympy.symbols("k sigma_y", positive=True)
tau_a, sigma_n_max, eps_a, gamma_a = sympy.symbols("tau_a sigma_n_max eps_a gamma_a", real=True)
tau, delta, sigma_t = sympy.symbols("tau delta sigma_T", real=True)

STRESSES = (
    Argument(sxx, "Stress sxx along the surface, tension positive [force/length^2]."),
    Argument(syy, "Stress syy normal to the surface [force/length^2]."),
    Argument(sxy, "Shear stress sxy [force/length^2]."),
)
ANGLE = Argument(
    theta,
    "Angle of the plane's normal from +x, towards +y (into the body) [rad]; the plane "
    "contains the z axis.",
)
MATERIAL = (
    Argument(E, "Young's modulus E > 0 of the lower body [force/length^2]."),
    Argument(nu, "Poisson's ratio nu of the lower body, 0 < nu < 1/2."),
)


@functools.cache
def plane_traction() -> tuple[sympy.Expr, sympy.Expr]:
    """(sigma_n, tau) on the plane of normal angle theta."""
    s = sympy.Matrix([[sxx, sxy], [sxy, syy]])
    n = sympy.Matrix([sympy.cos(theta), sympy.sin(theta)])
    t = sympy.Matrix([-sympy.sin(theta), sympy.cos(theta)])
    return sympy.expand((n.T * s * n)[0]), sympy.expand((t.T * s * n)[0])


@functools.cache
def plane_strains() -> tuple[sympy.Expr, sympy.Expr]:
    """(eps_n, gamma) on the plane: plane strain (eps_zz = 0, szz = nu (sxx + syy))."""
    eps_xx, eps_yy, gamma_xy = _hooke(sxx, syy, sxy)  # plane-strain Hooke's law
    eps = sympy.Matrix([[eps_xx, gamma_xy / 2], [gamma_xy / 2, eps_yy]])
    n = sympy.Matrix([sympy.cos(theta), sympy.sin(theta)])
    t = sympy.Matrix([-sympy.sin(theta), sympy.cos(theta)])
    return sympy.expand((n.T * eps * n)[0]), sympy.expand(2 * (t.T * eps * n)[0])


def derive() -> Derivation:
    d = Derivation(__file__)
    d.describe_module(
        "nucleation",
        "Crack-nucleation parameters: the normal and shear stress and strain on a plane "
        "through a point of the lower body (plane strain), and the criteria of Ruiz, "
        "Smith-Watson-Topper, Fatemi-Socie and Findley (beyond the paper; issue 18).",
    )
    normal, shear = plane_traction()
    eps_n, gamma = plane_strains()
    with d.equation("NC-1", "Normal and shear stress on a plane") as eq:
        eq.beyond_paper(
            "sigma_n = n.s.n and tau = t.s.n, n = (cos theta, sin theta), t = (-sin theta, "
            "cos theta)",
            derived=normal,
        )
        eq.holds(
            normal + normal.subs(theta, theta + sympy.pi / 2) - sxx - syy,
            how="two perpendicular planes carry the trace",
        )
        eq.holds(shear - sympy.diff(normal, theta) / 2, how="tau = (1/2) d sigma_n/d theta")
    with d.equation("NC-2", "Plane-strain normal and shear strain on a plane") as eq:
        szz = nu * (sxx + syy)
        trace = sxx + syy + szz
        three_d = [((1 + nu) * s_ - nu * trace) / E for s_ in (sxx, syy)]
        n2 = (sympy.cos(theta), sympy.sin(theta))
        eps_xy = (1 + nu) * sxy / E
        direct = three_d[0] * n2[0] ** 2 + three_d[1] * n2[1] ** 2 + 2 * eps_xy * n2[0] * n2[1]
        eq.holds(
            eps_n - direct,
            how="eps_n from the three-dimensional Hooke's law with szz = nu (sxx + syy)",
            derived=eps_n,
        )
        eq.holds(gamma - 2 * (1 + nu) * shear / E, how="gamma = tau/G, G = E/(2 (1 + nu))")
    with d.equation("NC-3", "Crack-nucleation criteria") as eq:
        eq.given(
            "Ruiz (tau delta, and sigma_T tau delta with sigma_T's tensile part), Smith-Watson-"
            "Topper (sigma_n,max eps_a), Fatemi-Socie (gamma_a (1 + k sigma_n,max/sigma_y)) and "
            "Findley (tau_a + k sigma_n,max), as their authors define them"
        )
    d.emit(
        name="plane_normal_stress",
        args=(*STRESSES, ANGLE),
        expr=normal,
        equations=("NC-1",),
        summary="Normal stress sigma_n on the plane of normal angle theta, tension positive.",
        doc="The plane contains the z axis; its normal makes theta with +x towards the depth.",
        module="nucleation",
        returns="sigma_n [force/length^2].",
    )
    d.emit(
        name="plane_shear_stress",
        args=(*STRESSES, ANGLE),
        expr=shear,
        equations=("NC-1",),
        summary="Shear stress tau on the plane of normal angle theta, along t = n rotated +90.",
        doc="The plane contains the z axis; its normal makes theta with +x towards the depth.",
        module="nucleation",
        returns="tau [force/length^2].",
    )
    d.emit(
        name="plane_normal_strain",
        args=(*STRESSES, ANGLE, *MATERIAL),
        expr=eps_n,
        equations=("NC-2",),
        summary="Normal strain eps_n on the plane of normal angle theta (plane strain).",
        doc="Linear elastic, isotropic; szz = nu (sxx + syy) of plane strain.",
        module="nucleation",
        returns="eps_n.",
    )
    d.emit(
        name="plane_shear_strain",
        args=(*STRESSES, ANGLE, *MATERIAL),
        expr=gamma,
        equations=("NC-2",),
        summary="Engineering shear strain gamma = tau/G on the plane of normal angle theta.",
        doc="Linear elastic, isotropic, G = E/(2 (1 + nu)).",
        module="nucleation",
        returns="gamma.",
    )
    amplitude_tau = Argument(tau_a, "Shear stress amplitude on the plane (half its range).")
    largest_normal = Argument(sigma_n_max, "Largest normal stress on the plane over the cycle.")
    constant_k = Argument(k, "The criterion's material constant k > 0.")
    d.emit(
        name="findley_parameter",
        args=(amplitude_tau, largest_normal, constant_k),
        expr=tau_a + k * sigma_n_max,
        equations=("NC-3",),
        summary="Findley's parameter tau_a + k sigma_n,max on a plane.",
        doc="Findley (1959); maximised over the planes through the point.",
        module="nucleation",
        returns="[force/length^2].",
    )
    d.emit(
        name="fatemi_socie_parameter",
        args=(
            Argument(gamma_a, "Engineering shear strain amplitude on the plane (half range)."),
            largest_normal,
            constant_k,
            Argument(sigma_y, "Yield stress sigma_y > 0 of the material."),
        ),
        expr=gamma_a * (1 + k * sigma_n_max / sigma_y),
        equations=("NC-3",),
        summary="Fatemi-Socie parameter gamma_a (1 + k sigma_n,max / sigma_y) on a plane.",
        doc="Fatemi and Socie (1988); maximised over the planes through the point.",
        module="nucleation",
        returns="dimensionless.",
    )
    d.emit(
        name="smith_watson_topper_parameter",
        args=(largest_normal, Argument(eps_a, "Normal strain amplitude on the plane.")),
        expr=sympy.Max(0, sigma_n_max) * eps_a,
        equations=("NC-3",),
        summary="Smith-Watson-Topper parameter sigma_n,max eps_a on a plane (0 in compression).",
        doc="Smith, Watson and Topper (1970): a plane that stays in compression does not open "
        "(the parameter is 0 there); maximised over the planes through the point.",
        module="nucleation",
        returns="[force/length^2].",
    )
    d.emit(
        name="ruiz_frictional_work",
        args=(
            Argument(tau, "Surface shear traction magnitude at the cycle's extremes."),
            Argument(delta, "Slip amplitude (half the peak-to-peak slip) [length]."),
        ),
        expr=tau * delta,
        equations=("NC-3",),
        summary="Ruiz's first parameter tau delta (frictional work density).",
        doc="Ruiz, Boddington and Chen (1984), along the surface of a slip zone.",
        module="nucleation",
        returns="[force/length].",
    )
    d.emit(
        name="ruiz_parameter",
        args=(
            Argument(sigma_t, "Surface-parallel stress sxx at the surface, its largest value."),
            Argument(tau, "Surface shear traction magnitude at the cycle's extremes."),
            Argument(delta, "Slip amplitude (half the peak-to-peak slip) [length]."),
        ),
        expr=sympy.Max(0, sigma_t) * tau * delta,
        equations=("NC-3",),
        summary="Ruiz's parameter sigma_T tau delta, with the tensile part of sigma_T.",
        doc="Ruiz, Boddington and Chen (1984): compression closes cracks, so only tension counts.",
        module="nucleation",
        returns="[force^2/length^3].",
    )
    return d
