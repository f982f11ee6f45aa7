"""Beyond the paper: the stick boundary to second order in dP with bulk tension, and why (22) errs.

**Exact steady-state conditions.**  Let D = q2 - q1 on (-a2, a2), with slip zones (b, a2) at
the right edge and (-a2, -b_L) at the left at both extremes of the cycle (the steady state of
Section 2; the other edge may slip either way).  In the slip zones D is known,
D = mu (p1 + p2) on the right and s mu (p1 + p2) on the left (s = +1 when the left edge slips
the same way as the right, -1 when it slips the opposite way; p1 = 0 beyond a1).  Points of
S = (-b_L, b) stick throughout the cycle, so the half-plane relation between the relative
surface strain and the shear traction gives (1/pi) PV int D(xi)/(xi - x) dxi = dsigma/4 on S
(the sign that makes a positive sigma give the positive K_II of (38)); D is bounded at both
ends of S, and int D = dQ.  The bounded inversion on the finite interval S (the same inversion
as (13), on a finite instead of a semi-infinite stick zone) exists only if two conditions
hold; exchanging the order of integration with the kernel identities derived below gives them
as integrals over the slip zones alone:

    (C1)  pi dsigma / 4 = int_R D dxi / sqrt((xi - b)(xi + b_L)) - int_L D dxi / sqrt(...),
    (C2)  dQ            = int_{R + L} D |xi - c0| dxi / sqrt((xi - b)(xi + b_L)),

c0 = (b - b_L)/2 the centre of S.  They are exact in the half-plane model, for any symmetric
law; without tension (C2) gives P(b) = P_K of (33) for every law (Jaeger-Ciavarella), and for
Hertz with tension and both edges slipping the same way the closed form
b = a(P_K) - R dsigma / (4 mu E*) (the pressure of the tilted profile h - theta x) satisfies
both at 30 digits.  (C1)-(C2) are checked on these below.

**Second order.**  With b = a1 - w, b_L = a1 - w_L, w = W1 dP + W2 dP^2, the edge expansion
p = L_I sqrt(a - x) + M_I (a - x)^(3/2) (M_I from (19)'s superposition, next order), the
law's Taylor coefficients a1, a'(P1), a''(P1), and Beta integrals, (C1)-(C2) are solved order
by order.  The result, with r = (lam + pi eta a1/4)/mu, rho = lam/mu, tau = pi eta a1/(4 mu):

    a1 - b = a'(r - 1) dP/2 + [-a''(1 - r)^2/8 + a'^2 Phi/(32 a1)] dP^2 + O(dP^3),
    Phi = 4 tau (2 - 2 rho - tau)                       (other edge slips the same way),
    Phi = 2 + 8 tau - 2 rho^2 - 4 rho tau - 6 tau^2    (other edge slips the opposite way),

i.e. b = a(P_eff) - a'^2 Phi dP^2/(32 a1), P_eff = (P1 + P2)/2 - (dQ + pi a1 dsigma/4)/(2 mu):
Jaeger's P_K with the tension turned into its equivalent shear force, plus a finite-contact
term.  The first-order term is (28).

**Why (22) errs.**  (22) solves the single-edge, semi-infinite problem (12) with the first-order
asymptotes; its dP^2 term is not derived but an artefact of where (21) is evaluated.  It is
right without tension for Hertz only because a^2 is affine in P.  With tension it weights the
tension term by the moving edge, pi eta a_i L_I,i/4, although the tension acts through
sigma'(c) x / 4 at the field point: (22) evaluated with one common point for both states
removes most of the eta^2 error (Hertz, opposite edges: 7 pi^2 a1^2 eta^2 -> 3 pi^2 a1^2
eta^2 in the coefficient below).  The rest, and the dependence on the other edge, cannot come
from any single-edge expansion: carrying the next terms of every edge expansion through
(12)-(16), as the issue suggested, gives a dP^2 term that is wrong even without tension.  At
second order the stick zone is finite and both edges enter (C1)-(C2).
"""

from __future__ import annotations

import functools

import mpmath
import sympy

from asymslip.codegen import Argument, Derivation

from ._glossary import L_I1, L_I2, P1, a, a1, a2, arguments, da_dP, dL_I_dP, dP, eta, lam, mu
from .contact_law_hertz import E_star, P, R, hertz_half_width
from .generic_law_comparison import (
    CURVATURE,
    d2a_dP2,
    d3a_dP3,
    half_width_near,
    multiplier_near,
    multiplier_ratio,
    second_order_gap,
    step,
    taylor_coefficients,
)
from .section2_calibrations import (
    _edge_expansion,
    load_slope,
    shear_slope,
    stick_boundary_proportional,
    tension_slope,
)
from .section2_validity import first_order_slip_zone_width
from .section3_exact_solution import permanent_stick_load

other_edge = sympy.Symbol("other_edge", real=True)
u = sympy.Symbol("u", positive=True)  # position across a slip zone, 0 at the stick end
X = sympy.Symbol("X", positive=True)  # field point beyond a unit stick interval, X > 1
half_angle = sympy.Symbol("v", positive=True)
xi, c = sympy.symbols("xi c", positive=True)
b_right, b_left = sympy.symbols("b b_L", positive=True)
gap = sympy.Symbol("g", positive=True)  # xi - b for a point of the right slip zone
W1, W2, V1, V2 = sympy.symbols("W1 W2 V1 V2", real=True)  # right / left width coefficients

OTHER_EDGE = Argument(
    other_edge,
    "+1 when the other edge of the contact slips in the same direction as this one (the same "
    "sign of q2 - q1 there), -1 when it slips the opposite way.  For an other edge that does "
    "not slip use +1: that branch joins the -1 branch continuously where the other edge starts "
    "to slip the opposite way, but in between it is not derived (see the module notes).",
)
LOAD_CHANGE = Argument(dP, "Normal-load change P2 - P1 > 0 [force/length].")


# --- the kernel identities behind (C1)-(C2) ----------------------------------------------


@functools.cache
def unit_kernels() -> tuple[sympy.Expr, sympy.Expr, sympy.Expr]:
    """int w dtau, int w dtau/(X - tau), int w tau dtau/(X - tau) over (-1, 1), w = (1-tau^2)^-1/2.

    tau = cos(theta) makes w dtau = dtheta; the half-angle substitution v = tan(theta/2) then
    makes the second integrand rational.  The third follows from tau = X - (X - tau).
    """
    theta_of_v = 2 * sympy.atan(half_angle)
    jacobian = sympy.diff(theta_of_v, half_angle)
    cosine = (1 - half_angle**2) / (1 + half_angle**2)
    assert sympy.simplify(sympy.cos(theta_of_v) - cosine) == 0
    zeroth = sympy.integrate(jacobian, (half_angle, 0, sympy.oo))
    # 1/(X - cos) dtheta = 2 dv / ((X + 1) v^2 + (X - 1)): positive coefficients for X > 1
    alpha, beta = sympy.symbols("alpha beta", positive=True)
    integrand = sympy.factor(sympy.cancel(jacobian / (X - cosine)))
    assert sympy.cancel(integrand - 2 / ((X + 1) * half_angle**2 + X - 1)) == 0
    first = sympy.integrate(2 / (alpha * half_angle**2 + beta), (half_angle, 0, sympy.oo))
    first = sympy.simplify(first.subs({alpha: X + 1, beta: X - 1}))
    second = sympy.simplify(X * first - zeroth)
    return zeroth, first, second


def interval_kernels() -> tuple[sympy.Expr, sympy.Expr]:
    """On S = (-b_L, b), for xi = b + g > b: the (C1) and (C2) weights, from the unit kernels.

    t = c0 + l tau with c0 = (b - b_L)/2, l = (b + b_L)/2, X = (xi - c0)/l.
    """
    _, first, second = unit_kernels()
    centre, half = (b_right - b_left) / 2, (b_right + b_left) / 2
    scaled = {X: (b_right + gap - centre) / half}
    # int_S dt / (sqrt((b - t)(t + b_L)) (xi - t)) = (1/l) * first(X)
    c1_weight = sympy.simplify(first.subs(scaled) / half)
    # int_S (t - c0) dt / (sqrt(...) (xi - t)) = second(X), and (C2) adds pi (the slip-zone force)
    c2_weight = sympy.simplify(second.subs(scaled) + sympy.pi)
    return c1_weight, c2_weight


# --- the second-order expansion ------------------------------------------------------------


def _beta_moment(polynomial: sympy.Expr, half_power: int) -> sympy.Expr:
    """int_0^1 polynomial(u) u^(-1/2) (1 - u)^(half_power + 1/2) du, term by term (Beta)."""
    poly = sympy.Poly(sympy.expand(polynomial), u)
    total = sympy.S.Zero
    for (j,), coefficient in poly.terms():
        total += coefficient * sympy.beta(
            sympy.Rational(2 * j + 1, 2), sympy.Rational(2 * half_power + 3, 2)
        )
    return sympy.expand(sympy.gammasimp(total))


def _truncate(expr: sympy.Expr, order: int) -> sympy.Expr:
    expanded = sympy.expand(expr)
    return sum((expanded.coeff(dP, k) * dP**k for k in range(order + 1)), sympy.S.Zero)


@functools.cache
def pressure_edge_coefficients() -> tuple[sympy.Expr, sympy.Expr]:
    """(L_I, M_I) at P1 of p = L_I sqrt(a - x) + M_I (a - x)^(3/2), in a1, a'(P1), a''(P1).

    From the superposition behind (19), carried one order further: P'(a) = 1/a'(P),
    P''(a) = -a''/a'^3.
    """
    leading, following = _edge_expansion(lambda c_, x_: load_slope(c_) / sympy.pi)
    slopes = {sympy.Derivative(load_slope(a), a): -d2a_dP2 / da_dP**3}
    values = {load_slope(a): 1 / da_dP}
    return tuple(
        sympy.simplify(term.subs(slopes).subs(values).subs(a, a1)) for term in (leading, following)
    )


# Placeholders for L_I(P1), L_I'(P1) and M_I(P1) while expanding: the law's expressions go in
# only after the solve.  The expansion itself runs in a sparse polynomial ring over QQ (with
# 1/a1 as a generator), which keeps make generate fast.
_L, _L_slope, _M = sympy.symbols("L Ldot M", real=True)
_inverse_a1 = sympy.Symbol("inverse_a1", positive=True)
_RING, *_ = sympy.polys.rings.ring(
    [u, dP, W1, W2, V1, V2, _L, _L_slope, _M, a1, _inverse_a1, da_dP, d2a_dP2, d3a_dP3],
    sympy.QQ,
)


def _ring_truncate(poly, order: int):
    """Drop the terms of ``poly`` above dP**order."""
    position = 1  # dP is the second generator
    return _RING.from_dict({m: c for m, c in poly.items() if m[position] <= order})


def _ring_beta_moment(poly, half_power: int):
    """int_0^1 poly(u) u^(-1/2) (1 - u)^(half_power + 1/2) du / pi, term by term (Beta)."""
    result = {}
    for monomial, coefficient in poly.items():
        j = monomial[0]
        moment = sympy.beta(sympy.Rational(2 * j + 1, 2), sympy.Rational(2 * half_power + 3, 2))
        ratio = sympy.gammasimp(moment / sympy.pi)
        assert ratio.is_Rational, ratio
        key = (0, *monomial[1:])
        result[key] = result.get(key, 0) + coefficient * sympy.QQ(ratio.p, ratio.q)
    return _RING.from_dict(result)


def _slip_zone_integrals(width: sympy.Expr, other: sympy.Expr) -> tuple[sympy.Expr, sympy.Expr]:
    """sqrt(2 a1)/pi times (int f/sqrt(..), int f |xi - c0|/sqrt(..)) over one slip zone, to dP^2.

    f = p1 + p2.  ``width`` is a1 minus this edge's stick end, ``other`` the same at the other
    edge.  With xi = b + d u, d = a_i - b: p_i = L_i sqrt(d (1 - u)) + M_I (d (1 - u))^(3/2),
    xi + b_other = 2 a1 (1 - e), e = (width + other - d u)/(2 a1), 1/sqrt(1 - e) = 1 + e/2,
    |xi - c0| = a1 - (width + other)/2 + d u.  L_2 = L_1 + L_I' dP suffices (the M terms and
    the corrections are already one order down).
    """
    near = _RING(half_width_near(dP))
    states = ((_RING(_L), _RING(a1)), (_RING(_L + _L_slope * dP), near))
    this, that = _RING(width), _RING(other)
    force_sum, moment_sum = _RING(0), _RING(0)
    quarter_inverse = _RING(_inverse_a1) / 4
    for multiplier, edge in states:
        d = _ring_truncate(edge - _RING(a1) + this, 2)
        u_ = _RING(u)
        weight = _ring_truncate((1 + (this + that - d * u_) * quarter_inverse) * d, 2)
        arm = _RING(a1) - (this + that) / 2 + d * u_
        for coefficient, half_power in ((multiplier, 0), (_RING(_M) * d, 1)):
            integrand = _ring_truncate(coefficient * weight, 2)
            force_sum += _ring_beta_moment(integrand, half_power)
            moment_sum += _ring_beta_moment(_ring_truncate(integrand * arm, 3), half_power)
    unring = {_inverse_a1: 1 / a1}
    return (
        _ring_truncate(force_sum, 2).as_expr().subs(unring),
        _ring_truncate(moment_sum, 3).as_expr().subs(unring),
    )


@functools.cache
def width_coefficients(direction: int) -> dict[sympy.Symbol, sympy.Expr]:
    """W1, W2 (right) and V1, V2 (left) of the widths, other edge slipping ``direction``."""
    right = W1 * dP + W2 * dP**2
    left = V1 * dP + V2 * dP**2
    # The integrals are linear in (L, L', M): divide by L so that only M/L and L'/L enter,
    # both rational in a1, a', a''; the load terms then carry sqrt(2 a1)/L = pi a1 a' (19).
    leading, following = pressure_edge_coefficients()
    slope = sympy.diff(multiplier_near(step), step).subs(step, 0)
    per_multiplier = {
        _M: sympy.cancel(following / leading) * _L,
        _L_slope: sympy.cancel(slope / leading) * _L,
    }

    def relative(expr: sympy.Expr) -> sympy.Expr:
        return sympy.expand(sympy.expand(expr.subs(per_multiplier)) / _L)

    load_scale = sympy.cancel(sympy.sqrt(2 * a1) / leading)
    assert not load_scale.has(sympy.sqrt(a1)), load_scale
    force_r, moment_r = map(relative, _slip_zone_integrals(right, left))
    force_l, moment_l = map(relative, _slip_zone_integrals(left, right))
    # (C1), (C2) times sqrt(2 a1)/(pi L): the ring left out pi/sqrt(2 a1)
    c1 = sympy.expand(mu * (force_r - direction * force_l) - eta * dP * load_scale / 4)
    c2 = sympy.expand(mu * (moment_r + direction * moment_l) - lam * dP * load_scale / sympy.pi)
    assert c1.coeff(dP, 0) == 0 and c2.coeff(dP, 0) == 0
    first = _solve_linear([c1.coeff(dP, 1), c2.coeff(dP, 1)], (W1, V1))
    second_eqs = [sympy.expand(c.coeff(dP, 2).subs(first)) for c in (c1, c2)]
    second = _solve_linear(second_eqs, (W2, V2))
    solution = {**first, **second}
    return {symbol: sympy.factor(solution[symbol]) for symbol in (W1, V1, W2, V2)}


def _solve_linear(equations: list[sympy.Expr], unknowns: tuple[sympy.Symbol, sympy.Symbol]):
    """Cramer's rule for two equations linear in two unknowns (each expanded)."""
    (x1, x2), rows = unknowns, []
    for equation in equations:
        equation = sympy.expand(equation)
        a_, b_ = equation.coeff(x1), equation.coeff(x2)
        rest = sympy.expand(equation - a_ * x1 - b_ * x2)
        assert not rest.has(x1, x2), "not linear"
        rows.append((a_, b_, -rest))
    (a11, a12, r1), (a21, a22, r2) = rows
    determinant = sympy.cancel(a11 * a22 - a12 * a21)
    assert determinant != 0
    return {
        x1: sympy.cancel((r1 * a22 - a12 * r2) / determinant),
        x2: sympy.cancel((a11 * r2 - r1 * a21) / determinant),
    }


@functools.cache
def second_order_width() -> sympy.Expr:
    """a1 - b through dP^2, both branches in one expression (other_edge = +1 or -1)."""
    same, opposite = width_coefficients(+1), width_coefficients(-1)
    assert sympy.simplify(same[W1] - opposite[W1]) == 0, (
        "the first order must not see the other edge"
    )
    coefficient = (1 + other_edge) / 2 * same[W2] + (1 - other_edge) / 2 * opposite[W2]
    return same[W1] * dP + sympy.factor(sympy.simplify(coefficient)) * dP**2


def width_second_coefficient() -> sympy.Expr:
    """W2: the coefficient of dP^2 in a1 - b, i.e. (28)'s error is -W2 dP^2 in b."""
    return sympy.expand(second_order_width()).coeff(dP, 2)


def paper_width_coefficients() -> list[sympy.Expr]:
    """dP^0..dP^2 coefficients of a1 - b(22) along the law, with tension."""
    ratio = sympy.Symbol("rho", positive=True)
    in_ratio = sympy.cancel(stick_boundary_proportional().subs(L_I2, ratio * L_I1))
    assert not in_ratio.has(L_I1)
    along = in_ratio.subs({a2: half_width_near(dP), ratio: multiplier_ratio()})
    return taylor_coefficients(a1 - along, 2)


@functools.cache
def paper_error_coefficient() -> sympy.Expr:
    """E with b(22) - b = E dP^2 + O(dP^3) (both branches, other_edge = +-1)."""
    return sympy.factor(sympy.simplify(width_second_coefficient() - paper_width_coefficients()[2]))


# --- the single-edge route of (12)-(16) carried one order further (for the record) ---------


@functools.cache
def single_edge_second_coefficient() -> sympy.Expr:
    """W2 from (12)-(16) with the next term of every edge expansion (semi-infinite stick zone).

    Consistency of the bounded inversion: int_b^a2 g(x)/sqrt(x - b) dx = 0 with
    g = mu (p1 + p2) - (T(a2) - T(a1)), T the full-stick traction (the superposition behind
    (20), with the tension kernel sigma'(c) x/4 at the field point), each edge-expanded to
    (a - x)^(3/2); int_b^a s^(1/2)/sqrt(x - b) = pi d/2, int s^(3/2)/sqrt(x - b) = 3 pi d^2/8.
    """
    normal = _edge_expansion(lambda c_, x_: load_slope(c_) / sympy.pi)
    shear = _edge_expansion(lambda c_, x_: shear_slope(c_) / sympy.pi + tension_slope(c_) * x_ / 4)

    def at(expr: sympy.Expr, h: sympy.Expr) -> sympy.Expr:
        """A coefficient at load P1 + h on the proportional path (dQ = lam dP, dsig = eta dP)."""
        expr = expr.replace(shear_slope, lambda arg: lam * load_slope(arg))
        expr = expr.replace(tension_slope, lambda arg: eta * load_slope(arg)).doit()
        slope = sympy.diff(half_width_near(step), step).subs(step, h)
        curvature = sympy.diff(half_width_near(step), step, 2).subs(step, h)
        expr = expr.subs(sympy.Derivative(load_slope(a), a), -curvature / slope**3)
        return expr.subs(load_slope(a), 1 / slope).subs(a, half_width_near(h))

    # Every coefficient relative to L_I(P1), to first order in dP at state 2 (the (a - x)^(3/2)
    # terms are one order down already).
    base = at(normal[0], sympy.S.Zero)
    width = W1 * dP + W2 * dP**2
    total = sympy.S.Zero
    for sign, state in ((+1, 1), (-1, 2)):
        d = _truncate(half_width_near(dP if state == 2 else 0) - a1 + width, 2)
        for (p_term, q_term), power in zip(zip(normal, shear, strict=True), (1, 2), strict=True):
            coefficient = mu * p_term + sign * q_term
            value = sympy.cancel(at(coefficient, step) / base)
            scaled = value.subs(step, 0)
            if state == 2 and power == 1:
                scaled += sympy.cancel(sympy.diff(value, step).subs(step, 0)) * dP
            integral = sympy.pi / 2 * d if power == 1 else 3 * sympy.pi / 8 * d**2
            total += _truncate(scaled * integral, 2)
    total = sympy.expand(total)
    first = _solve_one(total.coeff(dP, 1), W1)
    second = _solve_one(sympy.expand(total.coeff(dP, 2).subs(W1, first)), W2)
    return sympy.factor(second)


def _solve_one(equation: sympy.Expr, unknown: sympy.Symbol) -> sympy.Expr:
    slope = equation.coeff(unknown)
    rest = sympy.expand(equation - slope * unknown)
    assert not rest.has(unknown)
    return sympy.cancel(-rest / slope)


# --- numbers: Hertz, pure tension, edges slipping opposite ways (one unknown, elliptic) -----


def hertz_pure_tension_width(p1, p2, mu_, eta_, radius=1, modulus=1):
    """Exact a1 - b from (C1) for Hertz, lam = 0 (then b_L = b and (C2) holds by symmetry).

    int_b^a sqrt(a^2 - xi^2)/sqrt(xi^2 - b^2) dxi = a (K(m) - E(m)), m = 1 - b^2/a^2, so (C1)
    reads pi eta dP/4 = mu (E*/R) sum_i a_i (K(m_i) - E(m_i)) with p = (E*/2R) sqrt(a^2 - x^2).
    """

    def half(load):
        return mpmath.sqrt(4 * load * radius / (mpmath.pi * modulus))

    edges = (half(p1), half(p2))

    def residual(width):
        stick = edges[0] - width
        total = mpmath.mpf(0)
        for edge in edges:
            m = 1 - (stick / edge) ** 2
            total += edge * (mpmath.ellipk(m) - mpmath.ellipe(m))
        return mu_ * modulus / radius * total - mpmath.pi * eta_ * (p2 - p1) / 4

    guess = (edges[1] - edges[0]) * (mpmath.pi * eta_ * edges[0] / (4 * mu_) - 1) / 2
    return mpmath.findroot(residual, guess)


def _hertz_numbers(p1) -> list[mpmath.mpf]:
    """a1, a'(P1), a''(P1) of Hertz (R = E* = 1) at mpmath precision, from (29)."""
    law = hertz_half_width().subs({R: 1, E_star: 1})
    values = [law, sympy.diff(law, P), sympy.diff(law, P, 2)]
    return [mpmath.mpf(sympy.N(v.subs(P, p1), mpmath.mp.dps + 10)) for v in values]


def _evaluate(expr: sympy.Expr, values: dict) -> mpmath.mpf:
    function = sympy.lambdify(list(values), expr, modules="mpmath")
    return function(*values.values())


def pure_tension_table(ratios=("1.02", "1.05", "1.1")) -> list[tuple]:
    """(ratio, exact width, relative width errors of (22), (28), b2) for Hertz.

    R = E* = 1, P1 = 100, mu = 0.3, lam = 0, eta = 0.06 (pi eta a1/4 = 1.77 mu: the edges slip
    opposite ways), at a2/a1 = ratios; (22) with the true Hertz a2, L_I2 (no series).
    """
    rows = []
    paper = stick_boundary_proportional()
    with mpmath.workdps(30):
        p1, mu_, eta_ = mpmath.mpf(100), mpmath.mpf("0.3"), mpmath.mpf("0.06")
        a1_, slope, curvature = _hertz_numbers(p1)
        for ratio in ratios:
            p2 = p1 * mpmath.mpf(ratio) ** 2
            exact = hertz_pure_tension_width(p1, p2, mu_, eta_)
            a2_ = _hertz_half(p2)
            # (31): L_I proportional to sqrt(a) for Hertz; (22) needs only the ratio
            b22 = _evaluate(
                paper,
                {
                    mu: mu_,
                    lam: 0,
                    eta: eta_,
                    a1: a1_,
                    a2: a2_,
                    L_I1: mpmath.sqrt(a1_),
                    L_I2: mpmath.sqrt(a2_),
                },
            )
            values = {
                mu: mu_,
                lam: 0,
                eta: eta_,
                a1: a1_,
                da_dP: slope,
                d2a_dP2: curvature,
                dP: p2 - p1,
                other_edge: -1,
            }
            first = _evaluate(sympy.expand(second_order_width()).coeff(dP, 1) * dP, values)
            second = _evaluate(second_order_width(), values)
            rows.append(
                (ratio, exact, (a1_ - b22) / exact - 1, first / exact - 1, second / exact - 1)
            )
    return rows


# --- the derivation -------------------------------------------------------------------------


def _jaeger_reduction() -> sympy.Expr:
    """(C2) with eta = 0, b_L = b, both edges forward: sum_i (P_i - P(b)) mu - dQ, any law.

    p(xi) = (1/pi) int_xi^a P'(c) dc / sqrt(c^2 - xi^2); exchanging the integrals leaves
    int_b^c 2 xi dxi / (sqrt(c^2 - xi^2) sqrt(xi^2 - b^2)) = pi (substitute v = xi^2).
    """
    low, span = sympy.symbols("low span", positive=True)
    v = low + span * u  # v = xi^2 from b^2 to c^2 = b^2 + span: 2 xi dxi = dv
    integrand = sympy.diff(v, u) / sympy.sqrt((low + span - v) * (v - low))
    # the integrand is u^(-1/2) (1 - u)^(-1/2) whatever b and c
    assert sympy.cancel(integrand**2 * u * (1 - u)) == 1
    return _beta_moment(sympy.S.One, -1)


def _reduced(identity: sympy.Expr) -> sympy.Expr:
    """Rational reduction before the engine's simplify: the same check, a fraction of the time."""
    return sympy.cancel(sympy.expand(identity))


def derive() -> Derivation:  # noqa: C901 - one block per established result
    d = Derivation(__file__)
    d.describe_module(
        "second_order",
        "Beyond the paper: the stick boundary of a proportional cycle to second order in dP, "
        "with bulk tension, from the exact steady-state consistency conditions of the finite "
        "stick zone; and the error of (22).",
    )
    width = second_order_width()
    coefficients = {k: width_coefficients(k) for k in (+1, -1)}
    with d.equation(
        "X-C", "Exact steady-state conditions (C1)-(C2) of the finite stick zone"
    ) as eq:
        zeroth, first, second = unit_kernels()
        eq.holds(zeroth - sympy.pi, how="int_-1^1 dtau/sqrt(1 - tau^2) = pi")
        eq.holds(
            _reduced(first - sympy.pi / sympy.sqrt(X**2 - 1)),
            how="int_-1^1 dtau/(sqrt(1 - tau^2)(X - tau)) = pi/sqrt(X^2 - 1), X > 1 "
            "(half-angle substitution, rational)",
        )
        c1_weight, c2_weight = interval_kernels()
        eq.holds(
            _reduced(c1_weight - sympy.pi / sympy.sqrt(gap * (gap + b_right + b_left))),
            how="scaled onto S = (-b_L, b): the (C1) weight pi/sqrt((xi - b)(xi + b_L))",
        )
        eq.holds(
            _reduced(
                c2_weight
                - sympy.pi
                * (gap + (b_right + b_left) / 2)
                / sympy.sqrt(gap * (gap + b_right + b_left))
            ),
            how="and the (C2) weight pi |xi - c0|/sqrt((xi - b)(xi + b_L))",
        )
        eq.holds(
            _reduced(_jaeger_reduction() - sympy.pi),
            how="without tension, b_L = b: (C2) becomes mu (P1 + P2 - 2 P(b)) = dQ, i.e. "
            "P(b) = P_K of (33) for every law (Jaeger-Ciavarella), since "
            "int_b^c 2 xi dxi/(sqrt(c^2 - xi^2) sqrt(xi^2 - b^2)) = pi",
        )
        residuals = _tilted_hertz_residuals()
        eq.beyond_paper(
            "D = q2 - q1 known on the slip zones, (1/pi) PV int D/(xi - x) = dsigma/4 on the "
            "stick zone S = (-b_L, b), D bounded at both ends, int D = dQ: the bounded inversion "
            "on S exists iff pi dsigma/4 = int_R D/sqrt((xi - b)(xi + b_L)) - int_L (mirror) "
            "(C1) and dQ = int D |xi - c0|/sqrt((xi - b)(xi + b_L)) over both slip zones (C2); "
            "Hertz with tension, both edges forward: the tilted-profile closed form "
            "b = a(P_K) - R dsigma/(4 mu E*), b_L = a(P_K) + R dsigma/(4 mu E*) satisfies both "
            f"to {mpmath.nstr(max(residuals), 2)} (relative, 40-digit quadrature)",
        )
    with d.equation(
        "X-28", "(28) is the first-order term of the exact conditions, with tension"
    ) as eq:
        eq.holds(
            _reduced(sympy.expand(width).coeff(dP, 1) * dP - first_order_slip_zone_width()),
            how="the dP coefficient of the solution of (C1)-(C2) equals (28) (and (22)) for "
            "every law, eta of either sign, the other edge either way",
        )
    same, opposite = coefficients[+1][W2], coefficients[-1][W2]
    r = (lam + sympy.pi * eta * a1 / 4) / mu
    rho, tau = lam / mu, sympy.pi * eta * a1 / (4 * mu)
    phi = {
        +1: 4 * tau * (2 - 2 * rho - tau),
        -1: 2 + 8 * tau - 2 * rho**2 - 4 * rho * tau - 6 * tau**2,
    }
    with d.equation("X-b2", "Second-order stick boundary with tension (both edges slipping)") as eq:
        for direction, value in ((+1, same), (-1, opposite)):
            eq.holds(
                _reduced(value + d2a_dP2 * (1 - r) ** 2 / 8 - da_dP**2 * phi[direction] / a1 / 32),
                how=f"other edge {'same way' if direction > 0 else 'opposite way'}: W2 = "
                "-a''(1 - r)^2/8 + a'^2 Phi/(32 a1), r = (lam + pi eta a1/4)/mu, Phi = "
                + (
                    "4 tau (2 - 2 rho - tau)"
                    if direction > 0
                    else "2 + 8 tau - 2 rho^2 - 4 rho tau - 6 tau^2"
                ),
            )
        exact_k = taylor_coefficients(a1 - half_width_near(permanent_stick_load() - P1), 2)
        eq.holds(
            _reduced(same.subs(eta, 0) - exact_k[2]),
            how="eta = 0, both edges forward: W2 is the dP^2 coefficient of a1 - a(P_K) for "
            "every law (a1, a', a'' free): the exact Jaeger-Ciavarella result to second order",
        )
        eq.holds(
            _reduced(paper_error_coefficient().subs({eta: 0, other_edge: 1}) - second_order_gap()),
            how="and b(22) - b2 at eta = 0 is the generic-law gap "
            "-(1 - lam^2/mu^2)(a'' + a'^2/a) dP^2/8 of generic_law_comparison",
        )
        hertz = _hertz_tilted_width_series()
        hertz_law = {
            d2a_dP2: sympy.diff(hertz_half_width(), P, 2),
            da_dP: sympy.diff(hertz_half_width(), P),
            a1: hertz_half_width(),
        }
        for k in (1, 2):
            eq.holds(
                _reduced(
                    sympy.expand(width).coeff(dP, k).subs(other_edge, 1).subs(hertz_law)
                    - hertz[k].subs(P1, P)
                ),
                how=f"Hertz, both edges forward, with tension: the dP^{k} coefficient is that of "
                "a1 - a(P_K) + R dsigma/(4 mu E*), the tilted-profile closed form",
            )
        eq.holds(
            _reduced(coefficients[+1][V2] - same.subs(eta, -eta)),
            how="the left edge (same-way branch) is the right edge with eta -> -eta "
            "(backward slip seen from the left: lam -> -lam, eta -> eta, then flipped)",
        )
        eq.holds(
            _reduced(coefficients[-1][V2] - opposite.subs(lam, -lam)),
            how="the left edge (opposite branch) is the right edge with lam -> -lam: the edge "
            "rule of edge_symmetry; other_edge is the product of the two slip directions",
        )
        eq.holds(
            _reduced((same - opposite).subs(lam, mu * (tau - 1))),
            how="the two branches agree where the other edge starts to slip the opposite way "
            "(lam - pi eta a1/4 = -mu): the +1 branch is continuous across the no-slip range of "
            "the other edge, which is why it is the interim choice there",
        )
        extracted = _hertz_pure_tension_extracted_coefficient()
        eq.beyond_paper(
            "a1 - b = a'(r - 1) dP/2 + [-a''(1 - r)^2/8 + a'^2 Phi/(32 a1)] dP^2 + O(dP^3), "
            "i.e. b = a(P_eff) - a'^2 Phi dP^2/(32 a1), P_eff = (P1 + P2)/2 - (dQ + pi a1 "
            "dsigma/4)/(2 mu); Hertz, lam = 0, eta = 0.06, mu = 0.3, P1 = 100, opposite edges: "
            f"W2 extracted from the exact (C1) at dP -> 0 (60 digits) matches to "
            f"{mpmath.nstr(extracted, 2)} relative",
            derived=width,
        )
    error = paper_error_coefficient()
    with d.equation("22-T", "(22) with bulk tension: a spurious dP^2 term") as eq:
        hertz_error = {
            k: sympy.factor(error.subs(other_edge, k).subs(d2a_dP2, -(da_dP**2) / a1))
            for k in (+1, -1)
        }
        eq.holds(
            _reduced(
                hertz_error[+1]
                + sympy.pi * da_dP**2 * eta * (3 * sympy.pi * a1 * eta + 16 * lam) / (128 * mu**2)
            ),
            how="Hertz, both edges forward: b(22) - b = -pi a'^2 eta (3 pi a1 eta + 16 lam) "
            "dP^2/(128 mu^2) (sign: a1 - b of (22) is the larger)",
        )
        single_edge = single_edge_second_coefficient()
        eq.holds(
            _reduced(
                (single_edge - same).subs(eta, 0)
                + 3 * da_dP**2 * (lam**2 - mu**2) / (64 * a1 * mu**2)
            ),
            how="the single-edge route ((12)-(16) with every edge expansion to (a - x)^(3/2), "
            "tension at the field point) misses the finite-stick-zone terms: its dP^2 "
            "coefficient is off by -3 a'^2 (lam^2 - mu^2)/(64 a1 mu^2) even without tension",
        )
        table = pure_tension_table()
        described = "; ".join(
            f"a2/a1 = {ratio}: (22) {100 * float(e22):+.1f} %, (28) {100 * float(e28):+.2f} %, "
            f"b2 {100 * float(e2):+.3f} %"
            for ratio, _, e22, e28, e2 in table
        )
        eq.erratum(
            "(22)'s dP^2 term is an artefact of evaluating (21) at each state's edge: with "
            "tension it weights the tension term by the moving edge (pi eta a_i L_I,i/4) while "
            "the tension acts at the field point, and a single-edge expansion cannot hold the "
            "finite-stick-zone terms of the same order.  b(22) - b = E dP^2 + O(dP^3) with E "
            "emitted as paper_stick_boundary_error.  Hertz, R = E* = 1, P1 = 100, mu = 0.3, "
            "lam = 0, eta = 0.06 (edges slipping opposite ways), slip-zone width against the "
            f"exact (C1) at 30 digits: {described}",
            derived=error,
        )
    _emit(d, width, error)
    return d


def _emit(d: Derivation, width: sympy.Expr, error: sympy.Expr) -> None:
    common = (*arguments(mu, lam, eta, a1, da_dP), CURVATURE, LOAD_CHANGE, OTHER_EDGE)
    d.emit(
        name="slip_zone_width_second_order",
        args=common,
        expr=width,
        equations=("22", "28"),
        summary="Slip-zone width a1 - b to second order in dP, with bulk tension.",
        doc="From the exact steady-state conditions of the finite stick zone (beyond the paper): "
        "a'(r - 1) dP/2 + [-a''(1 - r)^2/8 + a'^2 Phi/(32 a1)] dP^2, r = (lam + pi eta a1/4)/mu. "
        " For the edge whose own-frame lam, eta are given, slipping forward (r > 1); exact to "
        "O(dP^3) when both edges slip.  The first term is (28).  No cancellation: a1 - b keeps "
        "full relative precision for small dP.",
        module="second_order",
        returns="a1 - b, same units as a1.",
    )
    d.emit(
        name="stick_boundary_second_order",
        args=common,
        expr=a1 - width,
        equations=("22", "28"),
        summary="Stick boundary b to second order in dP, with bulk tension.",
        doc="a1 minus slip_zone_width_second_order; see there for the domain.",
        module="second_order",
        returns="b, same units as a1.",
    )
    d.emit(
        name="slip_zone_width_second_coefficient",
        args=(*arguments(mu, lam, eta, a1, da_dP), CURVATURE, OTHER_EDGE),
        expr=width_second_coefficient(),
        equations=("28",),
        summary="W2 of a1 - b = W1 dP + W2 dP^2 + O(dP^3): (28) errs by -W2 dP^2 in b.",
        doc="The second-order coefficient of the slip-zone width from the exact conditions; the "
        "first-order (28) stick boundary is b(28) = b - W2 dP^2 + O(dP^3).",
        module="second_order",
        returns="W2 [length^3/force^2].",
    )
    d.emit(
        name="paper_stick_boundary_error",
        args=(*arguments(mu, lam, eta, a1, da_dP), CURVATURE, OTHER_EDGE),
        expr=error,
        equations=("22",),
        summary="E of b(22) - b = E dP^2 + O(dP^3): the second-order error of the headline (22).",
        doc="Zero for Hertz without tension; -(1 - lam^2/mu^2)(a'' + a'^2/a)/8 for other laws "
        "without tension; with tension nonzero for every law (Hertz, both edges forward: "
        "-pi a'^2 eta (3 pi a1 eta + 16 lam)/(128 mu^2)).",
        module="second_order",
        returns="E [length^3/force^2].",
    )
    # Laws give L_I'(P) (normal_multiplier_slope), not a''(P): (19) trades one for the other.
    ratio = sympy.Symbol("ell", real=True)
    curvature = sympy.solve(
        sympy.diff(multiplier_near(step), step).subs(step, 0) / multiplier_near(0) - ratio, d2a_dP2
    )[0]
    assert sympy.simplify(curvature + da_dP * (ratio + da_dP / (2 * a1))) == 0
    by_multiplier = {d2a_dP2: curvature.subs(ratio, dL_I_dP / L_I1)}
    multiplier_args = (*arguments(mu, lam, eta, a1, da_dP, L_I1, dL_I_dP), LOAD_CHANGE, OTHER_EDGE)
    d.emit(
        name="slip_zone_width_second_order_from_multiplier",
        args=multiplier_args,
        expr=sympy.factor(width.subs(by_multiplier)),
        equations=("19", "22", "28"),
        summary="Slip-zone width a1 - b to second order, from L_I and L_I'(P1) instead of a''.",
        doc="slip_zone_width_second_order with a'' = -a'(L_I'/L_I + a'/(2 a1)) from (19), so "
        "that a law's half_width_slope, normal_multiplier and normal_multiplier_slope suffice.",
        module="second_order",
        returns="a1 - b, same units as a1.",
    )
    _emit_dimensionless(d, sympy.factor(width.subs(by_multiplier)))
    d.emit(
        name="paper_stick_boundary_error_from_multiplier",
        args=(*arguments(mu, lam, eta, a1, da_dP, L_I1, dL_I_dP), OTHER_EDGE),
        expr=sympy.factor(error.subs(by_multiplier)),
        equations=("19", "22"),
        summary="E of b(22) - b = E dP^2 + O(dP^3), from L_I and L_I'(P1).",
        doc="paper_stick_boundary_error with a'' traded for L_I'(P1) through (19).",
        module="second_order",
        returns="E [length^3/force^2].",
    )


#: The dimensionless groups of the second-order width, each of order one wherever the width
#: itself is a double: lam/mu, eta a1/mu, a'(P1) dP/a1, L_I1 a1^(3/2)/dP, L_I'(P1) a1^(3/2).
GROUPS = (
    Argument(sympy.Symbol("lam_mu", real=True), "lambda/mu, the shear slope over friction."),
    Argument(sympy.Symbol("eta_a1_mu", real=True), "eta a1/mu, the tension slope over friction."),
    Argument(sympy.Symbol("growth", positive=True), "a'(P1) dP/a1, the contact growth of (24)."),
    Argument(
        sympy.Symbol("multiplier", positive=True),
        "L_I1 a1^(3/2)/dP, the normal edge multiplier in units of a1 and dP.",
    ),
    Argument(
        sympy.Symbol("multiplier_slope", real=True),
        "L_I'(P1) a1^(3/2), the multiplier's slope in units of a1.",
    ),
)


def _emit_dimensionless(d: Derivation, width: sympy.Expr) -> None:
    """The second-order width as a1 times a function of :data:`GROUPS` alone.

    The width is homogeneous of degree one in length and zero in load, and depends on lam and
    eta only through lam/mu and eta/mu: asserted below by putting the groups back.  Its
    dimensional terms (a1^3 eta^2 L_I' dP, mu^2 ...) overflow or underflow at loads of 1e300 or
    mu = 1e-300 although the width does not; in the groups every term is of order one.
    """
    lam_mu, eta_a1_mu, growth, multiplier, multiplier_slope = (g.symbol for g in GROUPS)
    unit = {mu: 1, lam: lam_mu, eta: eta_a1_mu, a1: 1, da_dP: growth, L_I1: multiplier}
    unit.update({dL_I_dP: multiplier_slope, dP: 1})
    dimensionless = sympy.factor(width.subs(unit, simultaneous=True))
    back = {lam_mu: lam / mu, eta_a1_mu: eta * a1 / mu, growth: da_dP * dP / a1}
    back.update({multiplier: L_I1 * a1 ** sympy.Rational(3, 2) / dP})
    back[multiplier_slope] = dL_I_dP * a1 ** sympy.Rational(3, 2)
    assert sympy.simplify(a1 * dimensionless.subs(back, simultaneous=True) - width) == 0
    d.emit(
        name="slip_zone_width_second_order_dimensionless",
        args=(*GROUPS, OTHER_EDGE),
        expr=dimensionless,
        equations=("19", "22", "28"),
        summary="(a1 - b)/a1 to second order, in dimensionless groups that cannot overflow.",
        doc="slip_zone_width_second_order_from_multiplier divided by a1, written in lam/mu, "
        "eta a1/mu, a'(P1) dP/a1, L_I1 a1^(3/2)/dP and L_I'(P1) a1^(3/2) (the width is "
        "homogeneous of degree one in length and zero in load, and depends on lam, eta only "
        "through lam/mu, eta/mu): the same digits at ordinary values, and no overflow of "
        "dimensional terms at loads of 1e300 or mu = 1e-300.",
        module="second_order",
        returns="(a1 - b)/a1, dimensionless.",
    )


# --- checks with numbers --------------------------------------------------------------------


def _tilted_hertz_residuals() -> list[mpmath.mpf]:
    """(C1), (C2) residuals, relative, for the Hertz tilted-profile solution (R = E* = 1)."""
    with mpmath.workdps(40):
        p1, p2 = mpmath.mpf(100), mpmath.mpf("110.25")
        mu_, lam_, eta_ = mpmath.mpf("0.3"), mpmath.mpf("0.9"), mpmath.mpf("0.02")
        dp = p2 - p1
        pk = (p1 + p2) / 2 - lam_ * dp / (2 * mu_)
        shift = eta_ * dp / (4 * mu_)  # R dsigma / (4 mu E*)
        stick_r, stick_l = _hertz_half(pk) - shift, _hertz_half(pk) + shift
        centre = (stick_r - stick_l) / 2
        edges = (_hertz_half(p1), _hertz_half(p2))

        def zone(stick, other, arm_sign):
            """Both integrals over one slip zone, p = (1/2) sqrt(a^2 - xi^2) for each state.

            xi = stick + span sin^2(phi) removes both endpoint square roots: the (C1) integrand
            becomes span cos^2(phi) sqrt(a + xi) / (2 sqrt(xi + other)) dphi... times 2/2.
            """
            force = moment = mpmath.mpf(0)
            for edge in edges:
                span = edge - stick

                def smooth(phi, edge=edge, span=span):
                    point = stick + span * mpmath.sin(phi) ** 2
                    value = span * mpmath.cos(phi) ** 2 * mpmath.sqrt(edge + point)
                    return value / mpmath.sqrt(point + other), point

                force += mpmath.quad(lambda f: smooth(f)[0], [0, mpmath.pi / 2])
                moment += mpmath.quad(
                    lambda f: smooth(f)[0] * (smooth(f)[1] + arm_sign * centre), [0, mpmath.pi / 2]
                )
            return force, moment

        force_r, moment_r = zone(stick_r, stick_l, -1)
        force_l, moment_l = zone(stick_l, stick_r, +1)
        c1 = mu_ * (force_r - force_l) - mpmath.pi * eta_ * dp / 4
        c2 = mu_ * (moment_r + moment_l) - lam_ * dp
        return [abs(c1) / (mu_ * force_r), abs(c2) / (lam_ * dp)]


def _hertz_half(load):
    """(29) with R = E* = 1, at mpmath precision."""
    return mpmath.sqrt(4 * load / mpmath.pi)


@functools.cache
def _hertz_tilted_width_series() -> list[sympy.Expr]:
    """dP^0..dP^2 coefficients of a1 - a(P_K) + R eta dP/(4 mu E*) for Hertz, in P1."""
    law = hertz_half_width()
    exact = law.subs(P, P1) - law.subs(P, permanent_stick_load()) + R * eta * dP / (4 * mu * E_star)
    series = sympy.expand(sympy.series(exact, dP, 0, 3).removeO())
    return [sympy.simplify(series.coeff(dP, k)) for k in range(3)]


def _hertz_pure_tension_extracted_coefficient() -> mpmath.mpf:
    """Relative difference between W2 and (w(h) - W1 h)/h^2 extrapolated to h -> 0 (Hertz)."""
    with mpmath.workdps(60):
        p1, mu_, eta_ = mpmath.mpf(100), mpmath.mpf("0.3"), mpmath.mpf("0.06")
        a1_, slope, curvature = _hertz_numbers(p1)
        values = {
            mu: mu_,
            lam: 0,
            eta: eta_,
            a1: a1_,
            da_dP: slope,
            d2a_dP2: curvature,
            other_edge: -1,
        }
        w1 = _evaluate(sympy.expand(second_order_width()).coeff(dP, 1), values)
        w2 = _evaluate(width_second_coefficient(), values)
        h = mpmath.mpf("1e-15")
        estimates = []
        for k in (1, 2):
            width = hertz_pure_tension_width(p1, p1 + k * h, mu_, eta_)
            estimates.append((width - w1 * k * h) / (k * h) ** 2)
        extrapolated = 2 * estimates[0] - estimates[1]  # removes the O(h) term
        return abs(extrapolated - w2) / abs(w2)
