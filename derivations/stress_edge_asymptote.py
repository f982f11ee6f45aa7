"""The stress amplitude near a contact edge from the paper's edge asymptotes (issue 18).

Conventions: those of ``stress_half_plane`` (depth y >= 0 into the lower body, tractions
exerted by the indenter, tension positive).  Near the right-hand edge the amplitude of the
cycle (state 2 minus state 1) is carried by square-root loads: the pressure change (4),
L_I2 sqrt(a2 - x) - L_I1 sqrt(a1 - x), and the shear change (49).  A square-root load on a
half-line has no finite Flamant integral -- its potential diverges at infinity -- so the edge
field is built from the potential of the edge eigenfunction instead:

EA-1  The load (c - t)^lam on t < c: the derivative of its potential converges, F'(w) =
      -int_0^inf s^lam / (w + s)^2 ds = -pi lam w^(lam - 1) / sin(pi lam) (w = zeta - c), so
      F(w) = -pi w^lam / sin(pi lam) + C.  The constant is real (the divergent part of the
      integral), and by HP-3 a real constant in Q is a uniform sxx, in P nothing: the edge
      field is the eigenfield below plus a uniform sxx to be fixed.  On the surface below the
      load Re F = -pi cot(pi lam) |w|^lam = 0 for half-integer lam: the regularised Hilbert
      transform of the load vanishes there, and Im F = pi (c - x)^lam is the load (HP-3).
EA-2  The eigenfields: HP-3 applied to F, in the polar form (rho, phi) of w, phi in [-pi, 0],
      with y w^(lam - 1) = rho^lam sin(-phi) e^(i (lam - 1) phi): finite at the edge for
      lam > 0.
EA-3  The uniform sxx: in a zone that sticks through the cycle the two bodies strain alike
      (the lower body carries q, the tension sigma; the indenter -q), so the shear part of the
      surface sxx there is -dsigma/2 (plane-strain Hooke's law, equal syy = -p); the
      regularised eigenfields give 0 there (EA-1), so the amplitude carries a uniform
      dsigma/2 -- the bulk change dsigma less half of it.
EA-4  The amplitudes: (49) with b from (17) is mu L_I2 sqrt(a2 - x) + mu L_I1 sqrt(a1 - x)_+ -
      K sqrt(b - x)_+, K = mu (L_I1 + L_I2) + L_II1 - L_II2: three square-root loads (the
      1/sqrt(a2 - x) term of section3_tractions vanishes at b17).
EA-5  Checked against the exact amplitude field of a Hertz cycle without tension (Jaeger-
      Ciavarella (47), a sum of semi-elliptic loads, HP-6): the difference falls like r/a
      relative to the field (r the distance from the edge).
EA-6  The next terms of the edge expansions, for the stated accuracy: p = L_I s^(1/2) (1 +
      k_p s + ...) and the full-stick shear q = L_II s^(1/2) (1 + k_q s + ...), s = a - x,
      from Mossakovskii's superposition (section2_calibrations) on a generic law.
EA-7  The near-edge error map: the committed ``generated/report/stress_error_map.csv``
      (``asymslip.stress.error_map``, ``make stress-error-map``) summarised -- the asymptote
      against the solver and the exact field over four laws, three contact growths, five
      load paths, both edges and six distances from the edge.
"""

from __future__ import annotations

import csv
import functools
import io
from pathlib import Path

import mpmath
import sympy

from asymslip.codegen import Argument, Derivation

from ._glossary import L_I, L_I1, L_I2, L_II1, L_II2, a, a1, a2, arguments, b, eta, lam, mu
from .section2_calibrations import _edge_expansion, load_slope
from .section2_consistency import stick_boundary
from .section3_tractions import distance, inner_root, stick_root, traction_difference_placeholders
from .solver_influence import _hooke
from .stress_half_plane import (
    COMPONENTS,
    Pi,
    Qi,
    Qr,
    dPi,
    dPr,
    dQi,
    dQr,
    potential_map,
    semi_ellipse_fields,
    y,
)

X = sympy.Symbol("X", real=True)  # x - c: the point from the load's edge, outward
exponent = sympy.Symbol("lam_e", real=True)  # the load's power (c - t)^lam
s, w_pos = sympy.symbols("s w", positive=True)
dsigma = sympy.Symbol("dsigma", real=True)
dL_I_da = sympy.Symbol("dL_I_da", real=True)

POWER = Argument(
    exponent,
    "Power lam of the load (c - t)^lam on t < c: 1/2 (the edge asymptotes (4), (5)), 3/2 "
    "(their next terms), -1/2 (a moved boundary); not an integer.",
)


# --- EA-1: the regularised potential -------------------------------------------------------------
@functools.cache
def potential_slope_half() -> sympy.Expr:
    """F'(w) for lam = 1/2 by SymPy: -int_0^inf sqrt(s)/(w + s)^2 ds, w > 0."""
    return -sympy.integrate(sympy.sqrt(s) / (w_pos + s) ** 2, (s, 0, sympy.oo))


def regularised_potential(power: sympy.Expr, w: sympy.Expr) -> sympy.Expr:
    """F(w) = -pi w^lam / sin(pi lam): the potential of (c - t)^lam up to a real constant."""
    return -sympy.pi * w**power / sympy.sin(sympy.pi * power)


def _mp_potential_slope(power: str, wv: str) -> mpmath.mpc:
    """-int_0^inf s^lam/(w + s)^2 ds (lam < 1), or for 1 <= lam < 2 the antiderivative of
    2 int s^lam/(w + s)^3 ds, by quadrature at a complex w below the surface."""
    lam_, w = mpmath.mpf(power), mpmath.mpmathify(wv)
    return -mpmath.quad(lambda sv: sv**lam_ / (w + sv) ** 2, _breaks(w))


def _breaks(w: mpmath.mpc) -> list[mpmath.mpf]:
    """Quadrature breaks on (0, inf), with the near-pole s = -Re w when it lies there."""
    near = -w.real
    return [0, near, 2 * near, mpmath.inf] if near > 0 else [0, 1, mpmath.inf]


def _mp_potential_curvature(power: str, wv: str) -> mpmath.mpc:
    lam_, w = mpmath.mpf(power), mpmath.mpmathify(wv)
    return 2 * mpmath.quad(lambda sv: sv**lam_ / (w + sv) ** 3, _breaks(w))


# --- EA-2: the eigenfields in polar form ----------------------------------------------------
# The polar parts of w = X - i y = rho e^(i phi), phi in [-pi, 0], that the fields need.
power_part, cos_part, sin_part = sympy.symbols("rho_lam cos_lam sin_lam", real=True)
angle_sine, cos_slope, sin_slope = sympy.symbols("sin_angle cos_lam1 sin_lam1", real=True)
PARTS = (
    Argument(power_part, "rho^lam, rho = |x - c - i y| the distance from the load's edge."),
    Argument(cos_part, "cos(lam phi), phi = atan2(-y, x - c) in [-pi, 0]."),
    Argument(sin_part, "sin(lam phi)."),
    Argument(angle_sine, "sin(-phi) = y / rho, in [0, 1] (0 at the edge itself)."),
    Argument(cos_slope, "cos((lam - 1) phi)."),
    Argument(sin_slope, "sin((lam - 1) phi)."),
)


def polar_parts() -> dict[sympy.Symbol, sympy.Expr]:
    """The polar parts as functions of (X, y, lam)."""
    distance = sympy.sqrt(X**2 + y**2)
    angle = sympy.atan2(-y, X)
    return {
        power_part: distance**exponent,
        cos_part: sympy.cos(exponent * angle),
        sin_part: sympy.sin(exponent * angle),
        angle_sine: y / distance,
        cos_slope: sympy.cos((exponent - 1) * angle),
        sin_slope: sympy.sin((exponent - 1) * angle),
    }


@functools.cache
def eigenfields() -> dict[tuple[str, str], sympy.Expr]:
    """(component, load) -> the field of the load (c - t)^lam as pressure (P = F) or shear
    (Q = F), in the polar parts of w = X - i y: linear in them, so that one set of parts per
    point and load serves every component.

    F = -pi rho^lam e^(i lam phi) / sin(pi lam) and y F' = -pi lam rho^lam sin(-phi)
    e^(i (lam - 1) phi) / sin(pi lam), with y = rho sin(-phi): no division by rho, finite at
    the edge for lam > 0.
    """
    sine = sympy.sin(sympy.pi * exponent)
    F = -sympy.pi * power_part * (cos_part + sympy.I * sin_part) / sine
    yF = -sympy.pi * exponent * power_part * angle_sine * (cos_slope + sympy.I * sin_slope) / sine
    F, yF = sympy.expand_complex(F), sympy.expand_complex(yF)
    mapping = potential_map()
    fields = {}
    for load in ("p", "q"):
        if load == "p":
            values = {Qr: 0, Qi: 0, Pi: sympy.im(F), dQr: 0, dQi: 0}
            values |= {dPr: sympy.re(yF) / y, dPi: sympy.im(yF) / y}
        else:
            values = {Qr: sympy.re(F), Qi: sympy.im(F), Pi: 0, dPr: 0, dPi: 0}
            values |= {dQr: sympy.re(yF) / y, dQi: sympy.im(yF) / y}
        for component in COMPONENTS:
            expr = sympy.expand(mapping[component].subs(values))
            assert not expr.has(y), "the depth did not cancel"
            fields[(component, load)] = sympy.collect(
                expr, [power_part * cos_part, power_part * sin_part]
            )
    return fields


def _mp_eigenfield(component: str, load: str, xv: str, yv: str, power: str) -> mpmath.mpf:
    """The field from HP-3 and the potential of EA-1 in mpmath's complex power (an
    independent evaluation of the polar form)."""
    lam_ = mpmath.mpf(power)
    w = mpmath.mpc(mpmath.mpf(xv), -mpmath.mpf(yv))
    F = -mpmath.pi * w**lam_ / mpmath.sin(mpmath.pi * lam_)
    dF = -mpmath.pi * lam_ * w ** (lam_ - 1) / mpmath.sin(mpmath.pi * lam_)
    zero = mpmath.mpf(0)
    if load == "p":
        values = (zero, zero, F.imag, zero, zero, dF.real, dF.imag)
    else:
        values = (F.real, F.imag, zero, dF.real, dF.imag, zero, zero)
    expression = potential_map()[component]
    function = sympy.lambdify((Qr, Qi, Pi, dQr, dQi, dPr, dPi, y), expression, "mpmath")
    return function(*values, mpmath.mpf(yv))


# --- EA-3: the uniform term ----------------------------------------------------------------------
@functools.cache
def stick_zone_shear_stress() -> sympy.Expr:
    """The shear part S of the lower body's surface sxx where the bodies stick (bonded).

    Lower body: sxx = -p + S + sigma, syy = -p; the indenter (traction -q, no tension,
    reflected): sxx = -p - S, syy = -p.  Equal eps_xx (plane strain) fixes S.
    """
    S, p = sympy.symbols("S p", real=True)
    lower = _hooke(-p + S + dsigma, -p, 0)[0]
    upper = _hooke(-p - S, -p, 0)[0]
    (solution,) = sympy.solve(sympy.Eq(lower, upper), S)
    return solution


@functools.cache
def uniform_amplitude() -> sympy.Expr:
    """The amplitude's uniform sxx: dsigma plus the stick zone's shear part (the regularised
    eigenfields contribute nothing to the surface sxx there)."""
    return dsigma + stick_zone_shear_stress()


# --- EA-4: the amplitudes of the square-root loads ------------------------------------------
@functools.cache
def shear_amplitudes() -> dict[str, sympy.Expr]:
    """Coefficients of sqrt(a2 - x), sqrt(a1 - x)_+ and sqrt(b - x)_+ in (49), and of the
    edge term 1/sqrt(a2 - x) at b from (17) (zero)."""
    expression = sympy.expand(traction_difference_placeholders())
    amplitudes = {
        "a2": expression.coeff(sympy.sqrt(distance)),
        "a1": expression.coeff(inner_root),
        "b": expression.coeff(stick_root),
        "edge": expression.coeff(1 / sympy.sqrt(distance)),
    }
    rest = expression - sum(
        amplitudes[key] * shape
        for key, shape in (
            ("a2", sympy.sqrt(distance)),
            ("a1", inner_root),
            ("b", stick_root),
            ("edge", 1 / sympy.sqrt(distance)),
        )
    )
    assert sympy.expand(rest) == 0, "(49) has other shape functions"
    return {key: sympy.factor(value) for key, value in amplitudes.items()}


# --- EA-6: the next terms of the edge expansions --------------------------------------------
@functools.cache
def next_term_ratios() -> tuple[sympy.Expr, sympy.Expr]:
    """(k_p, k_q): the next term's coefficient over the leading one, p and the full-stick q.

    Mossakovskii's superposition on a generic law P(a) (section2_calibrations): p from
    increments P'(c)/pi, q on the proportional path from lam P'(c)/pi + eta P'(c) x/4.  The
    law enters through P'(a) and P''(a), written with L_I (19) and its slope dL_I/da.
    """
    leading_p, next_p = _edge_expansion(lambda c_, x_: load_slope(c_) / sympy.pi)
    leading_q, next_q = _edge_expansion(
        lambda c_, x_: lam * load_slope(c_) / sympy.pi + eta * load_slope(c_) * x_ / 4
    )
    slope, curvature = sympy.symbols("P1_ P2_", positive=True)
    ratios = []
    for leading, following in ((leading_p, next_p), (leading_q, next_q)):
        ratio = (following / leading).doit()
        derivatives = ratio.atoms(sympy.Derivative, sympy.Subs)
        ratio = ratio.subs({term: curvature for term in derivatives})
        ratio = ratio.subs(load_slope(a), slope)
        assert not ratio.has(load_slope), f"the law is left in {ratio}"
        ratios.append(sympy.simplify(ratio))
    # dL_I/da = d/da [(1/pi) sqrt(2/a) P'(a)] = L_I (P''/P' - 1/(2a))
    curvature_of = sympy.solve(
        sympy.Eq(dL_I_da, L_I * (curvature / slope - 1 / (2 * a))), curvature
    )[0]
    return tuple(sympy.simplify(r.subs(curvature, curvature_of)) for r in ratios)


ERROR_MAP = Path(__file__).resolve().parents[1] / "generated" / "report" / "stress_error_map.csv"


def error_map_summary(text: str) -> list[str]:
    """The report's lines on the committed near-edge error map (its CSV text)."""
    body = "\n".join(line for line in text.splitlines() if line and not line.startswith("#"))
    rows = list(csv.DictReader(io.StringIO(body)))
    if not rows:
        return ["the committed near-edge error map is empty: run `make stress-error-map`"]
    quiet = [r for r in rows if r["near_edge"] == "1" and r["warned"] == "0"]
    loud = [r for r in rows if r not in quiet]
    near = [r for r in rows if r["near_edge"] == "1"]
    dominated = [r for r in near if abs(float(r["tau"])) > abs(float(r["lam_mu"]))]
    driven = [r for r in near if r not in dominated]

    def worst(chosen: list[dict[str, str]], column: str) -> str:
        values = [float(r[column]) for r in chosen]
        return f"{max(values):.3g}" if values else "-"

    laws = ", ".join(dict.fromkeys(r["law"] for r in rows))
    cycles = len({(r["law"], r["a2_a1"], r["lam_mu"], r["tau"]) for r in rows})
    lines = [
        f"{len(rows)} rows: {cycles} cycles ({laws}), both edges, r/a1 = "
        + ", ".join(dict.fromkeys(r["r_a1"] for r in rows))
        + f"; {sum(int(r['excluded']) for r in rows)} of {sum(int(r['points']) for r in rows)} "
        "points left out of the solver rows (the solver's unresolved surface next to a1, a2, b)",
        "largest error / stated accuracy without a warning (near_edge, no validity warning): "
        f"{worst([r for r in quiet if r['reference'] == 'solver'], 'error_over_stated')} against "
        f"the solver ({sum(r['reference'] == 'solver' for r in quiet)} rows), "
        f"{worst([r for r in quiet if r['reference'] == 'exact'], 'error_over_stated')} against "
        f"the exact Hertz field ({sum(r['reference'] == 'exact' for r in quiet)} rows); with a "
        f"warning: {worst(loud, 'error_over_stated')} ({len(loud)} rows)",
        "near the edge (near_edge) where the shear force drives the slip at least as much as "
        f"the tension: {worst(driven, 'error_over_stated')} ({len(driven)} rows); where the "
        "tension dominates (pi eta a1/(4 mu) > |lam/mu|, warned by edge_amplitude): "
        f"{worst(dominated, 'error_over_stated')} ({len(dominated)} rows)",
    ]
    for reference in ("solver", "exact"):
        chosen = [r for r in rows if r["reference"] == reference]
        if not chosen:
            continue
        by_distance = []
        for radius in dict.fromkeys(r["r_a1"] for r in chosen):
            at = [r for r in chosen if r["r_a1"] == radius]
            median = sorted(float(r["error_fraction"]) for r in at)[len(at) // 2]
            by_distance.append(f"{radius}: {median:.3g} / {worst(at, 'error_fraction')}")
        lines.append(
            f"error / largest amplitude against the {reference}, median / worst, by r/a1 -- "
            + "; ".join(by_distance)
        )
    return lines


def derive() -> Derivation:
    d = Derivation(__file__)
    d.describe_module(
        "edge_stress",
        "The stress amplitude near a contact edge from the edge asymptotes (4) and (49): the "
        "fields of square-root loads on a half-line, whose Flamant integrals diverge, from "
        "the potential of the edge eigenfunction; the uniform term fixed by the stick zone's "
        "strain compatibility; the amplitudes of (49); and the next terms of the edge "
        "expansions, for the stated accuracy (beyond the paper; issue 18).",
    )
    with d.equation("EA-1", "Potential of a square-root load on a half-line") as eq:
        half = sympy.Rational(1, 2)
        w = sympy.Symbol("w", positive=True)
        eq.holds(
            potential_slope_half().subs(w_pos, w) - sympy.diff(regularised_potential(half, w), w),
            how="lam = 1/2: F'(w) = -int_0^inf sqrt(s)/(w + s)^2 ds (convergent, SymPy) is the "
            "derivative of -pi sqrt(w): F = -pi sqrt(w) + a real constant",
            derived=regularised_potential(half, w),
        )
        eq.matches_numerically(
            lambda power, wv: -mpmath.pi
            * mpmath.mpf(power)
            * mpmath.mpmathify(wv) ** (mpmath.mpf(power) - 1)
            / mpmath.sin(mpmath.pi * mpmath.mpf(power)),
            _mp_potential_slope,
            [
                {"power": p, "wv": wv}
                for p in ("0.5", "-0.5")
                for wv in ("0.3-0.7j", "-2-0.01j", "1.5-2j")
            ],
            how="F'(w) for lam = 1/2 and -1/2 against quadrature at complex w below the surface",
            digits=16,
            symbolic=True,
        )
        eq.matches_numerically(
            lambda power, wv: -mpmath.pi
            * mpmath.mpf(power)
            * (mpmath.mpf(power) - 1)
            * mpmath.mpmathify(wv) ** (mpmath.mpf(power) - 2)
            / mpmath.sin(mpmath.pi * mpmath.mpf(power)),
            _mp_potential_curvature,
            [{"power": "1.5", "wv": wv} for wv in ("0.3-0.7j", "-2-0.01j", "1.5-2j")],
            how="F''(w) for lam = 3/2 (F' diverges) against quadrature",
            digits=16,
            symbolic=True,
        )
        for power in (sympy.Rational(1, 2), sympy.Rational(3, 2), -sympy.Rational(1, 2)):
            cot = sympy.cos(sympy.pi * power) / sympy.sin(sympy.pi * power)
            eq.holds(
                cot,
                how=f"lam = {power}: Re F = -pi cot(pi lam) |w|^lam = 0 on the surface under the "
                "load (the regularised Hilbert transform vanishes there)",
            )
        const = sympy.Symbol("C", real=True)
        constant = {Qr: const, Qi: 0, Pi: 0, dQr: 0, dQi: 0, dPr: 0, dPi: 0}
        mapping = potential_map()
        eq.holds(
            sympy.Abs(mapping["syy"].subs(constant)) + sympy.Abs(mapping["sxy"].subs(constant)),
            how="a real constant in Q changes neither syy nor sxy (HP-3): it is a uniform sxx",
        )
    fields = eigenfields()
    with d.equation("EA-2", "Edge eigenfields of the square-root loads") as eq:
        eq.beyond_paper(
            "HP-3 applied to F = -pi w^lam / sin(pi lam), w = x - c - i y, in polar form: the "
            "field of the load (c - t)^lam as a pressure or a shear traction, finite at the "
            "edge for lam > 0",
            derived=fields[("sxx", "p")],
        )
        for component in COMPONENTS:
            for load in ("p", "q"):
                in_place = fields[(component, load)].subs(polar_parts())
                function = sympy.lambdify((X, y, exponent), in_place, "mpmath")
                eq.matches_numerically(
                    lambda xv, yv, power, f=function: f(
                        mpmath.mpf(xv), mpmath.mpf(yv), mpmath.mpf(power)
                    ),
                    lambda xv, yv, power, c=component, ld=load: _mp_eigenfield(
                        c, ld, xv, yv, power
                    ),
                    [
                        {"xv": xv, "yv": yv, "power": power}
                        for xv, yv in (("-0.3", "0.2"), ("0.7", "0.05"), ("-1.1", "0"))
                        for power in ("0.5", "1.5")
                    ],
                    how=f"{component} of the {load} load: the polar form against mpmath's "
                    "complex powers",
                    digits=16,
                    symbolic=True,
                )
        half = sympy.Rational(1, 2)
        # On the surface under the load (X = -3/4, y = 0: phi = -pi, sin(-phi) = 0).
        under = {
            power_part: sympy.sqrt(sympy.Rational(3, 4)),
            cos_part: sympy.cos(-sympy.pi * half),
            sin_part: sympy.sin(-sympy.pi * half),
            angle_sine: 0,
            cos_slope: sympy.cos(sympy.pi * half),
            sin_slope: sympy.sin(sympy.pi * half),
            exponent: half,
        }
        root = sympy.sqrt(sympy.Rational(3, 4))

        def at(key: tuple[str, str]) -> sympy.Expr:
            return fields[key].subs(under)

        eq.holds(at(("syy", "p")) + root, how="under the load syy = -(c - x)^(1/2)")
        eq.holds(at(("sxx", "p")) + root, how="under the load sxx = -(c - x)^(1/2)")
        eq.holds(at(("sxy", "q")) + root, how="under the load sxy = -(c - x)^(1/2)")
        eq.holds(at(("sxx", "q")), how="under the shear load sxx = 0 (EA-1)")
        eq.holds(at(("syy", "q")), how="under the shear load syy = 0")
    with d.equation("EA-3", "Uniform term of the amplitude from the stick zone") as eq:
        eq.holds(
            stick_zone_shear_stress() + dsigma / 2,
            how="bonded similar bodies strain alike: the shear part of the lower body's "
            "surface sxx is -dsigma/2 where it sticks (plane-strain Hooke, syy = -p in both)",
            derived=uniform_amplitude(),
        )
        eq.beyond_paper(
            "the amplitude's uniform sxx is dsigma/2: the eigenfields give no surface sxx in "
            "the stick zone (EA-1), the bulk change gives dsigma, the shear -dsigma/2",
            derived=uniform_amplitude(),
        )
    amplitudes = shear_amplitudes()
    with d.equation("EA-4", "Square-root loads of the amplitude") as eq:
        eq.holds(
            amplitudes["edge"].subs(b, stick_boundary()),
            how="(49)'s 1/sqrt(a2 - x) term vanishes for b from (17)",
        )
        eq.holds(amplitudes["a2"] - mu * L_I2, how="sqrt(a2 - x): mu L_I2 (the slip at state 2)")
        eq.holds(amplitudes["a1"] - mu * L_I1, how="sqrt(a1 - x)_+: mu L_I1 (slip at state 1)")
        eq.holds(
            amplitudes["b"] + mu * (L_I1 + L_I2) + L_II1 - L_II2,
            how="sqrt(b - x)_+: -K, K = mu (L_I1 + L_I2) + L_II1 - L_II2",
            derived=amplitudes["b"],
        )
    with d.equation("EA-5", "Edge field against the exact Hertz amplitude") as eq:
        relative, against_estimate = _hertz_check()
        eq.details.append(
            "Fig. 5 cycle (R = E* = 1, mu = 0.1, P 100 -> 105, Q 0 -> 1), on half circles of "
            "radius r = 0.001, 0.01, 0.1 a2 about the edge: |exact - asymptote| / max|amplitude| "
            + ", ".join(f"{value:.2e}" for value in relative)
            + "; over the next-order estimate "
            + ", ".join(f"{value:.2f}" for value in against_estimate)
        )
        assert max(against_estimate) < 1.5, "the next-order terms do not explain the error"
        eq.beyond_paper(
            "the asymptotic amplitude differs from the exact Jaeger-Ciavarella field (a sum of "
            "semi-elliptic loads) by about the field of the next terms k A_c (c - t)^(3/2) of "
            "its loads (EA-6): near the edge their constant part, from the stick boundary's "
            "load k K (a2 - b)^(3/2), beyond it their growth with r",
        )
    with d.equation("EA-7", "Near-edge error map of the asymptotic amplitude") as eq:
        if ERROR_MAP.is_file():
            eq.details.extend(error_map_summary(ERROR_MAP.read_text(encoding="utf-8")))
            measured = "measured"
        else:
            eq.details.append("not measured yet: run `make stress-error-map`")
            measured = "to be measured"
        eq.beyond_paper(
            f"the asymptote against the reference solver and the exact Hertz field near both "
            f"edges ({measured}: generated/report/stress_error_map.csv, drawn in "
            "generated/figures/stress_error_map.png)",
        )
    kappa_p, kappa_q = next_term_ratios()
    with d.equation("EA-6", "Next terms of the edge expansions") as eq:
        eq.beyond_paper(
            "k_p = 1/(12 a) - (2/3) L_I'(a)/L_I, and k_q of the full-stick shear on the "
            "proportional path, from Mossakovskii's superposition",
            derived=kappa_p,
        )
        hertz = {dL_I_da: L_I / (2 * a)}  # (31): L_I = (E*/R) sqrt(a/2)
        eq.holds(
            kappa_p.subs(hertz) + 1 / (4 * a),
            how="Hertz: p = L_I sqrt(s) (1 - s/(4a) + ...), the expansion of sqrt(a^2 - x^2)",
        )
        eq.holds(
            kappa_q.subs(eta, 0) - kappa_p,
            how="without tension the full-stick shear is lam times a pressure increment",
        )
        eq.holds(
            sympy.denom(sympy.factor(sympy.cancel(kappa_q * (lam + sympy.pi * eta * a / 4) * L_I)))
            - 48 * a,
            how="k_q L_II has no pole where L_II vanishes: its denominator is 48 a",
        )
    for (component, load), expr in fields.items():
        kind = {"p": "pressure", "q": "shear"}[load]
        d.emit(
            name=f"edge_eigenfield_{kind}_{component}",
            args=(*PARTS, POWER),
            expr=expr,
            equations=("EA-1", "EA-2", "HP-3"),
            summary=f"Stress {component} of the {kind} (c - t)^lam on t < c, regularised.",
            doc=f"The lower half-plane under the {kind} (c - t)^lam on the half-line t < c "
            "(exerted by the indenter), whose Flamant integral diverges: the field of the "
            "potential -pi w^lam / sin(pi lam), w = x - c - i y = rho e^(i phi), i.e. up to a "
            "uniform sxx (fixed for a cycle's amplitude by edge_uniform_sxx), from the polar "
            "parts of w (computed once per point and load for all six fields).  Tension "
            "positive, plane strain; y >= 0, and not at the edge itself for lam < 0.",
            module="edge_stress",
            returns=f"{component} per unit load amplitude [force/length^2 per "
            "force/length^(2 + lam)].",
        )
    d.emit(
        name="edge_uniform_sxx",
        args=(Argument(dsigma, "Change sigma2 - sigma1 of the lower body's bulk tension."),),
        expr=uniform_amplitude(),
        equations=("EA-3",),
        summary="Uniform sxx of the amplitude near an edge: half the change of bulk tension.",
        doc="The amplitude (state 2 minus state 1) of the surface-parallel stress that the "
        "regularised edge eigenfields leave undetermined, fixed by the strain compatibility of "
        "the two bodies in the stick zone.",
        module="edge_stress",
        returns="sxx [force/length^2].",
    )
    for key, name, text in (
        ("a2", "state2", "sqrt(a2 - x), the slip zone's traction at state 2"),
        ("a1", "state1", "sqrt(a1 - x)_+, the slip zone's traction at state 1"),
        ("b", "stick", "sqrt(b - x)_+, the stick boundary's term -K"),
    ):
        expr = amplitudes[key]
        used = sorted(expr.free_symbols, key=lambda symbol: symbol.name)
        d.emit(
            name=f"edge_shear_amplitude_{name}",
            args=arguments(*used),
            expr=expr,
            equations=("49", "EA-4"),
            summary=f"In (49) at b17: the coefficient of {text}.",
            doc="(49) with the density (15) on b from (17) is a sum of three square-root loads "
            "in the paper's frame (the traction on the indenter, forward slip at the right "
            "edge; the lower body carries the negative).",
            module="edge_stress",
            returns="[force/length^(5/2)].",
        )
    slope_argument = Argument(dL_I_da, "Slope dL_I/da of the normal edge multiplier at a.")
    shear_multiplier = (lam + sympy.pi * eta * a / 4) * L_I  # (21)
    d.emit(
        name="edge_pressure_next_coefficient",
        args=(*arguments(a, L_I), slope_argument),
        expr=sympy.factor(kappa_p * L_I),
        equations=("4", "19", "EA-6"),
        summary="M_I: the pressure near an edge is L_I s^(1/2) + M_I s^(3/2) + ..., s = a - x.",
        doc="From Mossakovskii's superposition for any symmetric contact law (Hertz: M_I = "
        "-L_I/(4a)): the next term of (4), for the stated accuracy of the edge fields.",
        module="edge_stress",
        returns="M_I [force/length^(7/2)].",
    )
    d.emit(
        name="edge_shear_next_coefficient",
        args=(*arguments(a, lam, eta, L_I), slope_argument),
        expr=sympy.factor(sympy.cancel(kappa_q * shear_multiplier)),
        equations=("5", "21", "EA-6"),
        summary="M_II: the full-stick shear near an edge is L_II s^(1/2) + M_II s^(3/2) + ....",
        doc="On the proportional path dQ = lam dP, dsigma = eta dP (lam, eta as seen from the "
        "edge), from Mossakovskii's superposition: the next term of (5), for the stated "
        "accuracy of the edge fields; without tension M_II = lam M_I.",
        module="edge_stress",
        returns="M_II [force/length^(7/2)].",
    )
    return d


def _hertz_check() -> tuple[list[float], list[float]]:
    """Near the right edge of the Fig. 5 cycle, at three distances r from a2 (points on half
    circles of radius r): the worst |exact - asymptote| / max|amplitude|, and the worst ratio
    of |exact - asymptote| to the next-order estimate -- the field of the loads k A_c (c -
    t)^(3/2) (EA-6), largest component -- in doubles."""
    import numpy as np

    R, E, mu_, P1, P2, Q2 = 1.0, 1.0, 0.1, 100.0, 105.0, 1.0

    def half_width(P: float) -> float:
        return float(np.sqrt(4 * P * R / (np.pi * E)))

    def peak(P: float) -> float:
        return 2 * P / (np.pi * half_width(P))

    P_K = (P1 + P2) / 2 - Q2 / (2 * mu_)
    A1, A2, AK = half_width(P1), half_width(P2), half_width(P_K)
    L1, L2 = (E / R) * np.sqrt(A1 / 2), (E / R) * np.sqrt(A2 / 2)
    lam_ = Q2 / (P2 - P1)
    LII1, LII2 = lam_ * L1, lam_ * L2
    kappa = -1 / (4 * A1)  # EA-6 for Hertz (k_q = k_p without tension)
    symbols = (X, y, exponent)
    numeric = {
        k: sympy.lambdify(symbols, v.subs(polar_parts()), "numpy") for k, v in eigenfields().items()
    }
    ellipse = {
        k: sympy.lambdify((sympy.Symbol("x", real=True), y, sympy.Symbol("a", positive=True)), v)
        for k, v in semi_ellipse_fields().items()
    }
    values = {mu: mu_, L_I1: L1, L_I2: L2, L_II1: LII1, L_II2: LII2, a1: A1, a2: A2}
    b17 = float(stick_boundary().subs(values))
    loads = (  # edge, pressure amplitude, shear amplitude on the lower body (EA-4)
        (A2, L2, -mu_ * L2),
        (A1, -L1, -mu_ * L1),
        (b17, 0.0, mu_ * (L1 + L2) + LII1 - LII2),
    )
    relative, against_estimate = [], []
    for r in (0.001, 0.01, 0.1):
        angles = np.linspace(0, np.pi, 25)
        xs, ys = A2 + r * A2 * np.cos(angles), r * A2 * np.sin(angles)
        error, estimate, scale = np.zeros_like(xs), np.zeros_like(xs), 0.0
        for component in COMPONENTS:
            # exact: the pressure change and the shear change -mu (p2 + p1 - 2 pK) (47)
            exact = (
                peak(P2) / A2 * ellipse[(component, "p")](xs, ys, A2)
                - peak(P1) / A1 * ellipse[(component, "p")](xs, ys, A1)
                - mu_
                * (
                    peak(P2) / A2 * ellipse[(component, "q")](xs, ys, A2)
                    + peak(P1) / A1 * ellipse[(component, "q")](xs, ys, A1)
                    - 2 * peak(P_K) / AK * ellipse[(component, "q")](xs, ys, AK)
                )
            )
            asymptote, next_order = np.zeros_like(xs), np.zeros_like(xs)
            for edge, pressure, shear in loads:
                for power, target, factor in ((0.5, asymptote, 1.0), (1.5, next_order, kappa)):
                    target += factor * pressure * numeric[(component, "p")](xs - edge, ys, power)
                    target += factor * shear * numeric[(component, "q")](xs - edge, ys, power)
            scale = max(scale, float(np.max(np.abs(exact))))
            error = np.maximum(error, np.abs(exact - asymptote))
            estimate = np.maximum(estimate, np.abs(next_order))
        relative.append(float(np.max(error)) / scale)
        against_estimate.append(float(np.max(error / estimate)))
    return relative, against_estimate
