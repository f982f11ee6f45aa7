"""Influence coefficients of the reference solver, from the Flamant half-plane relations.

The reference solver (``asymslip.solver``) discretises the interface of two elastically similar
bodies in plane strain into N elements of width h, with a uniform pressure p_j and a uniform
shear traction q_j on element j, and collocates at the element centres x_i.  It needs the
surface displacements at x_i caused by one loaded element, and the surface strain of a
differential bulk tension.  All follow here from one starting point:

*Flamant's point-force solution* (Johnson, Contact Mechanics, Sec. 2.2): a force per unit
thickness applied at the origin of the surface of the half-plane z > 0 (z into the body) gives
the purely radial stress sigma_rr = -(2 F / pi) cos(beta) / r, beta the angle between the
radius and the force.  For a normal force P (along +z) and a tangential force F (along +x),
in Cartesian components

    normal:      sigma_xx = -(2P/pi) x^2 z / r^4,  sigma_zz = -(2P/pi) z^3 / r^4,
                 sigma_xz = -(2P/pi) x z^2 / r^4;
    tangential:  sigma_xx = -(2F/pi) x^3 / r^4,    sigma_zz = -(2F/pi) x z^2 / r^4,
                 sigma_xz = -(2F/pi) x^2 z / r^4.

The derivation checks that these fields are in equilibrium, leave the surface z = 0 (x != 0)
free of traction, and balance the applied force on a half circle.  Plane-strain Hooke's law
(eps_yy = 0) then gives the surface displacement gradients:

* tangential force: at the surface sigma_zz = 0, so du_x/dx = eps_xx = (1 - nu^2)/E sigma_xx
  = -(2 (1 - nu^2)/(pi E)) F / x;
* normal force: d^2 u_z/dx^2 = d gamma_xz/dx - d eps_xx/dz (compatibility), evaluated as
  z -> 0, integrates (u_z' odd in x) to du_z/dx = -(2 (1 - nu^2)/(pi E)) P / x;
* a bulk stress sigma_xx = sigma (sigma_zz = 0) strains the surface by (1 - nu^2) sigma / E.

Two elastically similar bodies, the lower body (1) and the indenter (2), each described in a
frame with z into the body and the same x (the relations are symmetric in the two: which one
lies above does not enter), with 1/E* = 2 (1 - nu^2)/E (the paper's plane-strain modulus, so
that (29) reads a^2 = 4 P R/(pi E*)):

* the pressure p presses both bodies in: the gap opens by w = u_z1 + u_z2, with
  dw/dx = -(2/(pi E*)) int p(t)/(x - t) dt;
* q(x) is the shear traction the indenter exerts on the lower body (along +x), Q = int q dx;
  the indenter carries -q.  The relative tangential displacement s = u_x2 - u_x1 (the
  indenter relative to the lower body) has ds/dx = +(2/(pi E*)) int q(t)/(x - t) dt;
* the differential bulk tension sigma = sigma_2 - sigma_1 (the indenter's bulk tension minus
  the lower body's) adds ds/dx = sigma/(2 E*).

The local (1 - 2 nu) terms of Johnson's (2.25) (du_x/dx from pressure, du_z/dx from shear) are
equal in the two bodies and cancel in w and s: the normal and tangential problems uncouple.
Under full stick ds/dx = 0 on the contact, i.e. (1/pi) int q/(x - t) dt = -sigma/4: on a
Hertz contact this gives q = (Q/pi + sigma x/4)/sqrt(a^2 - x^2) and, at the right edge,
K_II = Q/(pi sqrt(2a)) + (sigma/4) sqrt(a/2), the (38) of the paper (the solver's tests check
it).  Coulomb slip: where an element slips, q = mu p sign(ds/dt).

Which body carries the tension matters.  With the lower body alone in tension sigma_L,
sigma = -sigma_L, and under full stick q = (Q/pi - sigma_L x/4)/sqrt(a^2 - x^2): the stretched
lower body pulls its surface outward, the indenter holds it back with a traction along -x at
x > 0, and K_II = Q/(pi sqrt(2a)) - (sigma_L/4) sqrt(a/2).  The paper's (20), (21) and (38),
and the asymptotic formulas derived from them, carry +sigma: the sign of sigma above, the
indenter's bulk tension minus the lower body's (equivalently, a tension of the lower body with
q taken as the traction on the indenter).  The project's convention is the second reading: the
solver (``asymslip.solver.conventions``) takes body 1 to be the indenter, so that q is the
traction on the indenter, sigma the lower body's bulk tension minus the indenter's, and the
slip it reports is delta = u_x(indenter) - u_x(lower body) = -s, opposite in sign to the change
of q in a slip zone.

Integrating the point-force relations over one element (u = x_i - t, k = (x_i - x_j)/h an
integer): the displacement of a log kernel, made definite by a reference length ell,

    int_{(k-1/2) h}^{(k+1/2) h} ln(|u|/ell) du = [u ln(|u|/ell) - u] between the ends,

so that the opening of the gap at x_i per unit pressure on element j is
W(k) = -(2/(pi E*)) [ ... ], and the relative tangential displacement per unit shear traction
is S(k) = -W(k).  A constant added to the logarithm changes w and s by a multiple of the total
load, which the rigid approach and the rigid tangential shift absorb; taking ell at least a
quarter of the grid's length makes the matrix W(i - j) positive definite (the logarithmic
capacity of an interval is a quarter of its length), which the solver's conjugate gradients
need.  The coefficients depend on i - j only: the matrices are Toeplitz, and the solver
multiplies by them with FFTs.
"""

from __future__ import annotations

import functools

import mpmath
import sympy

from asymslip.codegen import Argument, Derivation

x, z, t, u = sympy.symbols("x z t u", real=True)
k = sympy.Symbol("k", integer=True)
r_pos = sympy.Symbol("r", positive=True)
h = sympy.Symbol("h", positive=True)
ell = sympy.Symbol("ell", positive=True)
E, nu = sympy.symbols("E nu", positive=True)
E_star = sympy.Symbol("E_star", positive=True)
force = sympy.Symbol("F", real=True)
load = sympy.Symbol("P", real=True)
sigma = sympy.Symbol("sigma", real=True)
beta = sympy.Symbol("beta", real=True)

OFFSET = Argument(
    k,
    "Offset i - j, in elements, of the collocation element i from the loaded element j (an "
    "integer, so that x_i - x_j = k h never lies on an element end).",
)
WIDTH = Argument(h, "Element width h > 0 [length].")
REFERENCE = Argument(
    ell,
    "Reference length ell > 0 of the logarithm [length]; at least a quarter of the grid's "
    "length makes the influence matrix positive definite.",
)
MODULUS = Argument(E_star, "Plane-strain contact modulus E* > 0 [force/length^2].")
TENSION = Argument(
    sigma,
    "Differential bulk tension sigma = sigma_2 - sigma_1: the bulk tension of the indenter "
    "minus that of the lower body [force/length^2].",
)
POSITION = Argument(x, "Position along the interface [length].")


#: Plane-strain Hooke's law for the in-plane strains (eps_yy = 0).
def _hooke(s_xx: sympy.Expr, s_zz: sympy.Expr, s_xz: sympy.Expr) -> tuple[sympy.Expr, ...]:
    eps_xx = (1 + nu) / E * ((1 - nu) * s_xx - nu * s_zz)
    eps_zz = (1 + nu) / E * ((1 - nu) * s_zz - nu * s_xx)
    gamma_xz = 2 * (1 + nu) / E * s_xz
    return eps_xx, eps_zz, gamma_xz


def _r4() -> sympy.Expr:
    return (x**2 + z**2) ** 2


@functools.cache
def flamant_normal() -> tuple[sympy.Expr, sympy.Expr, sympy.Expr]:
    """Cartesian stresses of a normal point force P (along +z, into the half-plane z > 0)."""
    c = -2 * load / sympy.pi
    return c * x**2 * z / _r4(), c * z**3 / _r4(), c * x * z**2 / _r4()


@functools.cache
def flamant_tangential() -> tuple[sympy.Expr, sympy.Expr, sympy.Expr]:
    """Cartesian stresses of a tangential point force F (along +x) on the half-plane z > 0."""
    c = -2 * force / sympy.pi
    return c * x**3 / _r4(), c * x * z**2 / _r4(), c * x**2 * z / _r4()


def _radial_form(
    stresses: tuple[sympy.Expr, ...], direction: tuple[sympy.Expr, ...], magnitude: sympy.Expr
) -> sympy.Expr:
    """sigma - sigma_rr n n with sigma_rr = -(2 F/pi) cos(beta)/r, n = (x, z)/r."""
    r = sympy.sqrt(x**2 + z**2)
    cos_beta = (direction[0] * x + direction[1] * z) / r
    radial = -2 * magnitude / sympy.pi * cos_beta / r
    n = (x / r, z / r)
    s_xx, s_zz, s_xz = stresses
    return sympy.Matrix(
        [s_xx - radial * n[0] ** 2, s_zz - radial * n[1] ** 2, s_xz - radial * n[0] * n[1]]
    )


def _equilibrium(stresses: tuple[sympy.Expr, ...]) -> sympy.Matrix:
    s_xx, s_zz, s_xz = stresses
    return sympy.Matrix(
        [sympy.diff(s_xx, x) + sympy.diff(s_xz, z), sympy.diff(s_xz, x) + sympy.diff(s_zz, z)]
    )


def _resultant(direction: tuple[int, int], magnitude: sympy.Expr) -> sympy.Matrix:
    """Force that the material inside the half circle r = rho receives from the outside.

    The field being radial (checked first), the traction on the half circle (x, z) =
    rho (cos phi, sin phi), 0 < phi < pi, is sigma_rr n with n = (cos phi, sin phi) and
    rho sigma_rr = -(2F/pi) d.n for the force direction d.  Its sum with the applied force
    must vanish.
    """
    phi = sympy.Symbol("phi", real=True)
    n = (sympy.cos(phi), sympy.sin(phi))
    radial = -2 * magnitude / sympy.pi * (direction[0] * n[0] + direction[1] * n[1])
    return sympy.Matrix([sympy.integrate(radial * c, (phi, 0, sympy.pi)) for c in n])


def _at_surface(expr: sympy.Expr) -> sympy.Expr:
    """The value on the surface z -> 0+ away from the load (x = r > 0).

    The fields are rational in x and z with denominators powers of x^2 + z^2, continuous at
    (r, 0) for r > 0: the limit is the value there.
    """
    rational = sympy.cancel(expr.subs(x, r_pos))
    assert sympy.denom(rational).subs(z, 0) != 0, "not continuous at the surface"
    return sympy.cancel(rational.subs(z, 0))


@functools.cache
def tangential_surface_strain() -> sympy.Expr:
    """du_x/dx on the surface at x = r > 0 under the tangential point force F at 0."""
    eps_xx, _, _ = _hooke(*flamant_tangential())
    return _at_surface(eps_xx)


@functools.cache
def normal_surface_slope() -> sympy.Expr:
    """du_z/dx on the surface at x = r > 0 under the normal point force P at 0.

    Compatibility: d/dx (du_z/dx) = d gamma_xz/dx - d eps_xx/dz, at z -> 0+; integrated in x
    with the constant zero because u_z is even in x for a normal force (so u_z' is odd).
    """
    eps_xx, _, gamma_xz = _hooke(*flamant_normal())
    curvature = _at_surface(sympy.diff(gamma_xz, x) - sympy.diff(eps_xx, z))
    return sympy.integrate(curvature, r_pos)


def _per_contact_modulus(expr: sympy.Expr) -> sympy.Expr:
    """Write E in terms of E*: 1/E* = 2 (1 - nu^2)/E for two similar bodies."""
    return sympy.simplify(expr.subs(E, 2 * (1 - nu**2) * E_star))


@functools.cache
def gap_opening_slope_kernel() -> sympy.Expr:
    """dw/dx at x from a unit normal force at t, w = u_z1 + u_z2 (both bodies pressed in)."""
    one_body = normal_surface_slope().subs({load: 1, r_pos: x - t})
    return _per_contact_modulus(2 * one_body)


@functools.cache
def relative_slip_slope_kernel() -> sympy.Expr:
    """ds/dx at x from a unit shear traction on the lower body at t, s = u_x2 - u_x1.

    The lower body (1) carries +F, the indenter (2) -F, each in its own frame with z into
    the body and the same x.
    """
    per_force = tangential_surface_strain().subs({force: 1, r_pos: x - t})
    return _per_contact_modulus(-per_force - per_force)


@functools.cache
def tension_strain() -> sympy.Expr:
    """ds/dx from bulk tensions sigma_2 (indenter) and sigma_1 (lower body): eps_xx2 - eps_xx1."""
    sigma1, sigma2 = sympy.symbols("sigma_1 sigma_2", real=True)
    eps2 = _hooke(sigma2, 0, 0)[0]
    eps1 = _hooke(sigma1, 0, 0)[0]
    difference = _per_contact_modulus(eps2 - eps1)
    return sympy.simplify(difference.subs(sigma2, sigma1 + sigma))


@functools.cache
def log_element_integral() -> sympy.Expr:
    """int over element j of ln(|x_i - t|/ell) dt, with x_i - x_j = k h.

    u = x_i - t runs over ((k - 1/2) h, (k + 1/2) h).  The antiderivative of ln(|u|/ell) is
    G(u) = u ln(|u|/ell) - u on either side of u = 0 (derived for u > 0 and mirrored: ln|u| is
    even, so G is odd) and continuous through G(0) = 0, so the integral is G(upper) - G(lower)
    also for the element containing x_i (k = 0), where the integrand is singular but
    integrable.
    """
    positive_u = sympy.Symbol("v", positive=True)
    antiderivative = sympy.integrate(sympy.log(positive_u / ell), positive_u)
    assert sympy.simplify(sympy.diff(antiderivative, positive_u) - sympy.log(positive_u / ell)) == 0
    G = antiderivative.subs(positive_u, sympy.Abs(u)) * sympy.sign(u)
    G = sympy.simplify(G.subs(sympy.sign(u) * sympy.Abs(u), u))
    upper, lower = (k + sympy.Rational(1, 2)) * h, (k - sympy.Rational(1, 2)) * h
    return sympy.expand(G.subs(u, upper) - G.subs(u, lower))


@functools.cache
def gap_opening_influence() -> sympy.Expr:
    """W(k): opening of the gap at x_i per unit pressure on element j.

    dw/dx = -(2/(pi E*)) int p/(x - t) dt integrates to w = -(2/(pi E*)) int p ln(|x - t|/ell)
    dt + const.
    """
    return -2 / (sympy.pi * E_star) * log_element_integral()


@functools.cache
def relative_slip_influence() -> sympy.Expr:
    """S(k): relative tangential displacement s at x_i per unit shear traction on element j."""
    return 2 / (sympy.pi * E_star) * log_element_integral()


def _mp_element_integral(k_value: int, h_value: str, ell_value: str) -> mpmath.mpf:
    """Independent reference: mpmath quadrature of ln(|u|/ell) over the element."""
    h_mp, ell_mp = mpmath.mpf(h_value), mpmath.mpf(ell_value)
    lower, upper = (k_value - mpmath.mpf(1) / 2) * h_mp, (k_value + mpmath.mpf(1) / 2) * h_mp
    points = [lower, 0, upper] if lower < 0 < upper else [lower, upper]
    return mpmath.quad(lambda v: mpmath.log(abs(v) / ell_mp), points)


def derive() -> Derivation:
    d = Derivation(__file__)
    d.describe_module(
        "solver_influence",
        "Influence coefficients of the reference solver: surface displacements of one "
        "uniformly loaded element of a uniform grid, and the surface strain of a differential "
        "bulk tension, for two elastically similar half-planes in plane strain (from "
        "Flamant's point-force solution; beyond the paper).",
    )
    normal, tangential = flamant_normal(), flamant_tangential()
    with d.equation("F-1", "Flamant's point-force fields") as eq:
        eq.given(
            "Flamant's radial stress field sigma_rr = -(2F/pi) cos(beta)/r of a point "
            "force on a half-plane (Johnson, Contact Mechanics, Sec. 2.2)"
        )
        for name, stresses, direction, magnitude in (
            ("normal", normal, (0, 1), load),
            ("tangential", tangential, (1, 0), force),
        ):
            residual = _radial_form(stresses, direction, magnitude)
            eq.holds(
                sympy.simplify(residual).norm(),
                how=f"{name}: the Cartesian components are the radial field sigma_rr n n",
            )
            eq.holds(
                sympy.Matrix([sympy.cancel(c) for c in _equilibrium(stresses)]).norm(),
                how=f"{name}: div sigma = 0",
            )
            surface = [s.subs(z, 0) for s in stresses[1:]]
            eq.holds(
                sympy.Matrix(surface).norm(),
                how=f"{name}: sigma_zz = sigma_xz = 0 on the surface z = 0, x != 0",
            )
            applied = sympy.Matrix([force, 0] if magnitude is force else [0, load])
            eq.holds(
                (_resultant(direction, magnitude) + applied).norm(),
                how=f"{name}: the stresses on a half circle balance the applied force",
            )
    with d.equation("F-2", "Surface displacement gradients of one half-plane") as eq:
        one = 2 * (1 - nu**2) / (sympy.pi * E)
        eq.holds(
            tangential_surface_strain() + one * force / r_pos,
            how="tangential force F: du_x/dx = eps_xx = -(2 (1 - nu^2)/(pi E)) F/x "
            "(sigma_zz = 0 on the surface, plane strain)",
        )
        eq.holds(
            normal_surface_slope() + one * load / r_pos,
            how="normal force P: du_z/dx = -(2 (1 - nu^2)/(pi E)) P/x, from "
            "d^2 u_z/dx^2 = d gamma_xz/dx - d eps_xx/dz at z -> 0",
        )
    with d.equation("F-3", "Two similar bodies: uncoupled relations in E*") as eq:
        eq.beyond_paper(
            "the gap opening w = u_z1 + u_z2 and the relative slip s = u_x2 - u_x1 of two "
            "similar half-planes, 1/E* = 2 (1 - nu^2)/E; the (1 - 2 nu) local terms of each "
            "body are equal and cancel",
            derived=relative_slip_slope_kernel(),
        )
        eq.holds(
            gap_opening_slope_kernel() + 2 / (sympy.pi * E_star) / (x - t),
            how="dw/dx = -(2/(pi E*)) int p(t)/(x - t) dt",
        )
        eq.holds(
            relative_slip_slope_kernel() - 2 / (sympy.pi * E_star) / (x - t),
            how="ds/dx = +(2/(pi E*)) int q(t)/(x - t) dt, q the traction on the lower body",
        )
        local = (1 - 2 * nu) * (1 + nu) / E  # Johnson (2.25): -local p in u_x', +local q in u_z'
        p_, q_ = sympy.symbols("p q", real=True)
        eq.holds(
            (-local * p_) - (-local * p_),
            how="du_x/dx of both bodies has the same -(1 - 2nu)(1 + nu) p/E: none in ds/dx",
        )
        eq.holds(
            (local * q_) + (local * -q_),
            how="du_z/dx gets +(1 - 2nu)(1 + nu) q/E in body 1 and the opposite in body "
            "2: none in dw/dx",
        )
        # E* of the paper: (29) a^2 = 4 P R/(pi E*) follows from (1/pi) int p/(x - t) dt =
        # (E*/2) h'(x) with h = x^2/(2R) and p = p0 sqrt(1 - x^2/a^2); checked by the tests.
    with d.equation("F-4", "Relative surface strain of a differential bulk tension") as eq:
        eq.beyond_paper(
            "plane strain, sigma_xx = sigma_i, sigma_zz = 0 in body i: eps_xx = (1 - nu^2) "
            "sigma_i/E, so ds/dx gains (sigma_2 - sigma_1)/(2 E*)",
            derived=tension_strain(),
        )
        eq.holds(
            tension_strain() - sigma / (2 * E_star),
            how="ds/dx = sigma/(2 E*), sigma = sigma_2 - sigma_1",
        )
        # Its sign and size under full stick: (1/pi) int q/(x - t) = -sigma/4, so on a Hertz
        # contact q = -sigma x/(4 sqrt(a^2 - x^2)) + ..., and K_II gains +(sigma/4) sqrt(a/2).
        hilbert = sympy.Symbol("H", real=True)  # (1/pi) int q/(x - t) dt
        stick = sympy.solve(sympy.Eq(2 / E_star * hilbert + tension_strain(), 0), hilbert)[0]
        eq.holds(
            stick + sigma / 4,
            how="full stick, ds/dx = 0: (1/pi) int q/(x - t) dt = -sigma/4, the tension "
            "term of (38) (K_II = Q/(pi sqrt(2a)) + (sigma/4) sqrt(a/2))",
        )
    with d.equation("F-5", "Element influence coefficients") as eq:
        integral = log_element_integral()
        eq.beyond_paper(
            "the point-force displacements integrated over a uniform element: "
            "[u ln(|u|/ell) - u] between (k - 1/2) h and (k + 1/2) h",
            derived=integral,
        )
        half, beyond = sympy.Rational(1, 2), sympy.Symbol("k0", positive=True) + 1
        eq.holds(
            sympy.diff(integral.subs(k, (x - t) / h), x).subs({x: t + beyond * h})
            - sympy.log((beyond + half) * h / ell)
            + sympy.log((beyond - half) * h / ell),
            how="d/dx of the element integral is ln|u|/ell between the element's ends "
            "(k > 1/2): the integral of the point-force slope 1/(x - t) over the element",
        )
        function = sympy.lambdify((k, h, ell), integral, "mpmath")
        eq.matches_numerically(
            lambda k_value, h_value, ell_value: function(
                k_value, mpmath.mpf(h_value), mpmath.mpf(ell_value)
            ),
            _mp_element_integral,
            [
                {"k_value": k_, "h_value": h_, "ell_value": l_}
                for k_, h_, l_ in [
                    (0, "0.01", "2"),
                    (1, "0.01", "2"),
                    (-1, "0.01", "2"),
                    (7, "0.3", "1.5"),
                    (-250, "0.001", "4"),
                    (3999, "0.0005", "8"),
                ]
            ],
            how="mpmath quadrature of ln(|u|/ell) over the element, including the singular "
            "element k = 0",
            digits=25,
            symbolic=True,
        )
    d.emit(
        name="gap_opening_influence",
        args=(OFFSET, WIDTH, REFERENCE, MODULUS),
        expr=gap_opening_influence(),
        equations=("F-3", "F-5"),
        summary="Opening of the gap at element centre i per unit pressure on element j.",
        doc="W(k) = -(2/(pi E*)) int_{(k - 1/2) h}^{(k + 1/2) h} ln(|u|/ell) du, k = i - j: "
        "the normal surface displacements of two similar half-planes (into each body, summed) "
        "caused by a uniform unit pressure on one element, from Flamant's solution.  Defined "
        "up to a multiple of the total load (the constant ln ell), which the rigid approach "
        "absorbs.  Toeplitz in i - j; positive definite on grids shorter than 4 ell.",
        module="solver_influence",
        returns="W: displacement per unit pressure [length^3/force].",
    )
    d.emit(
        name="relative_slip_influence",
        args=(OFFSET, WIDTH, REFERENCE, MODULUS),
        expr=relative_slip_influence(),
        equations=("F-3", "F-5"),
        summary="Relative tangential displacement at element centre i per unit shear "
        "traction on element j.",
        doc="S(k) = +(2/(pi E*)) int_{(k - 1/2) h}^{(k + 1/2) h} ln(|u|/ell) du = -W(k): "
        "s = u_x2 - u_x1 (the indenter relative to the lower body) caused by a uniform unit "
        "shear traction exerted on the lower body by the indenter (the indenter carrying the "
        "opposite traction), from Flamant's solution.  Defined up to a multiple of the total "
        "shear force (the constant ln ell), which the rigid tangential shift absorbs.",
        module="solver_influence",
        returns="S: displacement per unit shear traction [length^3/force].",
    )
    d.emit(
        name="tension_relative_displacement",
        args=(POSITION, TENSION, MODULUS),
        expr=tension_strain() * x,
        equations=("F-4", "38"),
        summary="Relative tangential displacement s = u_x2 - u_x1 at x from a differential "
        "bulk tension.",
        doc="sigma x/(2 E*): plane-strain bulk strains (1 - nu^2) sigma_i/E of the two bodies, "
        "differenced, with 1/E* = 2 (1 - nu^2)/E; up to a rigid shift.  Under full stick it "
        "produces the tension term (sigma/4) sqrt(a/2) of K_II in (38).",
        module="solver_influence",
        returns="s [length].",
    )
    return d
