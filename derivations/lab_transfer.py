"""Carrying a laboratory test over to a prototype: what must be equal for two edges to coincide.

Beyond the paper, on its own ambition (introduction): "to describe the behaviour of contact
edges ... in a small number of parameters so that the results of a laboratory experiment may be
carried over with confidence to different prototypes".

LT1  In the edge's own coordinate s = a2 - x, the slip-zone width (17), the shear-traction
     change (49) and the slip (the integral of (15)) depend on the contact only through
     mu, L_I1, L_I2, L_II1, L_II2 and da = a2 - a1: their derivatives with respect to a1 at
     fixed s vanish.  Two edges that share these six numbers coincide to leading order.
LT2  The peak shear change over the slip zone, q_diff at the stick boundary,
     mu (L_I1 sqrt(w) + L_I2 sqrt(w + da)) with w = a1 - b, from (8) and (11); checked
     against (49) at x = b.
LT3  A Hertz pad (29), (31) reproduces L_I1, L_I2 and da with exactly one (a1, a2, R):
     a1 = da L_I1^2 / (L_I2^2 - L_I1^2), R = E* sqrt(a1/2) / L_I1, which needs L_I2 > L_I1.
LT4  The rig's path slopes from the two shear multipliers, by (21) at the rig's own half-widths:
     eta = 4 (L_II2/L_I2 - L_II1/L_I1) / (pi da), lambda = L_II1/L_I1 - pi eta a1 / 4.
LT5  A rounded-flat rig at the prototype's own a1 and a2 (the second-order match): R from
     L_I1, and c from L_I2/L_I1 = sqrt(a2/a1) arccos(c/a2)/arccos(c/a1), which rises from the
     cylinder's sqrt(a2/a1) at c = 0 without bound as c -> a1; so it exists when the
     prototype's L_I grows at least as fast as a cylinder's of the same size.
"""

from __future__ import annotations

import functools

import sympy

from asymslip.codegen import Argument, Derivation
from asymslip.codegen.derivation import DerivationError

from ._glossary import L_I1, L_I2, L_II1, L_II2, a, a1, a2, arguments, b, da, dP_da, mu, x
from .contact_law_flat_rounded import R as corner_radius
from .contact_law_flat_rounded import c as flat
from .contact_law_flat_rounded import c_emit as flat_emit
from .contact_law_flat_rounded import flat_rounded_load_slope
from .contact_law_hertz import E_star, hertz_load
from .contact_law_hertz import R as pad_radius
from .section2_calibrations import normal_multiplier, slip_zone_width_from_multipliers
from .section3_slip_displacement import slip_on_loading
from .section3_tractions import traction_difference

lam = sympy.Symbol("lam", real=True)
eta = sympy.Symbol("eta", real=True)
s = sympy.Symbol("s", positive=True)  # distance from the state-2 edge, a2 - x
w = sympy.Symbol("w", positive=True)  # slip-zone width a1 - b

WIDTH = Argument(w, "Slip-zone width a1 - b >= 0 of the edge [length].")
GROWTH = Argument(da, "Advance of the edge a2 - a1 > 0 over the cycle [length].")
MODULUS = Argument(E_star, "Plane-strain contact modulus E* of the rig > 0 [force/length^2].")
RIG_L_I1 = Argument(L_I1, "Normal edge multiplier L_I at load state 1 (4) [force/length^(5/2)].")
RIG_L_I2 = Argument(L_I2, "Normal edge multiplier L_I at load state 2 (4) [force/length^(5/2)].")
HALF_WIDTH1 = Argument(a1, "Contact half-width of the rig at load state 1 [length].")
HALF_WIDTH2 = Argument(a2, "Contact half-width of the rig at load state 2, a2 > a1 [length].")
HALF_WIDTH = Argument(a, "Contact half-width a > c [length].")
FLAT = Argument(flat_emit, "Half-width c >= 0 of the flat face of the rig's pad [length].")
L_I_AT = Argument(
    sympy.Symbol("L_I", positive=True),
    "Normal edge multiplier L_I to reproduce at half-width a (4) [force/length^(5/2)].",
)


def _hertz_multiplier_of_half_width() -> sympy.Expr:
    """(19) with dP/da of (29): L_I of a cylinder of radius R at half-width a."""
    return normal_multiplier().subs(dP_da, sympy.diff(hertz_load(), a))


def _flat_rounded_multiplier_of_half_width() -> sympy.Expr:
    """(19) with dP/da of the rounded flat: L_I = E* sqrt(2a) arccos(c/a) / (pi R)."""
    return normal_multiplier().subs(dP_da, flat_rounded_load_slope())


@functools.cache
def edge_coordinates() -> dict[sympy.Symbol, sympy.Expr]:
    """x = a2 - s, a2 = a1 + da, b = a1 - w: the edge's own frame."""
    return {x: a1 + da - s, a2: a1 + da, b: a1 - w}


@functools.cache
def consistent_width() -> sympy.Expr:
    """a1 - b of (17) in the six edge numbers."""
    return slip_zone_width_from_multipliers()


@functools.cache
def peak_shear_change() -> sympy.Expr:
    """q2 - q1 at the stick boundary: mu p2 - (-mu p1) by (8) and (11), x = b."""
    p2 = L_I2 * sympy.sqrt(a2 - x)
    p1 = L_I1 * sympy.sqrt(a1 - x)
    at_boundary = (mu * p2 - (-mu * p1)).subs(x, b)
    return sympy.simplify(at_boundary.subs(edge_coordinates()))


@functools.cache
def hertz_match() -> dict[sympy.Symbol, sympy.Expr]:
    """LT3: the one (a1, R) of a cylinder with the given L_I1, L_I2 and a2 - a1 = da."""
    multiplier = _hertz_multiplier_of_half_width()
    equations = [
        sympy.Eq(multiplier.subs(a, a1), L_I1),
        sympy.Eq(multiplier.subs(a, a1 + da), L_I2),
    ]
    solutions = sympy.solve(equations, [a1, pad_radius], dict=True)
    assert len(solutions) == 1, f"expected one positive (a1, R), got {solutions}"
    (solution,) = solutions
    return {key: sympy.factor(value) for key, value in solution.items()}


@functools.cache
def hertz_radius() -> sympy.Expr:
    """LT3: R of the cylinder whose L_I at half-width a1 is L_I1 (the same R as hertz_match)."""
    (radius,) = sympy.solve(
        sympy.Eq(_hertz_multiplier_of_half_width().subs(a, a1), L_I1), pad_radius
    )
    solution = hertz_match()
    rise = {L_I2: L_I1 * (1 + sympy.Symbol("t", positive=True))}  # L_I2 > L_I1
    difference = (radius.subs(a1, solution[a1]) - solution[pad_radius]).subs(rise)
    assert sympy.simplify(sympy.factor(difference)) == 0
    return radius


@functools.cache
def path_slopes() -> dict[sympy.Symbol, sympy.Expr]:
    """LT4: lambda and eta of the rig's path from (21) at both of its states."""
    equations = [
        sympy.Eq((lam + sympy.pi * eta * a1 / 4) * L_I1, L_II1),
        sympy.Eq((lam + sympy.pi * eta * (a1 + da) / 4) * L_I2, L_II2),
    ]
    (solution,) = sympy.solve(equations, [lam, eta], dict=True)
    eta_value = sympy.factor(solution[eta])
    # lambda written from the state-1 ratio, so a1 multiplies only the tension term.
    lam_value = L_II1 / L_I1 - sympy.pi * eta_value * a1 / 4
    assert sympy.simplify(lam_value - solution[lam]) == 0
    return {lam: lam_value, eta: eta_value}


@functools.cache
def flat_rounded_radius() -> sympy.Expr:
    """LT5: R of the rounded flat whose L_I at half-width a is the given one."""
    target = L_I_AT.symbol
    (radius,) = sympy.solve(
        sympy.Eq(_flat_rounded_multiplier_of_half_width(), target), corner_radius
    )
    return radius


@functools.cache
def flat_rounded_ratio() -> sympy.Expr:
    """LT5: L_I2/L_I1 of one rounded flat between half-widths a1 and a2."""
    multiplier = _flat_rounded_multiplier_of_half_width()
    return sympy.simplify(multiplier.subs(a, a2) / multiplier.subs(a, a1))


def _emitted_flat(expr: sympy.Expr) -> sympy.Expr:
    """arccos(c/a) as atan2(sqrt((a - c)(a + c)), c), c allowed to be 0 (a cylinder)."""

    def angle(length: sympy.Expr) -> sympy.Expr:
        chord = sympy.sqrt(sympy.Max(0, (length - flat_emit) * (length + flat_emit)))
        return sympy.atan2(chord, flat_emit)

    # A separate symbol (c >= 0) keeps SymPy from turning atan2(y, c) into atan(y/c).
    expr = expr.subs(flat, flat_emit)
    expr = expr.replace(lambda e: isinstance(e, sympy.acos), lambda e: angle(flat_emit / e.args[0]))
    expr = expr.replace(
        lambda e: isinstance(e, sympy.asin), lambda e: sympy.pi / 2 - angle(flat_emit / e.args[0])
    )
    assert not expr.has(flat), expr
    return expr


#: A point of the edge state at which identities SymPy cannot simplify are checked (40 digits).
SAMPLE = {
    mu: sympy.Rational(3, 10),
    L_I1: 2,
    L_I2: sympy.Rational(21, 10),
    L_II1: sympy.Rational(7, 10),
    L_II2: sympy.Rational(9, 10),
    da: sympy.Rational(1, 20),
    E_star: 3,
}


def _vanishes(value: sympy.Expr, what: str) -> None:
    number = sympy.N(value, 40)
    if not abs(number) < sympy.Float(10) ** -30:
        raise DerivationError(f"{what}: residual {number}")


def _check_edge_state(d: Derivation) -> None:
    with d.equation("LT1", "The edge state: six numbers fix the near-edge solution") as eq:
        width = consistent_width()
        eq.beyond_paper(
            "two edges coincide to leading order when they share mu, L_I1, L_I2, L_II1, L_II2 "
            "and da = a2 - a1: the matching conditions",
            derived=width,
        )
        if width.free_symbols != {mu, L_I1, L_I2, L_II1, L_II2, da}:
            raise DerivationError(f"LT1: the width depends on {width.free_symbols}")
        eq.holds(
            sympy.diff(width, a1),
            how="a1 - b of (17) written with a2 = a1 + da contains no a1: the width is a "
            "function of mu, L_I1, L_I2, L_II1, L_II2 and da alone",
        )
        for where, distance in (
            ("in the slip zone (s = (a2 - b)/3)", (width + da) / 3),
            ("in the stick zone (s = 3 (a2 - b))", (width + da) * 3),
        ):
            for quantity, expr in (
                ("(49) q2 - q1", traction_difference()),
                ("the slip", slip_on_loading()),
            ):
                in_frame = expr.subs({x: a1 + da - s, a2: a1 + da}).subs(b, a1 - width)
                derivative = sympy.diff(in_frame, a1).subs(s, distance).subs(SAMPLE)
                for a1_value in (sympy.Rational(5, 2), 7, 40):
                    _vanishes(derivative.subs(a1, a1_value), f"LT1 {quantity} {where}")
                eq.details.append(
                    f"d/da1 of {quantity} at fixed distance s from the edge {where} vanishes "
                    "(40 digits at a1 = 2.5, 7, 40, b from (17))"
                )

    with d.equation("LT2", "Peak shear change over the slip zone") as eq:
        peak = peak_shear_change()
        eq.beyond_paper(
            "q2 - q1 = mu p2 + mu p1 at x = b (slip conditions (8), (11)); both terms grow "
            "with the distance from the edge, so it is the largest |q2 - q1| of the slip zone",
            derived=peak,
        )
        q49 = traction_difference().subs(edge_coordinates()).subs(s, w + da)
        at_b = (q49 - peak).subs(w, consistent_width()).subs(SAMPLE).subs(a1, 7)
        _vanishes(at_b, "LT2")
        eq.details.append("equals (49) at x = b with (17)'s b (40 digits)")


def _check_rig_solutions(d: Derivation) -> None:
    with d.equation("LT3", "Hertz pad reproducing L_I1, L_I2 and a2 - a1: unique") as eq:
        solution = hertz_match()
        eq.beyond_paper(
            "a1 = da L_I1^2/(L_I2^2 - L_I1^2) and R = E* sqrt(a1/2)/L_I1 is the only solution "
            "of (31) at a1 and a1 + da; a1 > 0 needs L_I2 > L_I1 (a cylinder's L_I rises with "
            "P), so a prototype whose L_I falls along the path has no exact Hertz match",
            derived=sympy.Tuple(solution[a1], solution[pad_radius]),
        )
        multiplier = _hertz_multiplier_of_half_width()
        # L_I2 > L_I1 written L_I1 (1 + t), t > 0, so that SymPy may take the square roots.
        rise = {L_I2: L_I1 * (1 + sympy.Symbol("t", positive=True))}
        for k, value, target in ((1, a1, L_I1), (2, a1 + da, L_I2)):
            back = multiplier.subs(a, value).subs(solution).subs(rise)
            eq.holds(
                sympy.factor(sympy.simplify(sympy.factor(back))) - target.subs(rise),
                how=f"the solution gives back L_I{k}",
            )
    with d.equation("LT4", "The rig's path slopes from the shear multipliers") as eq:
        slopes = path_slopes()
        eq.beyond_paper(
            "eta = 4 (L_II2/L_I2 - L_II1/L_I1)/(pi da), lambda = L_II1/L_I1 - pi eta a1/4: "
            "without bulk tension (eta = 0) a rig can match only L_II1/L_I1 = L_II2/L_I2",
            derived=sympy.Tuple(slopes[lam], slopes[eta]),
        )
        for k, half_width, L_I, L_II in ((1, a1, L_I1, L_II1), (2, a1 + da, L_I2, L_II2)):
            eq.holds(
                (slopes[lam] + sympy.pi * slopes[eta] * half_width / 4) * L_I - L_II,
                how=f"(21) at state {k} of the rig gives back L_II{k}",
            )
    with d.equation("LT5", "Rounded-flat rig at the prototype's own half-widths") as eq:
        radius = flat_rounded_radius()
        ratio = flat_rounded_ratio()
        eq.beyond_paper(
            "R = E* sqrt(2 a1) arccos(c/a1)/(pi L_I1); L_I2/L_I1 = sqrt(a2/a1) arccos(c/a2)/"
            "arccos(c/a1) rises with c from the cylinder's sqrt(a2/a1) without bound as "
            "c -> a1, so one c exists exactly when the prototype's L_I2/L_I1 >= sqrt(a2/a1).  "
            "The rig then shares a1 and a2 as well as L_I1, L_I2 and (LT4) lambda and eta, so "
            "dP/da at both states, hence a'(P1) and a''(P1) to O(da), and the terms of the "
            "second-order slip zone agree: the second-order match",
            derived=ratio,
        )
        back = _flat_rounded_multiplier_of_half_width().subs(corner_radius, radius)
        eq.holds(back - L_I_AT.symbol, how="R gives back L_I at half-width a")
        eq.holds(
            sympy.simplify(ratio.subs(flat, 0) - sympy.sqrt(a2 / a1)),
            how="at c = 0 the ratio is the cylinder's sqrt(a2/a1)",
        )
        slope = sympy.diff(ratio, flat)
        for a2_over_a1 in ("1.001", "1.05", "1.5"):
            for fraction in ("0.001", "0.3", "0.9", "0.999"):
                at = {a1: 1, a2: sympy.Float(a2_over_a1, 40), flat: sympy.Float(fraction, 40)}
                if not sympy.N(slope.subs(at), 40) > 0:
                    raise DerivationError(f"LT5: the ratio falls with c at {at}")
        near_flat = {a1: 1, a2: sympy.Rational(21, 20), flat: 1 - sympy.Rational(1, 10**12)}
        if not sympy.N(ratio.subs(near_flat), 40) > 100:
            raise DerivationError("LT5: the ratio stays bounded as c -> a1")
        eq.details.append(
            "d/dc of the ratio > 0 at 12 points (a2/a1 = 1.001, 1.05, 1.5; c/a1 = 0.001 to "
            "0.999; 40 digits); above 100 at c = a1 (1 - 1e-12), a2/a1 = 1.05"
        )


def derive() -> Derivation:
    d = Derivation(__file__)
    d.describe_module(
        "lab_transfer",
        "Carrying a laboratory test over to a prototype (beyond the paper): the edge state "
        "that two contacts must share, the rig that reproduces it and the peak shear change.",
    )
    _check_edge_state(d)
    _check_rig_solutions(d)
    solution = hertz_match()
    slopes = path_slopes()
    d.emit(
        name="peak_shear_change",
        args=(*arguments(mu, L_I1, L_I2), WIDTH, GROWTH),
        expr=peak_shear_change(),
        equations=("8", "11", "49"),
        summary="Largest |q2 - q1| over the slip zone: its value at the stick boundary.",
        doc="mu (L_I1 sqrt(w) + L_I2 sqrt(w + da)), w = a1 - b: the slip conditions (8) and (11) "
        "at x = b, equal to (49) there when b is (17)'s.  For backward slip q2 - q1 is its "
        "negative.",
        module="lab_transfer",
        returns="Peak shear change [force/length^2].",
    )
    d.emit(
        name="hertz_matched_half_width",
        args=(RIG_L_I1, RIG_L_I2, GROWTH),
        expr=solution[a1],
        equations=("29", "31"),
        summary="Half-width a1 of the one cylinder whose edge has L_I1, L_I2 and a2 - a1 = da.",
        doc="da L_I1^2/(L_I2^2 - L_I1^2) (LT3 of derivations/lab_transfer.py); needs "
        "L_I2 > L_I1, since a cylinder's L_I rises with the load.",
        module="lab_transfer",
        returns="a1 [length].",
    )
    d.emit(
        name="hertz_matched_radius",
        args=(MODULUS, RIG_L_I1, HALF_WIDTH1),
        expr=hertz_radius(),
        equations=("31",),
        summary="Radius R of the cylinder whose L_I at half-width a1 is L_I1.",
        doc="E* sqrt(a1/2)/L_I1, from (31) (LT3).",
        module="lab_transfer",
        returns="R [length].",
    )
    d.emit(
        name="matched_tension_slope",
        args=(*arguments(da, L_I1, L_I2, L_II1, L_II2),),
        expr=slopes[eta],
        equations=("18", "21"),
        summary="Slope eta = dsigma/dP of the rig's path that gives its edge L_II1 and L_II2.",
        doc="4 (L_II2/L_I2 - L_II1/L_I1)/(pi da) (LT4), with the rig's own L_I1, L_I2 and "
        "a2 - a1 = da.",
        module="lab_transfer",
        returns="eta [1/length].",
    )
    d.emit(
        name="matched_shear_slope",
        args=(*arguments(a1, da, L_I1, L_I2, L_II1, L_II2),),
        expr=slopes[lam],
        equations=("18", "21"),
        summary="Slope lambda = dQ/dP of the rig's path that gives its edge L_II1 and L_II2.",
        doc="L_II1/L_I1 - pi eta a1/4 with eta from matched_tension_slope (LT4), with the "
        "rig's own a1, L_I1, L_I2 and a2 - a1 = da.",
        module="lab_transfer",
        returns="lambda, dimensionless.",
    )
    d.emit(
        name="flat_rounded_matched_radius",
        args=(HALF_WIDTH, FLAT, MODULUS, L_I_AT),
        expr=_emitted_flat(flat_rounded_radius()),
        equations=("19",),
        summary="Corner radius R of the rounded flat whose L_I at half-width a is L_I.",
        doc="E* sqrt(2a) arccos(c/a)/(pi L_I) (LT5); c = 0 is the cylinder's radius.",
        module="lab_transfer",
        returns="R [length].",
    )
    d.emit(
        name="flat_rounded_multiplier_ratio",
        args=(HALF_WIDTH1, HALF_WIDTH2, FLAT),
        expr=_emitted_flat(flat_rounded_ratio()),
        equations=("19",),
        summary="L_I2/L_I1 of one rounded flat between half-widths a1 and a2 (> c).",
        doc="sqrt(a2/a1) arccos(c/a2)/arccos(c/a1) (LT5): sqrt(a2/a1) at c = 0, rising "
        "with c without bound as c -> a1.",
        module="lab_transfer",
        returns="L_I2/L_I1, dimensionless.",
    )
    return d
