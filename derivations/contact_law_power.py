"""Power-law punch h = A |x|^n, n >= 1: law, edge multiplier and pressure (beyond the paper).

n = 1 is the wedge, n = 2 with A = 1/(2R) the cylinder of (29).  With h'(x) = n A x^(n-1) for
x > 0 the plane-contact relation of ``contact_law_hertz`` is
    P(a) = E* n A int_0^a x^n / sqrt(a^2 - x^2) dx,
which x = a sqrt(t) turns into Euler's Beta integral int_0^1 t^(p-1) (1 - t)^(q-1) dt =
Gamma(p) Gamma(q)/Gamma(p + q): P = K(n) E* A a^n with the shape factor
    K(n) = (n sqrt(pi)/2) Gamma((n + 1)/2) / Gamma(n/2 + 1)      (K(1) = 1, K(2) = pi/2).
NumPy has no Gamma function, so the emitted kernels take K as an argument; the law class
computes it once (``math.gamma``).  The symbolic-n result is checked exactly against
``load_from_profile`` for n = 1, 2, 3, against (29) for n = 2, A = 1/(2R), and numerically for
n = 2.5.  a(P) = (P/(K E* A))^(1/n) is closed; the growth a(P1 + dP) - a(P1) is emitted as
a1 expm1(log1p(dP/P1)/n), free of cancellation however small dP/P1 is.

The pressure is Mossakovskii's superposition (1/pi) int_|x|^a P'(s) ds / sqrt(s^2 - x^2).  With
s^2 = a^2 (1 - z tau), z = 1 - x^2/a^2, it is Euler's integral of the hypergeometric function:
    p(x) = (n K E* A / pi) a^(n-2) sqrt(a^2 - x^2) 2F1(1 - n/2, 1; 3/2; 1 - x^2/a^2).
The 2F1 value is an argument of the emitted kernel (SciPy's ``hyp2f1`` evaluates it at run
time; it is 1 for n = 2).  For the wedge, 2F1(1/2, 1; 3/2; z) = atanh(sqrt z)/sqrt z and the
pressure is elementary, (E* A/pi) arccosh(a/|x|), emitted NumPy-only as a log1p.
"""

from __future__ import annotations

import functools

import mpmath
import sympy
from sympy.codegen.cfunctions import expm1, log1p

from asymslip.codegen import Argument, Derivation

from ._glossary import P1, a, dP, dP_da
from .contact_law_hertz import E_star, P, R, hertz_load, load_from_profile, x
from .section2_calibrations import normal_multiplier

n = sympy.Symbol("n", positive=True)
A = sympy.Symbol("A", positive=True)
K = sympy.Symbol("K", positive=True)  # the shape factor K(n), an argument of the kernels
F = sympy.Symbol("hypergeometric", positive=True)  # the value of the 2F1 in the pressure
t, tau, z, s, X = sympy.symbols("t tau z s X", positive=True)  # X stands for |x|

EXPONENT = Argument(n, "Exponent n >= 1 of the profile h = A |x|^n (n = 1: wedge).")
COEFFICIENT = Argument(A, "Coefficient A > 0 of the profile h = A |x|^n [length^(1-n)].")
MODULUS = Argument(E_star, "Plane-strain contact modulus E* > 0 [force/length^2].")
SHAPE = Argument(
    K,
    "Shape factor K(n) = (n sqrt(pi)/2) Gamma((n + 1)/2) / Gamma(n/2 + 1) of P = K E* A a^n "
    "(K = 1 for the wedge, pi/2 for n = 2); PowerLaw.shape_factor computes it.",
)
PARAMETERS = (EXPONENT, COEFFICIENT, MODULUS, SHAPE)
HALF_WIDTH = Argument(a, "Contact half-width a > 0 [length].")
LOAD = Argument(P, "Normal load per unit length, P > 0 [force/length].")
LOAD1 = Argument(P1, "Normal load at load state 1, P1 > 0 [force/length].")
LOAD_CHANGE = Argument(dP, "Normal-load change P2 - P1 > 0 [force/length].")
POSITION = Argument(x, "Position along the interface from the contact centre [length].")
UNIT = {A: 1, E_star: 1}  # numerical checks at A = E* = 1: P and p are proportional to A E*


def euler_form(expr: sympy.Expr, var: sympy.Symbol) -> tuple[sympy.Expr, dict[str, sympy.Expr]]:
    """Write expr as C var^e0 (1 - var)^e1 (1 - w var)^e2; return C and the exponents, and w.

    Each factor's base is factored and normalised to the forms var, 1 - var, 1 - w var; the
    constant parts must be positive so that powers of products split.
    """
    expanded = sympy.expand_power_base(sympy.powdenest(expr, force=True), force=True)
    constant, exponents = sympy.S.One, {"var": sympy.S.Zero, "one_minus": sympy.S.Zero}
    for factor in sympy.Mul.make_args(sympy.powsimp(expanded, force=True)):
        base, exponent = factor.as_base_exp()
        if not base.has(var):
            constant *= factor
            continue
        scale, linear = sympy.factor(base).as_independent(var, as_Add=False)
        line = sympy.Poly(linear, var)
        assert line.degree() == 1, factor
        intercept, slope = line.coeff_monomial(1), line.coeff_monomial(var)
        if intercept == 0:
            assert (scale * slope).is_positive, factor
            constant *= (scale * slope) ** exponent
            exponents["var"] += exponent
            continue
        assert sympy.simplify(scale * intercept).is_positive, factor
        constant *= (scale * intercept) ** exponent
        ratio = sympy.simplify(-slope / intercept)
        if ratio == 1:
            exponents["one_minus"] += exponent
        else:
            exponents["w"], exponents["one_minus_w"] = ratio, exponent
    return sympy.simplify(constant), exponents


def power_profile() -> sympy.Expr:
    """The gap profile h(x) = A |x|^n, the starting point of the law."""
    return A * sympy.Abs(x) ** n


@functools.cache
def beta_integral() -> tuple[sympy.Expr, dict[str, sympy.Expr]]:
    """int_0^a x h'(x) / sqrt(a^2 - x^2) dx in t = x^2/a^2: the constant and exponents."""
    xp = sympy.Symbol("x", positive=True)
    integrand = xp * sympy.diff(power_profile().subs(x, xp), xp) / sympy.sqrt(a**2 - xp**2)
    in_t = integrand.subs(xp, a * sympy.sqrt(t)) * sympy.diff(a * sympy.sqrt(t), t)
    return euler_form(in_t, t)


@functools.cache
def power_load() -> sympy.Expr:
    """P(a) = E* int_0^a x h'/sqrt(a^2 - x^2) dx (the even integrand, twice half of (E*/2))."""
    constant, exponents = beta_integral()
    p, q = exponents["var"] + 1, exponents["one_minus"] + 1
    beta = sympy.gamma(p) * sympy.gamma(q) / sympy.gamma(p + q)  # Euler's Beta integral
    return sympy.gammasimp(E_star * constant * beta)


@functools.cache
def shape_factor() -> sympy.Expr:
    """K(n) = P / (E* A a^n)."""
    return sympy.gammasimp(power_load() / (E_star * A * a**n))


def with_shape_factor(expr: sympy.Expr) -> sympy.Expr:
    """Replace K(n) by the kernel argument K (NumPy has no Gamma function)."""
    return sympy.simplify(expr.subs(shape_factor(), K))


@functools.cache
def power_half_width() -> sympy.Expr:
    """a(P), the positive root of K E* A a^n = P."""
    (root,) = sympy.solve(sympy.Eq(with_shape_factor(power_load()), P), a)
    return root


@functools.cache
def power_multiplier() -> sympy.Expr:
    """(19) with dP/da of the law, in terms of P."""
    slope = sympy.diff(with_shape_factor(power_load()), a)
    return sympy.simplify(normal_multiplier().subs(dP_da, slope).subs(a, power_half_width()))


@functools.cache
def power_growth() -> sympy.Expr:
    """a(P1 + dP) - a(P1) = a1 ((1 + dP/P1)^(1/n) - 1) = a1 expm1(log1p(dP/P1)/n)."""
    a1 = power_half_width().subs(P, P1)
    ratio = sympy.powsimp(power_half_width().subs(P, P1 + dP) / a1, force=True)
    exponent = sympy.expand_log(sympy.log(ratio), force=True)  # log(1 + dP/P1)/n, as logs
    per_n = sympy.simplify(exponent * n)
    assert sympy.simplify(per_n - sympy.log(1 + dP / P1)) == 0, per_n
    return a1 * expm1(log1p(dP / P1) / n)


@functools.cache
def pressure_integral() -> tuple[sympy.Expr, dict[str, sympy.Expr]]:
    """int_X^a s^(n-1) ds / sqrt(s^2 - X^2) in s^2 = a^2 (1 - z tau), X^2 = a^2 (1 - z)."""
    integrand = s ** (n - 1) / sympy.sqrt(s**2 - X**2)
    s_of_tau = a * sympy.sqrt(1 - z * tau)  # tau = 0 at s = a, tau = 1 at s = X
    in_tau = (integrand.subs(s, s_of_tau) * -sympy.diff(s_of_tau, tau)).subs(
        X, a * sympy.sqrt(1 - z)
    )
    return euler_form(in_tau, tau)


@functools.cache
def power_pressure_hypergeometric() -> sympy.Expr:
    """p(X) with the 2F1 of Euler's integral, in terms of a and z = 1 - X^2/a^2."""
    constant, exponents = pressure_integral()
    b = exponents["var"] + 1
    c_ = exponents["one_minus"] + b + 1
    assert exponents["w"] == z
    alpha = -exponents["one_minus_w"]
    euler_beta = sympy.gamma(b) * sympy.gamma(c_ - b) / sympy.gamma(c_)
    integral = constant * euler_beta * sympy.hyper([alpha, b], [c_], z)
    slope = sympy.diff(with_shape_factor(power_load()), a).subs(a, s)
    assert sympy.simplify(slope / s ** (n - 1)).free_symbols.isdisjoint({s})
    return sympy.simplify(slope / s ** (n - 1)) * integral / sympy.pi


def _edge(a_: sympy.Expr, x_: sympy.Expr) -> sympy.Expr:
    """sqrt(a^2 - x^2) from the product (a - |x|)(a + |x|), clamped to 0 outside."""
    return sympy.sqrt(sympy.Max(0, (a_ - sympy.Abs(x_)) * (a_ + sympy.Abs(x_))))


@functools.cache
def power_pressure() -> sympy.Expr:
    """The emitted kernel: the 2F1 value passed in, sqrt(a^2 - x^2) clamped to 0 outside."""
    derived = power_pressure_hypergeometric()
    (hyper,) = derived.atoms(sympy.hyper)
    edge = sympy.Symbol("S", positive=True)
    in_edge = derived.subs(hyper, F).subs(z, edge**2 / a**2)  # sqrt(z) = S/a
    assert not in_edge.has(z)
    return sympy.powsimp(in_edge, force=True).subs(edge, _edge(a, x))


@functools.cache
def hypergeometric_argument() -> sympy.Expr:
    """z = 1 - x^2/a^2 as (a - |x|)(a + |x|)/a^2, clamped to 0 outside the contact."""
    (hyper,) = power_pressure_hypergeometric().atoms(sympy.hyper)
    assert hyper.argument == z
    return sympy.Max(0, (a - sympy.Abs(x)) * (a + sympy.Abs(x))) / a**2


@functools.cache
def wedge_pressure_elementary() -> sympy.Expr:
    """n = 1: 2F1(1/2, 1; 3/2; z) = atanh(sqrt z)/sqrt z, so p = (E* A/pi) atanh(sqrt(z))."""
    return sympy.hyperexpand(power_pressure_hypergeometric().subs(n, 1)).subs(K, 1)


@functools.cache
def wedge_pressure() -> sympy.Expr:
    """atanh(S/a) = ln((a + S)/|x|) = log1p((a - |x| + S)/|x|): no cancellation at either end.

    (a + S)(a - S) = x^2 turns the atanh's ratio (a + S)/(a - S) into ((a + S)/|x|)^2; the
    log1p argument is a sum of non-negative terms, 0 at |x| = a and growing as x -> 0, where
    the pressure has its logarithmic singularity.
    """
    elementary = wedge_pressure_elementary()
    (atanh,) = elementary.atoms(sympy.atanh)
    outside = sympy.Max(0, a - sympy.Abs(x))
    return elementary.subs(atanh, log1p((outside + _edge(a, x)) / sympy.Abs(x)))


def _mp(expr: sympy.Expr, *symbols: sympy.Symbol):
    """An mpmath function of ``symbols`` that accepts numbers or decimal strings."""
    function = sympy.lambdify(symbols, expr, modules=["mpmath", {"hyper": _hyper}])
    return lambda *values: function(*map(mpmath.mpf, values))


def _hyper(upper, lower, argument):
    return mpmath.hyper(list(upper), list(lower), argument)


def _load_by_quadrature(n_value, a_value):
    """P/(E* A) = (1/2) int_{-a}^{a} x h'(x)/sqrt(a^2 - x^2) dx for h = |x|^n, by mpmath."""
    n_value, a_value = mpmath.mpf(n_value), mpmath.mpf(a_value)
    return mpmath.quad(
        lambda t: 0 if t >= a_value else n_value * t**n_value / mpmath.sqrt(a_value**2 - t**2),
        [0, a_value],
    )


def _pressure_by_superposition(n_value, a_value, x_value):
    """p/(E* A) = (1/pi) int_|x|^a P'(s) ds/sqrt(s^2 - x^2), P' = n K s^(n-1), by mpmath.

    K(n) is the derived shape factor (itself checked against quadrature in "PL-law").
    """
    n_value, a_value, x_value = map(mpmath.mpf, (n_value, a_value, x_value))
    K_value = mpmath.sqrt(mpmath.pi) * mpmath.gamma((n_value + 1) / 2) / mpmath.gamma(n_value / 2)
    return (
        mpmath.quad(
            # A node rounded onto the integrable endpoint singularity contributes nothing.
            lambda t: 0
            if t <= abs(x_value)
            else n_value * K_value * t ** (n_value - 1) / mpmath.sqrt(t**2 - x_value**2),
            [abs(x_value), a_value],
        )
        / mpmath.pi
    )


def derive() -> Derivation:  # noqa: C901 - one block per established result
    d = Derivation(__file__)
    d.describe_module(
        "power_law",
        "Power-law punch h = A |x|^n, n >= 1 (n = 1 the wedge, n = 2 the cylinder), beyond the "
        "paper: contact law, edge multiplier of (19), growth of the contact and pressure.",
    )
    load = power_load()
    with d.equation("PL-law", "Contact law of the power-law punch") as eq:
        eq.beyond_paper(
            "P = E* n A int_0^a x^n/sqrt(a^2 - x^2) dx, with x = a sqrt(t) Euler's Beta "
            "integral: P = K(n) E* A a^n, K(n) = sqrt(pi) Gamma((n + 1)/2)/Gamma(n/2)",
            derived=load,
        )
        eq.holds(
            shape_factor()
            - n * sympy.sqrt(sympy.pi) / 2 * sympy.gamma((n + 1) / 2) / sympy.gamma(n / 2 + 1),
            how="equivalently K(n) = (n sqrt(pi)/2) Gamma((n + 1)/2)/Gamma(n/2 + 1)",
        )
        eq.holds(
            load.subs(n, 1) - load_from_profile(A * sympy.Abs(x)),
            how="n = 1 (wedge): equals the plane-contact integral of A |x| done by SymPy",
        )
        eq.holds(
            load.subs({n: 2, A: 1 / (2 * R)}) - hertz_load(),
            how="n = 2, A = 1/(2R): the Hertz law P(a) of contact_law_hertz",
        )
        load_mp = _mp(load.subs(UNIT), n, a)
        eq.matches_numerically(
            lambda n_value, a_value: load_mp(n_value, a_value),
            _load_by_quadrature,
            [{"n_value": n_, "a_value": "1.7"} for n_ in ("2.5", "3")],
            how="mpmath quadrature of the plane-contact relation (n = 2.5, 3)",
            digits=15,
            symbolic=True,
        )
    half_width = power_half_width()
    with d.equation("PL-29", "Power-law half-width a(P)") as eq:
        eq.beyond_paper("the power law inverted (not in the paper)", derived=half_width)
        eq.holds(
            with_shape_factor(load).subs(a, half_width) - P,
            how="a = (P/(K E* A))^(1/n) solves K E* A a^n = P",
            derived=half_width,
        )
        eq.matches_paper(
            half_width.subs({n: 2, A: 1 / (2 * R), K: shape_factor().subs(n, 2)}) ** 2,
            4 * P * R / (sympy.pi * E_star),
            how="n = 2, A = 1/(2R) reproduces (29)",
            printed=r"a^2=\frac{4PR}{\pi E^*}",
        )
    multiplier = power_multiplier()
    with d.equation("PL-19", "Normal edge multiplier of the power-law punch from (19)") as eq:
        eq.beyond_paper("(19) applied to the power law (not in the paper)", derived=multiplier)
        eq.holds(
            multiplier - sympy.sqrt(2) * n * P / (sympy.pi * half_width ** sympy.Rational(3, 2)),
            how="(19) with dP/da = n P/a: L_I = sqrt(2) n P/(pi a^(3/2))",
            derived=multiplier,
        )
        hertz = {n: 2, A: 1 / (2 * R), K: shape_factor().subs(n, 2)}
        eq.holds(
            multiplier.subs(hertz) - E_star / R * sympy.sqrt(half_width.subs(hertz) / 2),
            how="n = 2, A = 1/(2R) gives (31)",
        )
    multiplier_slope = sympy.simplify(sympy.diff(multiplier, P))
    with d.equation("PL-26", "Slope dL_I/dP of the power-law multiplier") as eq:
        eq.beyond_paper("d/dP of the power-law L_I (not in the paper)", derived=multiplier_slope)
        eq.holds(
            multiplier_slope - (1 - sympy.Rational(3, 2) / n) * multiplier / P,
            how="L_I ~ P^(1 - 3/(2n)): dL_I/dP = (1 - 3/(2n)) L_I/P, negative for n < 3/2",
            derived=multiplier_slope,
        )
    growth = power_growth()
    with d.equation("PL-growth", "Growth a(P1 + dP) - a(P1) without cancellation") as eq:
        eq.beyond_paper(
            "the power-law growth, rewritten with expm1/log1p (not in the paper)",
            derived=growth,
        )
        eq.holds(
            growth.rewrite(sympy.exp).rewrite(sympy.log)
            - (half_width.subs(P, P1 + dP) - half_width.subs(P, P1)),
            how="a1 expm1(log1p(dP/P1)/n) = a(P1 + dP) - a(P1): a2/a1 = (1 + dP/P1)^(1/n)",
            derived=growth,
        )
    pressure = power_pressure_hypergeometric()
    with d.equation("PL-p", "Pressure under the power-law punch") as eq:
        eq.beyond_paper(
            "Mossakovskii's superposition; s^2 = a^2 (1 - z tau) makes it Euler's integral "
            "B(b, c - b) 2F1(alpha, b; c; z) with alpha = 1 - n/2, b = 1, c = 3/2",
            derived=pressure,
        )
        pressure_mp = _mp(pressure.subs(K, shape_factor()).subs(UNIT), n, a, z)

        def closed(n_value, a_value, x_value):
            n_value, a_value, x_value = map(mpmath.mpf, (n_value, a_value, x_value))
            return pressure_mp(n_value, a_value, 1 - x_value**2 / a_value**2)

        eq.matches_numerically(
            closed,
            _pressure_by_superposition,
            [
                {"n_value": n_, "a_value": "1.3", "x_value": x_}
                for n_, x_ in [("1.5", "0.2"), ("7", "-1.2")]
            ],
            how="mpmath quadrature of the superposition integral (n = 1.5, 7)",
            digits=15,
            symbolic=True,
        )
        eq.matches_numerically(
            lambda n_value, a_value: 2
            * mpmath.quad(lambda t: closed(n_value, a_value, t), [0, a_value]),
            lambda n_value, a_value: load_mp(n_value, a_value),
            [{"n_value": "2.5", "a_value": "1.3"}],
            how="int_{-a}^{a} p dx = P(a) (n = 2.5)",
            digits=15,
            symbolic=True,
        )
        cylinder = {n: 2, A: 1 / (2 * R), K: shape_factor().subs(n, 2)}
        at_two = sympy.hyperexpand(pressure.subs(cylinder))
        hertz_P = hertz_load()
        eq.matches_paper(
            at_two.subs(z, (a**2 - X**2) / a**2),
            2 * hertz_P / (sympy.pi * a**2) * sympy.sqrt(a**2 - X**2),
            how="n = 2, A = 1/(2R): 2F1(0, 1; 3/2; z) = 1 and p is the Hertz pressure (48)",
            printed=r"p(x,P)=\frac{2P}{\pi a^2}\sqrt{a^2-x^2}",
        )
        eq.holds(
            wedge_pressure_elementary() - E_star * A / sympy.pi * sympy.atanh(sympy.sqrt(z)),
            how="n = 1 (wedge): 2F1(1/2, 1; 3/2; z) = atanh(sqrt z)/sqrt z, so "
            "p = (E* A/pi) atanh(sqrt(1 - x^2/a^2)) = (E* A/pi) arccosh(a/|x|)",
        )
        wedge_mp = _mp(wedge_pressure().subs(UNIT), a, x)
        eq.matches_numerically(
            lambda a_value, x_value: wedge_mp(a_value, x_value),
            lambda a_value, x_value: _pressure_by_superposition(1, a_value, x_value),
            [{"a_value": "1.3", "x_value": "-0.4"}],
            how="the emitted wedge form log1p((a - |x| + S)/|x|) against the superposition "
            "integral at n = 1",
            digits=15,
            symbolic=True,
        )
        multiplier_mp = _mp(multiplier.subs(P, load).subs(K, shape_factor()).subs(UNIT), n, a)
        gap = mpmath.mpf(10) ** -25
        eq.matches_numerically(
            lambda n_value, a_value: closed(n_value, a_value, mpmath.mpf(a_value) * (1 - gap))
            / mpmath.sqrt(mpmath.mpf(a_value) * gap),
            lambda n_value, a_value: multiplier_mp(n_value, a_value),
            [{"n_value": "2.5", "a_value": "1.3"}],
            how="p/sqrt(a - x) -> L_I of (19) at the edge, as in (4) (a - x = 1e-25 a)",
            digits=20,
            symbolic=True,
        )

    def emit(name, args, expr, equations, summary, doc, returns):
        assert not expr.has(sympy.gamma), name  # K stands for the Gamma ratio
        d.emit(
            name=name,
            args=args,
            expr=expr,
            equations=equations,
            summary=summary,
            doc=doc,
            module="power_law",
            returns=returns,
        )

    emit(
        "power_law_profile",
        (POSITION, EXPONENT, COEFFICIENT),
        power_profile(),
        ("29",),
        "Gap profile h(x) = A |x|^n of the power-law punch.",
        "The starting point of the power law (its slope n A x^(n-1), x > 0, is what the "
        "plane-contact relation integrates); the reference solver's normal problem starts "
        "from it.",
        "h [length].",
    )
    emit(
        "power_law_load",
        (HALF_WIDTH, *PARAMETERS),
        with_shape_factor(load),
        ("29",),
        "Normal load P(a) = K E* A a^n of the power-law punch h = A |x|^n.",
        "The counterpart of (29), from the plane-contact relation and Euler's Beta integral.",
        "P [force/length].",
    )
    emit(
        "power_law_load_slope",
        (HALF_WIDTH, *PARAMETERS),
        sympy.diff(with_shape_factor(load), a),
        ("29",),
        "Slope dP/da = n K E* A a^(n-1) of the power law.",
        "Positive: the law is increasing.",
        "dP/da [force/length^2].",
    )
    emit(
        "power_law_half_width",
        (LOAD, *PARAMETERS),
        half_width,
        ("29",),
        "Contact half-width a(P) = (P/(K E* A))^(1/n) of the power-law punch.",
        "The inverse of the law, in closed form.",
        "a [length].",
    )
    emit(
        "power_law_half_width_growth",
        (LOAD1, LOAD_CHANGE, *PARAMETERS),
        growth,
        ("23", "42"),
        "Growth a(P1 + dP) - a(P1) of the power-law contact, without cancellation.",
        "a1 expm1(log1p(dP/P1)/n) from a2/a1 = (1 + dP/P1)^(1/n): keeps full relative "
        "precision for any dP/P1 > 0, down to dP/P1 of 1e-300.",
        "a2 - a1 [length].",
    )
    emit(
        "power_law_normal_edge_multiplier",
        (LOAD, *PARAMETERS),
        multiplier,
        ("19",),
        "Normal edge multiplier L_I = sqrt(2) n P/(pi a^(3/2)) of the power law at load P.",
        "(19) with dP/da = n P/a.",
        "L_I [force/length^(5/2)].",
    )
    emit(
        "power_law_normal_edge_multiplier_slope",
        (LOAD, *PARAMETERS),
        multiplier_slope,
        ("26",),
        "Slope dL_I/dP = (1 - 3/(2n)) L_I/P of the power-law edge multiplier.",
        "Negative for n < 3/2 (the wedge's L_I falls as the load grows), zero at n = 3/2.",
        "dL_I/dP [1/length^(3/2)].",
    )
    emit(
        "power_law_hypergeometric_argument",
        (POSITION, HALF_WIDTH),
        hypergeometric_argument(),
        ("48",),
        "Argument z = 1 - x^2/a^2 of the hypergeometric factor of the power-law pressure.",
        "Formed as (a - |x|)(a + |x|)/a^2, without cancellation near the edges, and clamped "
        "to 0 outside the contact.",
        "z in [0, 1].",
    )
    emit(
        "power_law_pressure",
        (
            POSITION,
            HALF_WIDTH,
            *PARAMETERS,
            Argument(
                F,
                "The value 2F1(1 - n/2, 1; 3/2; z) at z from "
                "power_law_hypergeometric_argument (1 for n = 2; scipy.special.hyp2f1).",
            ),
        ),
        power_pressure(),
        ("4", "48"),
        "Contact pressure under the power-law punch, given its hypergeometric factor.",
        "(n K E* A/pi) a^(n-2) sqrt(a^2 - x^2) 2F1(1 - n/2, 1; 3/2; 1 - x^2/a^2), from "
        "Mossakovskii's superposition; the counterpart of (48) (n = 2), with the edge "
        "asymptote (4).  0 outside the contact.",
        "p [force/length^2].",
    )
    emit(
        "wedge_pressure",
        (POSITION, HALF_WIDTH, COEFFICIENT, MODULUS),
        wedge_pressure(),
        ("4", "48"),
        "Contact pressure (E* A/pi) arccosh(a/|x|) under a wedge (power law with n = 1).",
        "Written (E* A/pi) log1p((a - |x| + sqrt(a^2 - x^2))/|x|): sums of non-negative terms, "
        "accurate near the edges and the apex, 0 outside the contact.  The apex x = 0 is a "
        "logarithmic singularity: it divides by zero there (the law class returns +inf).",
        "p [force/length^2].",
    )
    return d
