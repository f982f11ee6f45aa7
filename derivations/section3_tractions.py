"""Section 3.4, Eqs. (46)-(49): the shear-traction difference q2 - q1, exact and asymptotic.

Exact, (47)-(48): the Hertz pressure comes from Mossakovskii's superposition of flat punches,
    p(x) = (1/pi) int_x^a P'(c) dc / sqrt(c^2 - x^2),
applied to the Hertz law (29).  Clamped as sqrt(Max(0, a^2 - x^2)) it vanishes outside the
contact, so mu (p(x, P2) + p(x, P1) - 2 p(x, P_K)) is the whole piecewise (47) in one line.

Asymptotic, (49): with the density (15), the dislocation integral splits into finite Hilbert
transforms J(c, x) = int_c^a2 sqrt((t - c)(a2 - t)) dt/(t - x) for c = b and c = a1.  Writing
sqrt((t - c)(a2 - t))/(t - x) = sqrt((a2 - t)/(t - c)) (1 + (x - c)/(t - x)) reduces J to the
weight integral of (16) and the transform (14), both derived in Section 2 with the
rationalising substitution; below the interval (x < c) a reflection t -> c + a2 - t maps J onto
the second branch of (14).  The principal value (c < x < a2) and the ordinary integral (x < c)
differ by -pi sqrt((c - x)(a2 - x)), which a clamp sqrt(Max(0, c - x)) switches on.  The
stick boundary b stays an argument.  Unless b is the consistent value (17), the result carries
an edge-singular term K (b - b17) / (2 sqrt(a2 - x)); K is derived here.
"""

from __future__ import annotations

import functools

import mpmath
import sympy

from asymslip.codegen import Argument, Derivation

from ._glossary import L_I1, L_I2, L_II1, L_II2, P1, a, a1, a2, arguments, b, dP, mu, x
from .contact_law_hertz import (
    LOAD,
    LOAD1,
    LOAD_CHANGE,
    MODULUS,
    RADIUS,
    E_star,
    P,
    hertz_half_width,
    hertz_load,
)
from .section2_consistency import scaled_weight_integral, stick_boundary
from .section2_dislocation_density import EXAMPLE_CYCLE, dislocation_density
from .section2_hilbert_identity import hilbert_on_interval

P_K = sympy.Symbol("P_K", positive=True)
PERMANENT_STICK_LOAD = Argument(
    P_K,
    "Load P_K of (33) whose Hertz half-width a(P_K) is the permanent stick zone, "
    "0 < P_K < P1 [force/length].",
)

# Integration variables and positive distances that fix where x lies.
c_var, inner = sympy.symbols("c x_inner", positive=True)
t = sympy.Symbol("t", real=True)
lower, top = sympy.symbols("c d", real=True)  # the interval (c, d) of J
s, w = sympy.symbols("s w", positive=True)


# --- (48): Hertz pressure --------------------------------------------------------------------


@functools.cache
def hertz_pressure_unclamped() -> sympy.Expr:
    """p(x) inside the contact (0 < x < a), by Mossakovskii's superposition, in terms of a."""
    slope = sympy.diff(hertz_load(), a).subs(a, c_var)
    integral = sympy.integrate(slope / sympy.sqrt(c_var**2 - inner**2), (c_var, inner, a))
    return sympy.simplify(integral / sympy.pi)


@functools.cache
def hertz_pressure() -> sympy.Expr:
    """(48) in terms of the load P, clamped so that it is zero for |x| >= a(P)."""
    pressure = hertz_pressure_unclamped()
    (root,) = [f for f in pressure.atoms(sympy.Pow) if f.exp == sympy.Rational(1, 2)]
    clamped = pressure.subs(root, sympy.sqrt(sympy.Max(0, root.base)))
    return clamped.subs(inner, x).subs(a, hertz_half_width())


def pressure_at(load: sympy.Expr) -> sympy.Expr:
    return hertz_pressure().subs(P, load)


# The pressures of any symmetric law at the three loads of (47), for its general form.
pressure2, pressure1, pressure_K = sympy.symbols("p2 p1 p_K", nonnegative=True)
PRESSURES = (
    Argument(
        pressure2,
        "Contact pressure p(x, P2) at load state 2, zero outside the contact [force/length^2].",
    ),
    Argument(
        pressure1,
        "Contact pressure p(x, P1) at load state 1, zero outside the contact [force/length^2].",
    ),
    Argument(
        pressure_K,
        "Contact pressure p(x, P_K) at the load P_K of (33), zero outside its "
        "contact [force/length^2].",
    ),
)
_pressure = sympy.Function("p")  # the law's pressure p(x, P) at x, as a function of the load


@functools.cache
def jaeger_ciavarella_difference() -> sympy.Expr:
    """(47) for any symmetric law, in the law's pressure at P2, P1 and P_K.

    Jaeger-Ciavarella: at each end of the cycle the shear traction is full sliding, mu p_i,
    corrected in the permanent stick zone by -2 mu p(x, P_K) relative to the other end, so
    q2 - q1 = mu (p(x, P2) + p(x, P1)) - 2 mu p(x, P_K), each pressure zero outside its contact
    (which makes this one expression all three ranges of (47)).  The starting point of
    Section 3.1; for Hertz it is checked against the paper's piecewise (47) below.
    """
    return mu * (_pressure(P1 + dP) + _pressure(P1) - 2 * _pressure(P_K))


@functools.cache
def general_traction_difference() -> sympy.Expr:
    """(47) with the three pressures as arguments."""
    general = jaeger_ciavarella_difference().subs(
        {_pressure(P1 + dP): pressure2, _pressure(P1): pressure1, _pressure(P_K): pressure_K}
    )
    assert general.free_symbols == {mu, pressure1, pressure2, pressure_K}, general
    return general


@functools.cache
def hertz_traction_difference() -> sympy.Expr:
    """(47) for Hertz: the clamps switch the P_K and P1 terms off where they vanish."""
    return jaeger_ciavarella_difference().replace(_pressure, pressure_at)


# --- (49): finite Hilbert transform of the semicircle weight ----------------------------------


@functools.cache
def semicircle_transform() -> tuple[sympy.Expr, sympy.Expr]:
    """(inside, outside): J = int_c^d sqrt((t-c)(d-t)) dt/(t-x) for c < x < d (PV) and x < c.

    sqrt((t - c)(d - t))/(t - x) = sqrt((d - t)/(t - c)) (1 + (x - c)/(t - x)), so J is the
    weight integral of (16) plus (x - c) times the finite Hilbert transform (14).  Below the
    interval, the reflection t -> c + d - t gives J(x) = -J(c + d - x) with c + d - x > d,
    where (14) has its second branch.
    """
    split = sympy.sqrt(top - t) / sympy.sqrt(t - lower) * (1 + (x - lower) / (t - x))
    assert sympy.simplify(split - sympy.sqrt(t - lower) * sympy.sqrt(top - t) / (t - x)) == 0

    def transform(point: sympy.Expr, inside: bool) -> sympy.Expr:
        return scaled_weight_integral(lower, top) + (point - lower) * hilbert_on_interval(
            lower, top, point, inside=inside
        )

    inside = sympy.expand(transform(x, inside=True))
    # x = c - s, d = c + w: positive distances let the square roots split.
    reflected = -transform(lower + top - x, inside=False)
    reflected = sympy.simplify(reflected.subs({x: lower - s, top: lower + w}))
    outside = reflected.subs({s: lower - x, w: top - lower})
    return inside, outside


@functools.cache
def clamped_semicircle_transform() -> sympy.Expr:
    """J for every x < d in one expression: the inside form plus a jump switched on for x < c."""
    inside, outside = semicircle_transform()
    jump = sympy.simplify(outside - inside)
    below = sympy.sqrt(lower - x)
    rest = sympy.simplify(jump / below)
    assert not rest.has(below), "the jump must be proportional to sqrt(c - x)"
    return inside + sympy.sqrt(sympy.Max(0, lower - x)) * rest


# --- (49): the asymptotic traction difference ---------------------------------------------------

distance = sympy.Symbol("y", positive=True)  # a2 - x, distance from the contact edge
stick_root, inner_root = sympy.symbols("S_b S_1", nonnegative=True)  # placeholders for clamps
CLAMPS = {
    stick_root: sympy.sqrt(sympy.Max(0, b - x)),
    inner_root: sympy.sqrt(sympy.Max(0, a1 - x)),
}


@functools.cache
def density_pieces() -> dict[sympy.Expr, sympy.Expr]:
    """(15) as {lower end c: coefficient of sqrt(Max(0, x - c))}, for c = b and c = a1."""
    roots = {b: sympy.sqrt(sympy.Max(0, x - b)), a1: sympy.sqrt(sympy.Max(0, x - a1))}
    density = dislocation_density()
    pieces = sympy.collect(sympy.expand(density), list(roots.values()), evaluate=False)
    assert set(pieces) == set(roots.values()), f"unexpected density shape {pieces}"
    return {c: pieces[root] for c, root in roots.items()}


@functools.cache
def traction_difference_placeholders() -> sympy.Expr:
    """(49) with x = a2 - y and the stick/inner clamps as placeholders S_b, S_1."""
    transform = clamped_semicircle_transform().subs(top, a2)
    # int_{a2}^{b} = -int_b^{a2}; on (c, a2) sqrt(a2 - t) sqrt(t - c) is the semicircle weight.
    integral = -sum(
        coefficient * transform.subs(lower, c) for c, coefficient in density_pieces().items()
    )
    dislocations = E_star / (2 * sympy.pi * sympy.sqrt(a2 - x)) * integral
    full_stick_change = L_II2 * sympy.sqrt(a2 - x) - L_II1 * sympy.sqrt(sympy.Max(0, a1 - x))
    total = full_stick_change + dislocations
    total = total.subs({clamp: name for name, clamp in CLAMPS.items()})
    total = sympy.expand(total.subs(x, a2 - distance))
    assert not total.has(x), "x must enter only through the clamps and a2 - x"
    return total


def _shape_functions() -> dict[sympy.Expr, sympy.Expr]:
    """(49) as {shape function of x: coefficient}: sqrt(y), 1/sqrt(y), S_b, S_1 with y = a2 - x."""
    grouped: dict[sympy.Expr, sympy.Expr] = {}
    for term in sympy.Add.make_args(traction_difference_placeholders()):
        coefficient, shape = term.as_independent(distance, stick_root, inner_root)
        grouped[shape] = grouped.get(shape, 0) + coefficient
    allowed = {sympy.sqrt(distance), 1 / sympy.sqrt(distance), stick_root, inner_root}
    assert set(grouped) <= allowed, f"unexpected shape functions {set(grouped) - allowed}"
    return grouped


@functools.cache
def edge_coefficient() -> sympy.Expr:
    """Coefficient of 1/sqrt(a2 - x) in (49), written with the lengths a1 - b and a2 - b."""
    coefficient = sympy.expand(_shape_functions()[1 / sympy.sqrt(distance)])
    to_a1, to_a2 = coefficient.coeff(a1), coefficient.coeff(a2)
    # Translation invariance: the coefficient depends on the positions only through lengths.
    assert sympy.expand(to_a1 * (a1 - b) + to_a2 * (a2 - b) - coefficient) == 0
    return sympy.factor(to_a1) * (a1 - b) + sympy.factor(to_a2) * (a2 - b)


@functools.cache
def traction_difference() -> sympy.Expr:
    """(49) in closed form for every x < a2, branch-free, b an argument."""
    result = sum(
        sympy.factor(value) * shape
        for shape, value in _shape_functions().items()
        if shape != 1 / sympy.sqrt(distance)
    )
    result += edge_coefficient() / sympy.sqrt(distance)
    return result.subs(distance, a2 - x).subs(CLAMPS)


@functools.cache
def edge_strength() -> sympy.Expr:
    """K of the edge-singular term K (b - b17) / (2 sqrt(a2 - x))."""
    return sympy.factor(2 * sympy.diff(edge_coefficient(), b))


# --- independent numerical references -----------------------------------------------------------


def _principal_quadrature(weighted, x_value, breaks, lo, hi):
    """PV int_lo^hi weighted(t)/(t - x) dt by subtracting the value at the pole."""
    if not lo < x_value < hi:
        return mpmath.quad(lambda t: weighted(t) / (t - x_value), breaks)
    at_pole = weighted(x_value)

    def regular(t):
        # Tanh-sinh nodes can round onto the pole itself; the integrand's limit there is finite.
        return 0 if t == x_value else (weighted(t) - at_pole) / (t - x_value)

    regular_part = mpmath.quad(regular, sorted({*breaks, x_value}))
    return regular_part + at_pole * mpmath.log((hi - x_value) / (x_value - lo))


def _semicircle_quadrature(c_value, d_value, x_value):
    def weight(t):
        return mpmath.sqrt((t - c_value) * (d_value - t))

    return _principal_quadrature(weight, x_value, [c_value, d_value], c_value, d_value)


EXAMPLE = EXAMPLE_CYCLE  # mu L_I2 - L_II2 < 0 puts b17 inside a1, as in Fig. 5


def _example(b_shift: str) -> dict[sympy.Symbol, sympy.Rational]:
    values = {symbol: sympy.Rational(value) for symbol, value in EXAMPLE.items()}
    values[b] = stick_boundary().subs(values) + sympy.Rational(b_shift)
    return values


def derive() -> Derivation:
    d = Derivation(__file__)
    d.describe_module(
        "tractions",
        "Section 3.4 of the paper: the difference q2 - q1 of the shear tractions at the two "
        "ends of the load cycle, exact for the Hertzian contact and asymptotic (corrective slip).",
    )
    with d.equation("48", "Hertz contact pressure") as eq:
        a_of_p = hertz_half_width()
        unclamped = hertz_pressure_unclamped().subs(inner, x).subs(a, a_of_p)
        eq.matches_paper(
            unclamped,
            2 * P / (sympy.pi * a_of_p**2) * sympy.sqrt(a_of_p**2 - x**2),
            how="Mossakovskii superposition (1/pi) int_x^a P'(c) dc/sqrt(c^2 - x^2) of the "
            "Hertz law (29); clamped as sqrt(Max(0, a^2 - x^2)) to vanish outside the contact",
            printed=r"p(x,P)=\frac{2P}{\pi a^2}\sqrt{a^2-x^2}",
        )

    with d.equation("47", "Exact shear-traction difference for the Hertzian contact") as eq:
        _check_exact_ranges(eq)
    with d.equation("47", "Exact shear-traction difference for any symmetric law") as eq:
        general = general_traction_difference()
        eq.holds(
            general.subs(
                {
                    pressure2: pressure_at(P1 + dP),
                    pressure1: pressure_at(P1),
                    pressure_K: pressure_at(P_K),
                }
            )
            - hertz_traction_difference(),
            how="the Jaeger-Ciavarella superposition in the law's own pressures; with the "
            "Hertz pressures (48) it is the Hertz (47) checked range by range above",
            derived=general,
        )

    with d.equation("49", "Finite Hilbert transform of sqrt((t - c)(a2 - t))") as eq:
        inside, outside = semicircle_transform()
        eq.beyond_paper(
            "sqrt((t-c)(d-t))/(t-x) = sqrt((d-t)/(t-c)) (1 + (x-c)/(t-x)): the weight integral "
            "of (16) plus (x - c) times (14); reflection t -> c + d - t for x < c: "
            f"J = {inside} for c < x < d (PV), {outside} for x < c",
            derived=sympy.Tuple(inside, outside),
        )
        numeric = sympy.lambdify((lower, top, x), clamped_semicircle_transform(), "mpmath")
        points = [
            {"c_value": mpmath.mpf(cv), "d_value": mpmath.mpf(dv), "x_value": mpmath.mpf(xv)}
            for cv, dv, xv in [
                ("0.9", "1.05", "1"),
                ("-1", "2", "0.5"),
                ("0.9", "1.05", "0"),
                ("0.3", "0.4", "0.29"),
            ]
        ]
        eq.matches_numerically(
            lambda c_value, d_value, x_value: numeric(c_value, d_value, x_value),
            _semicircle_quadrature,
            points,
            how="mpmath quadrature (principal value inside, ordinary below c)",
            symbolic=True,
        )

    with d.equation("49", "Asymptotic shear-traction difference in closed form") as eq:
        total = traction_difference()
        b17 = stick_boundary()
        slip_zone = total.subs(CLAMPS[stick_root], 0).subs(b, b17)
        eq.holds(
            slip_zone
            - mu * L_I2 * sympy.sqrt(a2 - x)
            - mu * L_I1 * sympy.sqrt(sympy.Max(0, a1 - x)),
            how="with b from (17), in the slip zone q_diff = mu (p2 + p1) asymptotically, "
            "i.e. mu L_I2 sqrt(a2 - x) + mu L_I1 H(a1 - x) sqrt(a1 - x), as (8) and (11) demand",
            derived=total,
        )
        assert not total.has(E_star), "E* cancels between (1) and (15)"
        numeric = sympy.lambdify(x, total.subs(_example("-1/50")), "mpmath")

        def closed_form(fraction):
            values = {s_.name: v for s_, v in _example("-1/50").items()}
            return numeric(_position(values, fraction))

        eq.matches_numerically(
            closed_form,
            _reference_traction_difference,
            [{"fraction": f} for f in ("-3", "0.2", "0.6", "0.97")],
            how="(49) by principal-value quadrature of the density (15) with b = b17 - 1/50: "
            "stick zone, both slip-zone pieces",
            digits=20,  # the closed form is exact; 20 digits keep the quadrature quick
            symbolic=True,
        )

    with d.equation("49", "Edge-singular term when b is not the consistent (17)") as eq:
        strength = edge_strength()
        eq.erratum(
            "Section 3.4 builds (15) with b from (35), but (15) solves (12) only for b from "
            "(17); otherwise (49) gains K (b - b17)/(2 sqrt(a2 - x)) with "
            f"K = {strength} = mu (L_I1 + L_I2) + L_II1 - L_II2, the denominator of (17)",
            derived=strength,
        )
        eq.holds(
            edge_coefficient() - strength * (b - b17) / 2,
            how="the coefficient of 1/sqrt(a2 - x) equals K (b - b17)/2",
        )
        eq.holds(
            strength - (mu * (L_I1 + L_I2) + L_II1 - L_II2),
            how="K = mu (L_I1 + L_I2) + L_II1 - L_II2",
        )

    d.emit(
        name="hertz_pressure",
        args=(*arguments(x), LOAD, RADIUS, MODULUS),
        expr=hertz_pressure(),
        equations=("48",),
        summary="Hertz contact pressure p(x, P) of the cylinder, zero outside the contact.",
        doc="Mossakovskii's superposition of flat-punch pressures for the Hertz law (29), "
        "(E*/2R) sqrt(a^2 - x^2) with a = a(P); the clamp sqrt(Max(0, a^2 - x^2)) makes it 0 "
        "for |x| >= a(P) without branches.",
        module="tractions",
        returns="Contact pressure [force/length^2].",
    )
    d.emit(
        name="hertz_shear_traction_difference",
        args=(
            *arguments(x),
            LOAD1,
            LOAD_CHANGE,
            PERMANENT_STICK_LOAD,
            *arguments(mu),
            RADIUS,
            MODULUS,
        ),
        expr=hertz_traction_difference(),
        equations=("46", "47", "48"),
        summary="Exact q_diff = q2 - q1 of the Hertzian contact (Jaeger-Ciavarella).",
        doc="mu (p(x, P2) + p(x, P1) - 2 p(x, P_K)) with P2 = P1 + dP and clamped pressures "
        "(48): this one expression is all three ranges of (47), since p(x, P_K) = 0 for "
        "x > b = a(P_K) and p(x, P1) = 0 for x > a1.  Valid for 0 < P_K < P1 (a permanent "
        "stick zone exists), any x.",
        module="tractions",
        returns="q2 - q1 [force/length^2].",
    )
    d.emit(
        name="jaeger_ciavarella_traction_difference",
        args=(*PRESSURES, *arguments(mu)),
        expr=general_traction_difference(),
        equations=("46", "47"),
        summary="Exact q_diff = q2 - q1 of any symmetric contact without bulk tension.",
        doc="mu (p2 + p1 - 2 p_K), the Jaeger-Ciavarella superposition behind (47), from the "
        "law's own pressures at P2, P1 and P_K, each zero outside its contact: one expression "
        "for all three ranges of (47).  Forward slip; for backward slip negate it "
        "(derivations/edge_symmetry.py).  Valid for eta = 0 and a symmetric contact.",
        module="tractions",
        returns="q2 - q1 [force/length^2].",
    )
    d.emit(
        name="shear_traction_difference",
        args=arguments(x, b, a1, a2, mu, L_I1, L_I2, L_II1, L_II2),
        expr=traction_difference(),
        equations=("15", "46", "49"),
        summary="Asymptotic q_diff = q2 - q1 at the right-hand edge (corrective slip).",
        doc="(49) in closed form for every x < a2 (stick zone and both slip-zone pieces), "
        "with the density (15) built on the given stick boundary b (b <= a1).  E* cancels "
        "between (1) and (15).  For b from (17) the slip zone carries mu (p2 + p1); any other "
        "b adds the edge-singular term K (b - b17)/(2 sqrt(a2 - x)), K = mu (L_I1 + L_I2) + "
        "L_II1 - L_II2 (the paper's Fig. 5 uses b from (35)).  Requires x < a2: the term "
        "1/sqrt(a2 - x) is infinite at the edge.",
        module="tractions",
        returns="q2 - q1 [force/length^2].",
    )
    return d


def _position(values: dict, fraction: str) -> mpmath.mpf:
    """x = b + (a2 - b) * fraction: below b for fraction < 0, in the slip zone for 0..1."""
    return values["b"] + (values["a2"] - values["b"]) * mpmath.mpf(fraction)


def _reference_traction_difference(fraction: str) -> mpmath.mpf:
    """(49) as printed, with (15) transcribed, by (principal-value) quadrature."""
    v = {s_.name: mpmath.mpf(q.p) / q.q for s_, q in _example("-1/50").items()}
    a1v, a2v, bv = v["a1"], v["a2"], v["b"]
    coefficient1 = v["mu"] * v["L_I1"] + v["L_II1"]
    total = coefficient1 + v["mu"] * v["L_I2"] - v["L_II2"]

    def density(t):  # (15)
        inner_part = mpmath.sqrt(t - a1v) if t > a1v else 0
        return (-2 * mpmath.sqrt(t - bv) * total + 2 * coefficient1 * inner_part) / v["E_star"]

    x_value = _position(v, fraction)
    integral = -_principal_quadrature(
        lambda t: mpmath.sqrt(a2v - t) * density(t), x_value, [bv, a1v, a2v], bv, a2v
    )
    inner_part = mpmath.sqrt(a1v - x_value) if x_value < a1v else 0
    return (
        v["L_II2"] * mpmath.sqrt(a2v - x_value)
        - v["L_II1"] * inner_part
        + v["E_star"] / (2 * mpmath.pi * mpmath.sqrt(a2v - x_value)) * integral
    )


def _check_exact_ranges(eq) -> None:
    """(47): on each range of x the clamped form equals the paper's branch with (48)."""
    e1, e2, e3, g = sympy.symbols("e1 e2 e3 g", positive=True)
    scale = hertz_half_width() ** 2 / P  # a(P)^2 = scale * P for Hertz
    assert not sympy.simplify(scale).has(P)
    a_of = {load: hertz_half_width().subs(P, load) for load in (P1 + dP, P1, P_K)}

    def paper_pressure(load):  # (48) as printed, no clamp; the prefactor cancelled first
        prefactor = sympy.cancel(2 * load / (sympy.pi * a_of[load] ** 2))
        return prefactor * sympy.sqrt(a_of[load] ** 2 - x**2)

    p2, p1, pk = (paper_pressure(load) for load in (P1 + dP, P1, P_K))
    # x^2 = scale * g; each range puts g between the loads with positive gaps.
    ranges = [
        ("0 < x < b", {P_K: g + e1, P1: g + e1 + e2, dP: e3}, mu * (p2 + p1 - 2 * pk)),
        ("b < x < a1", {P_K: g - e1, P1: g + e2, dP: e3}, mu * (p2 + p1)),
        ("a1 < x < a2", {P_K: g - e1 - e2, P1: g - e1, dP: e1 + e3}, mu * p2),
    ]

    clamp = sympy.Function("clamp")  # Max(0, .) held unevaluated while the loads go in

    def place(expr: sympy.Expr, loads: dict) -> sympy.Expr:
        expr = expr.replace(sympy.Max, lambda *args: clamp(*args))
        expr = expr.subs(x, sympy.sqrt(scale * g)).subs(loads, simultaneous=True)
        # Expanded radicands let Max(0, .) see their sign, and put both sides in one form.
        expr = expr.replace(clamp, lambda *args: sympy.Max(*[sympy.expand(a) for a in args]))
        return sympy.expand(
            expr.replace(
                lambda e: e.is_Pow and e.exp == sympy.S.Half,
                lambda e: sympy.sqrt(sympy.expand(e.base)),
            )
        )

    for label, loads, paper in ranges:
        placed = place(hertz_traction_difference(), loads)
        assert not placed.has(sympy.Max), f"{label}: clamps not resolved: {placed}"
        eq.matches_paper(
            placed,
            place(paper, loads),
            how=f"one clamped expression; on {label} it is the paper's branch",
            printed=r"\mu(p(x,P_2)+p(x,P_1)-2p(x,P_K))\ \text{clamped}",
        )
