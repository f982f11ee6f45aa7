"""Flat punch with rounded corners: contact law, edge multiplier and pressure (beyond the paper).

The profile is flat over |x| < c and circular, of radius R, beyond:
    h(x) = 0 for |x| < c,   h(x) = (|x| - c)^2 / (2 R) for |x| > c.
The law P(a) comes from the plane-contact relation of ``contact_law_hertz``,
    P(a) = (E*/2) int_{-a}^{a} x h'(x) / sqrt(a^2 - x^2) dx,
and is asserted to be the published E* a^2 (pi - 2 phi0 - sin 2 phi0) / (4 R), phi0 = arcsin(c/a).
L_I follows from (19).  The emitted forms use the corner angle psi = pi/2 - phi0 = arccos(c/a),
computed as atan2(sqrt((a - c)(a + c)), c): accurate as a -> c and defined for c = 0, where the
law is Hertz's (29).  a(P) has no closed form; the law class inverts P(a) numerically.

The pressure is Mossakovskii's superposition of flat-punch pressures,
    p(x) = (1/pi) int_{max(|x|, c)}^{a} P'(s) ds / sqrt(s^2 - x^2).
Integrated by parts (P'(s)/s vanishes at s = c, sqrt(s^2 - x^2) at s = |x|), the remainder is
rationalised by u = sqrt((s^2 - x^2)/(s^2 - c^2)): partial fractions in u with one real
antiderivative for |x| < c (u from u(a) up to infinity) and |x| > c (u from 0 up to u(a)).  The
logarithms of that closed form are singular at |x| = c with cancelling coefficients; the emitted
form gathers them into (c - |x|) ln|c^2 - x^2| and writes each t ln t as ln(t^t), so that x = 0,
+-c, +-a raise no NumPy warning (0^0 = 1).  It is checked against the derived form, against
int p dx = P and against the edge asymptote (4) with L_I of (19); tests/test_contact_laws.py
compares it with an independent principal-value inversion of the profile.
"""

from __future__ import annotations

import functools

import mpmath
import sympy

from asymslip.codegen import Argument, Derivation

from ._glossary import a, dP_da
from .contact_law_hertz import E_star, load_from_profile, x
from .section2_calibrations import normal_multiplier

c = sympy.Symbol("c", positive=True)  # flat half-width, > 0 while deriving
# Emitted code allows c = 0 (a plain cylinder).  A separate symbol of the same name keeps
# SymPy from turning atan2(y, c) into atan(y/c) on the strength of c > 0.
c_emit = sympy.Symbol("c", nonnegative=True)
R = sympy.Symbol("R", positive=True)
s, u, X, excess = sympy.symbols("s u X excess", positive=True)  # X stands for |x|
psi = sympy.Symbol("psi", positive=True)  # corner angle arccos(c/a)
chord = sympy.Symbol("D", positive=True)  # sqrt(a^2 - c^2)
edge = sympy.Symbol("S", positive=True)  # sqrt(a^2 - x^2)

HALF_WIDTH = Argument(a, "Contact half-width a > c [length].")
FLAT = Argument(c_emit, "Half-width c >= 0 of the flat face of the punch [length].")
RADIUS = Argument(R, "Radius R > 0 of the rounded corners [length].")
MODULUS = Argument(E_star, "Plane-strain contact modulus E* > 0 [force/length^2].")
POSITION = Argument(x, "Position along the interface from the contact centre [length].")
LAW_ARGS = (HALF_WIDTH, FLAT, RADIUS, MODULUS)


def profile() -> sympy.Expr:
    """The gap h(x): flat over |x| < c, circular of radius R beyond."""
    return sympy.Piecewise(
        ((x + c) ** 2 / (2 * R), x < -c), (0, x < c), ((x - c) ** 2 / (2 * R), True)
    )


def profile_branch_free() -> sympy.Expr:
    """The same profile without branches: Max(0, |x| - c)^2/(2R), c allowed to be 0."""
    return sympy.Max(0, sympy.Abs(x) - c_emit) ** 2 / (2 * R)


@functools.cache
def flat_rounded_load() -> sympy.Expr:
    """P(a) for a > c, from the plane-contact relation."""
    raw = load_from_profile(profile())
    # The integral comes with Min(a, c) and Max(-a, -c); in contact a > c, i.e. a = c + excess.
    return sympy.expand(raw.subs(a, c + excess).subs(excess, a - c))


@functools.cache
def flat_rounded_load_slope() -> sympy.Expr:
    return sympy.simplify(sympy.diff(flat_rounded_load(), a))


@functools.cache
def flat_rounded_multiplier() -> sympy.Expr:
    """(19) with dP/da of the law, in terms of a."""
    return normal_multiplier().subs(dP_da, flat_rounded_load_slope())


@functools.cache
def flat_rounded_multiplier_slope() -> sympy.Expr:
    """dL_I/dP = (dL_I/da) / (dP/da), in terms of a."""
    return sympy.simplify(sympy.diff(flat_rounded_multiplier(), a) / flat_rounded_load_slope())


def _integrate_partial_fractions(expr: sympy.Expr, var: sympy.Symbol) -> sympy.Expr:
    """Real antiderivative of a sum of k/(alpha var + beta): sum of (k/alpha) ln|var + beta/alpha|.

    Valid on any interval free of the poles, whichever sign var + beta/alpha has there.
    """
    total = sympy.S.Zero
    for term in sympy.Add.make_args(sympy.apart(expr, var)):
        numerator, denominator = sympy.fraction(sympy.factor(term))
        linear = sympy.Poly(denominator, var)
        assert linear.degree() == 1 and not numerator.has(var), term
        alpha, beta = linear.coeff_monomial(var), linear.coeff_monomial(1)
        total += numerator / alpha * sympy.log(sympy.Abs(var + beta / alpha))
    return total


def _log_coefficients(expr: sympy.Expr) -> sympy.Expr:
    """sum k_i of sum k_i ln|var - p_i|, which behaves as (sum k_i) ln var for large var."""
    return sympy.Add(*(term.as_independent(sympy.log)[0] for term in sympy.Add.make_args(expr)))


@functools.cache
def pressure_pieces() -> dict[str, sympy.Expr]:
    """Mossakovskii's integral for the law: by parts, then the rationalising substitution."""
    slope_over_s = sympy.simplify(flat_rounded_load_slope().subs(a, s) / s)  # P'(s)/s
    primitive = sympy.integrate(s / sympy.sqrt(s**2 - X**2), s)  # of s / sqrt(s^2 - x^2)
    derivative = sympy.simplify(sympy.diff(slope_over_s, s))
    # (P'(s)/s)' sqrt(s^2 - x^2) ds = k(u) u d(s^2) / (2 s^2), u = sqrt((s^2 - X^2)/(s^2 - c^2))
    per_u = sympy.simplify(derivative * s * sympy.sqrt(s**2 - c**2))
    square = (c**2 * u**2 - X**2) / (u**2 - 1)  # s^2 as a function of u
    rational = sympy.factor(per_u * u * sympy.diff(square, u) / (2 * square))
    antiderivative = _integrate_partial_fractions(rational, u)
    return {
        "slope_over_s": slope_over_s,
        "primitive": primitive,
        "per_u": per_u,
        "square": square,
        "rational": rational,
        "antiderivative": antiderivative,
        "boundary": slope_over_s.subs(s, a) * primitive.subs(s, a),
        "at_edge": sympy.sqrt((a**2 - X**2) / (a**2 - c**2)),  # u at s = a
    }


@functools.cache
def flat_rounded_pressure_closed() -> sympy.Expr:
    """p at |x| = X < a as derived: boundary term minus the antiderivative at u(a).

    Its value at the lower limit is zero both for X < c (u -> oo) and X > c (u = 0).
    """
    pieces = pressure_pieces()
    remainder = pieces["antiderivative"].subs(u, pieces["at_edge"])
    return (pieces["boundary"] - remainder) / sympy.pi


@functools.cache
def in_angle(expr: sympy.Expr) -> sympy.Expr:
    """Write arcsin(c/a) = pi/2 - psi and sqrt(a^2 - c^2) = D."""
    replaced = expr.subs(sympy.asin(c / a), sympy.pi / 2 - psi)
    return sympy.simplify(replaced.subs(sympy.sqrt(a**2 - c**2), chord))


def chord_value() -> sympy.Expr:
    """D = sqrt(a^2 - c^2), clamped to 0 for a <= c."""
    return sympy.sqrt(sympy.Max(0, (a - c_emit) * (a + c_emit)))


def angle_value() -> sympy.Expr:
    """psi = arccos(c/a) as atan2(D, c): accurate as a -> c, pi/2 for c = 0."""
    return sympy.atan2(chord_value(), c_emit)


def emitted(expr: sympy.Expr) -> sympy.Expr:
    """psi as atan2(D, c) and D = sqrt(Max(0, (a - c)(a + c))), with c allowed to be 0."""
    return expr.subs(c, c_emit).subs({psi: angle_value(), chord: chord_value()})


def emitted_at_angle(expr: sympy.Expr) -> sympy.Expr:
    """The same quantity with psi and D left as arguments, for callers that evaluate many
    quantities at one half-width (a Newton iteration needs P and dP/da together)."""
    return expr.subs(c, c_emit)


ANGLE = Argument(
    psi, "Corner angle psi = arccos(c/a) at this half-width, from flat_rounded_corner_angle [rad]."
)
assert chord.name == "D" and psi.name == "psi"
CHORD = Argument(
    chord, "Chord D = sqrt(a^2 - c^2) at this half-width, from flat_rounded_chord [length]."
)


@functools.cache
def pressure_bracket() -> sympy.Expr:
    """p pi R / E*, rearranged so that each logarithmic singularity has a vanishing coefficient.

    In psi, D, S = sqrt(a^2 - x^2) and X = |x|, the derived form's ln|u - 1| and ln|c u - X|
    are singular at X = c.  Since (u - 1)(u + 1) = (c^2 - X^2)/D^2 and
    (c u - X)(c u + X) = a^2 (c^2 - X^2)/D^2 with u = S/D, both singular parts are ln|c^2 - X^2|
    and combine with the coefficient (c - X)/2.  Each t ln t is written ln(t^t).
    """
    t = (c - X) / a  # zero at |x| = c
    # |t|^t: base and exponent are the same rounded number, so they underflow together and
    # 0^0 = 1; (c + X)^t is 0^0 only at c = X = 0, and (c S + X D)^(2X/a) only at X = 0.
    powers = ((c * edge + X * chord) / a**2) ** (2 * X / a) * ((c + X) / a) ** t * abs(t) ** t
    return psi * edge - c * sympy.log((edge + chord) / a) + a / 2 * sympy.log(powers)


@functools.cache
def flat_rounded_pressure() -> sympy.Expr:
    """The emitted pressure: |x| clamped to a, and sign(S) = 0 outside the contact."""
    inside = sympy.Min(sympy.Abs(x), a)
    edge_value = sympy.sqrt(sympy.Max(0, (a - inside) * (a + inside)))
    # At |x| = a the bracket's terms cancel only to rounding: sign(S) makes the outside exactly
    # 0, and Max(0, .) keeps a rounding error within a few ulps of the edge from going negative.
    bracket = pressure_bracket().subs({edge: edge_value, X: inside})
    return emitted(sympy.Max(0, sympy.sign(edge_value) * E_star * bracket / (sympy.pi * R)))


# --- independent numerical references (mpmath) --------------------------------------------------


def _mp(expr: sympy.Expr, *symbols: sympy.Symbol):
    """An mpmath function of ``symbols`` that accepts numbers or decimal strings."""
    function = sympy.lambdify(symbols, expr, "mpmath")
    return lambda *values: function(*map(mpmath.mpf, values))


def derive() -> Derivation:  # noqa: C901 - one block per established result
    d = Derivation(__file__)
    d.describe_module(
        "flat_rounded",
        "Flat punch with rounded corners (flat half-width c, corner radius R), beyond the "
        "paper: contact law P(a), edge multiplier L_I of (19) and contact pressure.",
    )
    load, slope = flat_rounded_load(), flat_rounded_load_slope()
    multiplier, multiplier_slope = flat_rounded_multiplier(), flat_rounded_multiplier_slope()
    law_mp = {
        name: _mp(expr, a, c, R, E_star)
        for name, expr in [
            ("load", load),
            ("slope", slope),
            ("multiplier", multiplier),
            ("multiplier_slope", multiplier_slope),
        ]
    }
    law_points = [
        {"a_value": a_, "c_value": c_}
        for a_, c_ in [("2", "1"), ("1.001", "1"), ("5", "0.5"), ("3", "0")]
    ]

    def emitted_matches(eq, name: str, expr: sympy.Expr) -> None:
        function = _mp(emitted(in_angle(expr)), a, c_emit, R, E_star)
        eq.matches_numerically(
            lambda a_value, c_value: function(a_value, c_value, 1, 1),
            lambda a_value, c_value: law_mp[name](a_value, c_value, 1, 1),
            law_points,
            how="the emitted atan2 form equals the derived one (c/a = 1/2, 0.999, 0.1, 0)",
            symbolic=True,
        )

    with d.equation("FR-law", "Contact law of the flat punch with rounded corners") as eq:
        eq.beyond_paper(
            "the plane-contact relation P = (E*/2) int x h'(x)/sqrt(a^2 - x^2) dx with "
            "h = (|x| - c)^2/(2R) beyond the flat |x| < c",
            derived=load,
        )
        phi0 = sympy.asin(c / a)
        eq.matches_paper(
            load,
            E_star * a**2 * (sympy.pi - 2 * phi0 - sympy.sin(2 * phi0)) / (4 * R),
            how="equals the published E* a^2 (pi - 2 phi0 - sin 2 phi0)/(4R), phi0 = arcsin(c/a)",
            printed=r"P=\frac{E^* a^2}{4R}\left(\pi-2\phi_0-\sin 2\phi_0\right),"
            r"\ \phi_0=\arcsin\frac{c}{a}",
        )
        eq.holds(
            load.subs(c, 0) - sympy.pi * E_star * a**2 / (4 * R),
            how="c = 0 gives the Hertz law (29)",
        )
        eq.holds(
            in_angle(load) - E_star * (a**2 * psi - c * chord) / (2 * R),
            how="with psi = arccos(c/a), D = sqrt(a^2 - c^2): P = E* (a^2 psi - c D)/(2R)",
        )
        emitted_matches(eq, "load", load)
    with d.equation("FR-slope", "Slope dP/da of the rounded-flat law") as eq:
        eq.beyond_paper("d/da of the rounded-flat law (not in the paper)", derived=slope)
        eq.holds(
            in_angle(slope) - E_star * a * psi / R,
            how="dP/da = E* a arccos(c/a)/R > 0 for a > c: the law is increasing",
            derived=slope,
        )
        emitted_matches(eq, "slope", slope)
    with d.equation("FR-19", "Normal edge multiplier of the rounded flat, from (19)") as eq:
        eq.beyond_paper(
            "(19) applied to the rounded-flat law (not in the paper)",
            derived=multiplier,
        )
        eq.holds(
            in_angle(multiplier) - E_star * sympy.sqrt(2 * a) * psi / (sympy.pi * R),
            how="(19): L_I = E* sqrt(2a) arccos(c/a)/(pi R)",
            derived=multiplier,
        )
        eq.holds(
            multiplier.subs(c, 0) - E_star / R * sympy.sqrt(a / 2),
            how="c = 0 gives the Hertz multiplier (31)",
        )
        emitted_matches(eq, "multiplier", multiplier)
    with d.equation("FR-26", "Slope dL_I/dP of the rounded-flat multiplier") as eq:
        eq.beyond_paper(
            "(dL_I/da)/(dP/da) for the rounded-flat law (not in the paper)",
            derived=multiplier_slope,
        )
        half = sympy.Rational(1, 2)
        eq.holds(
            in_angle(multiplier_slope)
            - sympy.sqrt(2) / (sympy.pi * a ** sympy.Rational(3, 2)) * (half + c / (chord * psi)),
            how="dL_I/dP = (dL_I/da)/(dP/da) = sqrt(2)/(pi a^(3/2)) (1/2 + c/(D arccos(c/a)))",
            derived=multiplier_slope,
        )
        eq.holds(
            multiplier_slope.subs(c, 0) - multiplier.subs(c, 0) / (4 * load.subs(c, 0)),
            how="c = 0 gives the Hertz L_I' = L_I/(4P) of (30)",
        )
        emitted_matches(eq, "multiplier_slope", multiplier_slope)

    closed = flat_rounded_pressure_closed()
    with d.equation("FR-p", "Pressure under the flat punch with rounded corners") as eq:
        eq.beyond_paper(
            "Mossakovskii's superposition (1/pi) int P'(s) ds/sqrt(s^2 - x^2), by parts and "
            "u = sqrt((s^2 - x^2)/(s^2 - c^2)); one closed form for |x| < c and |x| > c",
            derived=closed,
        )
        pieces = pressure_pieces()
        eq.holds(
            pieces["slope_over_s"].subs(s, c) + pieces["primitive"].subs(s, X),
            how="the by-parts boundary terms vanish at the lower limit: P'(s)/s = 0 at s = c, "
            "sqrt(s^2 - x^2) = 0 at s = |x|",
        )
        eq.holds(
            pieces["per_u"] - E_star * c / R,
            how="(P'(s)/s)' = E* c/(R s sqrt(s^2 - c^2)), so the remainder is "
            "(E* c/R) int u d(s^2)/(2 s^2) with u = sqrt((s^2 - x^2)/(s^2 - c^2))",
        )
        square = pieces["square"]
        eq.holds(
            (square - X**2) / (square - c**2) - u**2,
            how="s^2 = (c^2 u^2 - x^2)/(u^2 - 1) inverts that u",
        )
        eq.holds(
            sympy.diff(pieces["antiderivative"].replace(sympy.Abs, lambda w: w), u)
            - pieces["rational"],
            how="the partial-fraction antiderivative differentiates back to the integrand "
            "(d ln|w| = dw/w on either side of each pole)",
        )
        eq.holds(
            _log_coefficients(pieces["antiderivative"]) + pieces["antiderivative"].subs(u, 0),
            how="it vanishes at u -> oo (s -> c when |x| < c: its log coefficients sum to 0) "
            "and at u = 0 (s = |x| when |x| > c)",
        )
        bracket_mp = _mp(pressure_bracket(), a, c, X, psi, chord, edge)
        closed_mp = _mp(closed, a, c, X, R, E_star)

        def emitted_bracket(a_value, c_value, x_value):
            a_value, c_value, x_value = map(mpmath.mpf, (a_value, c_value, x_value))
            return (
                bracket_mp(
                    a_value,
                    c_value,
                    abs(x_value),
                    mpmath.acos(c_value / a_value),
                    mpmath.sqrt(a_value**2 - c_value**2),
                    mpmath.sqrt(a_value**2 - x_value**2),
                )
                / mpmath.pi
            )

        eq.matches_numerically(
            emitted_bracket,
            lambda a_value, c_value, x_value: closed_mp(a_value, c_value, x_value, 1, 1),
            [
                {"a_value": a_, "c_value": c_, "x_value": x_}
                for a_, c_, x_ in [
                    ("2", "1", "0.3"),
                    ("2", "1", "1.5"),
                    ("2", "1", "1.9999"),
                    ("1.01", "1", "0.5"),
                    ("3", "0.1", "0.05"),
                    ("3", "0.1", "2"),
                ]
            ],
            how="the emitted rearrangement equals the derived form on both sides of |x| = c",
            symbolic=True,
        )
        kernel_mp = _mp(flat_rounded_pressure(), x, a, c_emit, R, E_star)
        eq.matches_numerically(
            lambda a_value, c_value, x_value: kernel_mp(x_value, a_value, c_value, 1, 1),
            lambda a_value, c_value, x_value: 0
            if abs(x_value) >= a_value
            else closed_mp(a_value, c_value, abs(x_value), 1, 1)
            if c_value > 0
            else mpmath.sqrt(a_value**2 - x_value**2) / 2,  # c = 0: Hertz's (48), E* = R = 1
            [
                {"a_value": mpmath.mpf(2), "c_value": mpmath.mpf(c_), "x_value": mpmath.mpf(x_)}
                for c_, x_ in [(1, "-0.3"), (1, "1.5"), (1, "-2.5"), (0, "0.5")]
            ],
            how="the emitted kernel (|x| clamped to a) equals the derived form inside, 0 "
            "outside, and Hertz's (48) for c = 0",
            symbolic=True,
        )
        eq.matches_numerically(
            lambda a_value, c_value: 2
            * mpmath.quad(lambda t: emitted_bracket(a_value, c_value, t), [0, c_value, a_value]),
            lambda a_value, c_value: law_mp["load"](a_value, c_value, 1, 1),
            [{"a_value": mpmath.mpf(2), "c_value": mpmath.mpf(1)}],
            how="int_{-a}^{a} p dx = P(a)",
            digits=15,
            symbolic=True,
        )
        gap = mpmath.mpf(10) ** -40
        eq.matches_numerically(
            lambda a_value, c_value: emitted_bracket(a_value, c_value, a_value * (1 - gap))
            / mpmath.sqrt(a_value * gap),
            lambda a_value, c_value: law_mp["multiplier"](a_value, c_value, 1, 1),
            [{"a_value": mpmath.mpf(2), "c_value": mpmath.mpf(1)}],
            how="p/sqrt(a - x) -> L_I of (19) at the edge, as in (4) (a - x = 1e-40 a)",
            symbolic=True,
        )

    def emit(name, args, expr, equations, summary, doc, returns):
        d.emit(
            name=name,
            args=args,
            expr=expr,
            equations=equations,
            summary=summary,
            doc=doc,
            module="flat_rounded",
            returns=returns,
        )

    with d.equation("FR-h", "Profile of the flat punch with rounded corners") as eq:
        eq.given(
            "the gap h = 0 over the flat |x| < c and (|x| - c)^2/(2R) beyond: the "
            "starting point of the rounded-flat law",
            derived=profile(),
        )
        inside, beyond_ = sympy.symbols("f e", positive=True)
        (left, _), (flat, _), (right, _) = profile().args  # the pieces x < -c, |x| < c, x > c
        for piece, point, how in (
            (flat, {x: c * inside / (1 + inside)}, "on the flat 0 < x < c"),
            (flat, {x: -c * inside / (1 + inside)}, "on the flat -c < x < 0"),
            (right, {x: c + beyond_}, "beyond the right corner x > c"),
            (left, {x: -c - beyond_}, "beyond the left corner x < -c"),
        ):
            eq.holds(
                profile_branch_free().subs(c_emit, c).subs(point) - piece.subs(point),
                how=f"the branch-free Max(0, |x| - c)^2/(2R) equals it {how}",
            )
    emit(
        "flat_rounded_profile",
        (POSITION, FLAT, RADIUS),
        profile_branch_free(),
        ("29",),
        "Gap profile h(x) = Max(0, |x| - c)^2/(2R) of the flat punch with rounded corners.",
        "Flat (h = 0) over |x| < c, circular of radius R (in the parabolic, half-plane "
        "approximation) beyond; c = 0 is the cylinder of (29).  The starting point of the law; "
        "the reference solver's normal problem starts from it.",
        "h [length].",
    )

    emit(
        "flat_rounded_load",
        LAW_ARGS,
        emitted(in_angle(load)),
        ("29",),
        "Normal load P(a) of the flat punch with rounded corners at half-width a.",
        "The counterpart of (29): P = E* (a^2 psi - c sqrt(a^2 - c^2))/(2R) with psi = "
        "arccos(c/a) = atan2(sqrt((a - c)(a + c)), c), accurate as a -> c and equal to Hertz's "
        "law for c = 0.  Zero for a <= c: any load P > 0 gives a > c.  For a close to c, P "
        "is a difference of nearly equal terms (relative error about 1e-16 (c/a)/(1 - c/a)), as "
        "ill-conditioned as the law itself there.",
        "P [force/length].",
    )
    emit(
        "flat_rounded_load_slope",
        LAW_ARGS,
        emitted(in_angle(slope)),
        ("29",),
        "Slope dP/da = E* a arccos(c/a)/R of the rounded-flat law.",
        "Positive for a > c, so the law is increasing; zero for a <= c.",
        "dP/da [force/length^2].",
    )
    emit(
        "flat_rounded_normal_edge_multiplier",
        LAW_ARGS,
        emitted(in_angle(multiplier)),
        ("19",),
        "Normal edge multiplier L_I of the rounded flat at half-width a.",
        "(19) with the slope of the law: L_I = E* sqrt(2a) arccos(c/a)/(pi R).",
        "L_I [force/length^(5/2)].",
    )
    emit(
        "flat_rounded_normal_edge_multiplier_slope",
        LAW_ARGS,
        emitted(in_angle(multiplier_slope)),
        ("26",),
        "Slope dL_I/dP of the rounded-flat edge multiplier at half-width a > c.",
        "(dL_I/da)/(dP/da) = sqrt(2)/(pi a^(3/2)) (1/2 + c/(sqrt(a^2 - c^2) arccos(c/a))); it "
        "grows without bound as a -> c, where the contact is nearly a flat punch.",
        "dL_I/dP [1/length^(3/2)].",
    )
    # The same four quantities from psi and D computed once (a Newton step needs P and P').
    emit(
        "flat_rounded_chord",
        (HALF_WIDTH, FLAT),
        chord_value(),
        ("29",),
        "Chord D = sqrt(a^2 - c^2) of the rounded flat at half-width a (0 for a <= c).",
        "The length shared by the law, its slope and the edge multiplier.",
        "D [length].",
    )
    emit(
        "flat_rounded_corner_angle",
        (CHORD, FLAT),
        angle_value().subs(chord_value(), chord),
        ("29",),
        "Corner angle psi = arccos(c/a) of the rounded flat, from its chord D.",
        "atan2(D, c) with D = sqrt(a^2 - c^2) from flat_rounded_chord: accurate as a -> c "
        "(where arccos(c/a) loses digits), pi/2 for c = 0 and 0 for a <= c.",
        "psi [rad].",
    )
    for name, expr in (
        ("load", load),
        ("load_slope", slope),
        ("normal_edge_multiplier", multiplier),
        ("normal_edge_multiplier_slope", multiplier_slope),
    ):
        at_angle = emitted_at_angle(in_angle(expr))
        used = [arg for arg in (ANGLE, CHORD) if arg.symbol in at_angle.free_symbols]
        emit(
            f"flat_rounded_{name}_at_angle",
            (*LAW_ARGS, *used),
            at_angle,
            ("26",)
            if name.endswith("slope") and "multiplier" in name
            else ("19",)
            if "multiplier" in name
            else ("29",),
            f"flat_rounded_{name} from the corner angle (and chord) at half-width a.",
            f"Equals flat_rounded_{name}(a, c, R, E_star) with psi and D passed in, so that "
            "several quantities at one half-width share one atan2 and one sqrt.",
            "As flat_rounded_" + name + ".",
        )
    emit(
        "flat_rounded_pressure",
        (POSITION, *LAW_ARGS),
        flat_rounded_pressure(),
        ("4", "48"),
        "Contact pressure p(x) under the flat punch with rounded corners; 0 for |x| >= a.",
        "The counterpart of (48), with the edge asymptote (4): (E*/(pi R)) [psi S - c ln((S + "
        "D)/a) + |x| ln((c S + |x| D)/a^2) + ((c - |x|)/2) ln(|c^2 - x^2|/a^2)], S = sqrt(a^2 - "
        "x^2), D = sqrt(a^2 - c^2), psi = arccos(c/a).  The logarithmic singularities at |x| = "
        "c cancel; t ln t terms are written ln(t^t), so x = 0, +-c, +-a give no warning.  Needs "
        "a > c.  The terms are larger than p near the edges and, for a close to c, everywhere: "
        "the relative error grows there (about 1e-13 at a - |x| = 1e-6 a, 1e-10 at c/a = "
        "0.9999).",
        "p [force/length^2].",
    )
    return d
