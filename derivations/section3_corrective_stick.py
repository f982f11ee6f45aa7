"""Section 3.2, Eqs. (37)-(44): the corrective-stick (full-sliding) asymptote of [12].

Starting points: the singular edge traction (37) of a sliding increment, its calibration
K_II(Q, sigma, a) (38) from [13], and the slip-zone size (40) from [12].  Along the
proportional path (18) the change of K_II at fixed contact size gives (39); (40) with the Hertz
multiplier (31) gives (41), and its first-order expansion (42)-(44).

In (41) both Delta K_II (39) and L_I (31) are evaluated at a = a1, the load-state-1 contact;
the emitted functions follow that choice.

The Hertz width a1 - b of (41) is the difference of two terms of order dP; eliminating dP for
the contact growth da = a2 - a1 through the Hertz law (dP = P(a1 + da) - P(a1)) turns it into
da [2 a1 (lam - mu + pi eta a1/4) + da (lam + pi eta a1/4)] / (4 mu a1), whose O(dP^2) part is
computed directly (no cancellation at lam = mu, eta = 0).
"""

from __future__ import annotations

import functools

import sympy

from asymslip.codegen import Argument, Derivation

from ._glossary import L_I, L_I1, P1, a, a1, a2, arguments, da, dP, eta, lam, mu
from .contact_law_hertz import (
    LOAD1,
    LOAD_CHANGE,
    MODULUS,
    RADIUS,
    E_star,
    P,
    R,
    hertz_growth,
    hertz_half_width,
    hertz_load,
    hertz_multiplier,
)
from .section3_exact_solution import eps, exact_stick_ratio_series

Q, Q1, sigma, sigma1 = sympy.symbols("Q Q1 sigma sigma1", real=True)
x = sympy.Symbol("x", real=True)
stress_intensity = sympy.Symbol("K_II", real=True)
intensity_change = sympy.Symbol("dK_II", real=True)  # Delta K_II over the cycle

HERTZ_ARGS = (
    LOAD1,
    LOAD_CHANGE,
    Argument(lam, "Load-path slope lambda = dQ/dP (18), either sign."),
    Argument(eta, "Load-path slope eta = dsigma/dP (18), either sign [1/length]."),
    Argument(mu, "Coefficient of friction, mu > 0."),
    RADIUS,
    MODULUS,
)


def sliding_intensity(shear: sympy.Expr, tension: sympy.Expr, half_width: sympy.Expr):
    """(38) from [13] p. 135: K_II of the sliding solution under Q and sigma (starting point)."""
    return shear / (sympy.pi * sympy.sqrt(2 * half_width)) + tension / 4 * sympy.sqrt(
        half_width / 2
    )


def paper_slip_zone_depth() -> sympy.Expr:
    """(40) from [12]: d1 = Delta K_II / (mu L_I) - Delta a / 2 (starting point)."""
    return intensity_change / (mu * L_I) - da / 2


@functools.cache
def intensity_rate() -> sympy.Expr:
    """(39): Delta K_II / Delta P along the path (18), at fixed contact size a."""
    change = sliding_intensity(Q1 + lam * dP, sigma1 + eta * dP, a) - sliding_intensity(
        Q1, sigma1, a
    )
    return sympy.expand(sympy.simplify(change / dP))


@functools.cache
def slip_zone_depth() -> sympy.Expr:
    """(40) with Delta K_II = dP * (39) and L_I, both at a = a1."""
    return paper_slip_zone_depth().subs(
        {intensity_change: dP * intensity_rate().subs(a, a1), L_I: L_I1}
    )


@functools.cache
def hertz_multiplier_of_width() -> sympy.Expr:
    """(31) as a function of the half-width a: L_I(P(a))."""
    return sympy.simplify(hertz_multiplier().subs(P, hertz_load()))


def _hertz_in_widths(expr: sympy.Expr) -> sympy.Expr:
    """L_I1 = (31) at a1 and dP = P(a1 + da) - P(a1) from (29)."""
    load_change = sympy.expand(hertz_load().subs(a, a1 + da) - hertz_load().subs(a, a1))
    return expr.subs({L_I1: hertz_multiplier_of_width().subs(a, a1), dP: load_change})


@functools.cache
def hertz_depth_in_widths() -> sympy.Expr:
    """d1 of (40) for Hertz in terms of a1 and da = a2 - a1, with dP eliminated."""
    depth = sympy.factor(_hertz_in_widths(slip_zone_depth()))
    numerator, denominator = sympy.fraction(depth)
    # Grouped by powers of da: the O(da) coefficient vanishes at lam = mu, eta = 0 by itself.
    bracket = sympy.collect(sympy.expand(numerator / da), da, sympy.factor)
    return da * bracket / denominator


@functools.cache
def hertz_slip_zone_depth() -> sympy.Expr:
    """a1 - b of (41) in terms of P1, dP: a1 = a(P1), da = a(P1 + dP) - a(P1) rationalised."""
    return hertz_depth_in_widths().subs({a1: hertz_half_width().subs(P, P1), da: hertz_growth()})


@functools.cache
def hertz_stick_boundary() -> sympy.Expr:
    """(41): b = a1 - d1 for Hertz."""
    return hertz_half_width().subs(P, P1) - hertz_slip_zone_depth()


@functools.cache
def hertz_stick_ratio_series(order: int) -> sympy.Expr:
    """b/a1 of (41) as a series in eps = dP/P1 through eps**order (P1, R, E* cancel)."""
    growth_ratio = hertz_half_width().subs(P, P1 * (1 + eps)) / hertz_half_width().subs(P, P1)
    ratio = sympy.expand(1 - hertz_depth_in_widths().subs(da, a1 * (growth_ratio - 1)) / a1)
    assert ratio.free_symbols <= {eps, lam, mu, eta, a1}, ratio
    return sympy.series(ratio, eps, 0, order + 1).removeO()


def derive() -> Derivation:
    d = Derivation(__file__)
    d.describe_module(
        "corrective_stick",
        "Section 3.2 of the paper: the corrective-stick (full-sliding) asymptote of [12] for "
        "the steady-state slip zone, generic and for the Hertzian contact.",
    )
    with d.equation("37", "Singular edge traction of a sliding increment") as eq:
        eq.given(
            "from [12]: q = K_II / sqrt(a - x) as a - x -> 0",
            derived=stress_intensity / sympy.sqrt(a - x),
        )
    with d.equation("38", "Sliding calibration K_II(Q, sigma, a)") as eq:
        eq.given(
            "from [13] p. 135: K_II = Q/(pi sqrt(2a)) + (sigma/4) sqrt(a/2)",
            derived=sliding_intensity(Q, sigma, a),
        )
    with d.equation("39", "Change of K_II along the proportional path") as eq:
        eq.matches_paper(
            intensity_rate(),
            lam / (sympy.pi * sympy.sqrt(2 * a)) + eta / 4 * sympy.sqrt(a / 2),
            how="(38) at Q1 + lam dP, sigma1 + eta dP minus (38) at Q1, sigma1, at fixed a, "
            "divided by dP",
            printed=r"\frac{\Delta K_{II}}{\Delta P}=\frac{\lambda}{\pi\sqrt{2a}}"
            r"+\frac{\eta}{4}\sqrt{\frac{a}{2}}",
        )
    with d.equation("40", "Corrective-stick slip zone b = a1 - d1") as eq:
        eq.given(
            "from [12]: d1 = Delta K_II/(mu L_I) - Delta a/2; here Delta K_II = dP (39) and "
            "L_I are taken at a = a1, as the paper's (41) does",
            derived=paper_slip_zone_depth(),
        )
    with d.equation("41", "Corrective-stick stick boundary for Hertz") as eq:
        derived_41 = a1 - slip_zone_depth().subs(
            {L_I1: hertz_multiplier_of_width().subs(a, a1), da: a2 - a1}
        )
        eq.matches_paper(
            derived_41,
            a1
            - dP * R / (sympy.pi * mu * E_star * a1) * (lam + sympy.pi * eta * a1 / 4)
            + (a2 - a1) / 2,
            how="(40) with (39) at a1 and L_I of (31) at a1",
            printed=r"b=a_1-\frac{\Delta P R}{\pi\mu E^* a_1}\left(\lambda+\frac{\pi\eta a_1}{4}"
            r"\right)+\frac{a_2-a_1}{2}",
        )
        eq.holds(
            hertz_depth_in_widths() - _hertz_in_widths(slip_zone_depth()),
            how="emitted width: dP = P(a1 + da) - P(a1) eliminated, a1 - b = da [2 a1 (lam - mu "
            "+ pi eta a1/4) + da (lam + pi eta a1/4)]/(4 mu a1), da from the rationalised "
            "Hertz growth",
            derived=hertz_depth_in_widths(),
        )
    # (42) and (43) are written in terms of the symbol a1 = a(P1).
    load1 = hertz_load().subs(a, a1)
    with d.equation("42", "First-order Hertz contact growth") as eq:
        growth_series = sympy.series(hertz_half_width().subs(P, P1 + dP), dP, 0, 2).removeO()
        a2_first = sympy.simplify(growth_series.subs(P1, load1))
        eq.matches_paper(
            a2_first,
            a1 * (1 + 2 * R * dP / (sympy.pi * E_star * a1**2)),
            how="series of a(P1 + dP) from (29) to first order in dP, with P1 = P(a1)",
            printed=r"a_2\approx a_1\left(1+\frac{2R\Delta P}{\pi E^* a_1^2}\right)",
        )
    with d.equation("43", "Corrective-stick boundary with the first-order growth") as eq:
        derived_43 = derived_41.subs(a2, a2_first)
        eq.matches_paper(
            derived_43,
            a1 / 2 * (2 + 2 * R * dP / (sympy.pi * E_star * a1**2))
            - dP * R / (sympy.pi * a1 * mu * E_star) * (lam + sympy.pi * eta * a1 / 4),
            how="(42) substituted into (41)",
            printed=r"b\approx\frac{a_1}{2}\left(2+\frac{2R\Delta P}{\pi E^* a_1^2}\right)"
            r"-\frac{\Delta P R}{\pi a_1\mu E^*}\left(\lambda+\frac{\pi\eta a_1}{4}\right)",
        )
    with d.equation("44", "Corrective-stick stick ratio to first order") as eq:
        # (29) recalled: a1^2 = 4 P1 R/(pi E*), i.e. R/(pi E*) = a1^2/(4 P1).
        derived_44 = sympy.expand(derived_43 / a1).subs(R, sympy.pi * E_star * a1**2 / (4 * P1))
        paper_44 = 1 - (lam / mu + eta / mu * sympy.pi * a1 / 4 - 1) * dP / (4 * P1)
        eq.matches_paper(
            derived_44,
            paper_44,
            how="(43) divided by a1, with (29) for R/(pi E* a1^2)",
            printed=r"\frac{b}{a_1}\approx 1-\left(\frac{\lambda}{\mu}+\frac{\eta}{\mu}"
            r"\frac{\pi a_1}{4}-1\right)\frac{\Delta P}{4P_1}",
        )
        eq.holds(
            hertz_stick_ratio_series(1).subs(eps, dP / P1) - paper_44,
            how="and (44) is the first-order term in dP/P1 of (41)/a1 with the exact growth",
        )
        eq.holds(
            paper_44.subs(eta, 0) - exact_stick_ratio_series(1).subs(eps, dP / P1),
            how="at eta = 0 it equals the exact first-order result (36)",
        )

    d.emit(
        name="shear_intensity_rate",
        args=arguments(lam, eta, a),
        expr=intensity_rate(),
        equations=("38", "39"),
        summary="Rate Delta K_II / Delta P of the sliding stress intensity along the path.",
        doc="(38) differenced along the proportional path (18) at fixed contact size a.",
        module="corrective_stick",
        returns="Delta K_II / Delta P [1/length^(3/2)].",
    )
    d.emit(
        name="corrective_stick_slip_zone_width",
        args=arguments(mu, lam, eta, a1, da, L_I1, dP),
        expr=slip_zone_depth(),
        equations=("39", "40"),
        summary="Slip-zone width d1 = a1 - b of the corrective-stick asymptote [12].",
        doc="(40) with Delta K_II = dP times (39), both Delta K_II and L_I evaluated at the "
        "load-state-1 contact a1 (the choice the paper's (41) makes).  The two terms come from "
        "independent inputs, so their difference is as well conditioned as the inputs allow.  "
        "Valid when da and d1 are small compared with a1; a slip zone inside a1 (d1 > 0) needs "
        "roughly lam + pi eta a1/4 > mu.",
        module="corrective_stick",
        returns="a1 - b, same units as a1.",
    )
    d.emit(
        name="hertz_stick_boundary_corrective_stick",
        args=HERTZ_ARGS,
        expr=hertz_stick_boundary(),
        equations=("31", "39", "40", "41"),
        summary="Corrective-stick stick boundary b of (41) for the Hertzian contact.",
        doc="a1 minus the cancellation-free width; a1 = a(P1) and the growth a2 - a1 from (29) "
        "in rationalised form.  Valid under (32): dP/P1 << 1 and dP/P1 |1 - lam/mu| << 1.",
        module="corrective_stick",
        returns="b [length].",
    )
    d.emit(
        name="hertz_slip_zone_width_corrective_stick",
        args=HERTZ_ARGS,
        expr=hertz_slip_zone_depth(),
        equations=("40", "41"),
        summary="Corrective-stick slip-zone width a1 - b of (41) for Hertz, without cancellation.",
        doc="da [2 a1 (lam - mu + pi eta a1/4) + da (lam + pi eta a1/4)]/(4 mu a1) with "
        "da = a(P1 + dP) - a(P1) rationalised: the part of order dP^2 is computed directly, so "
        "the width keeps full relative precision for tiny dP/P1, also at lam = mu.  Valid "
        "under (32).",
        module="corrective_stick",
        returns="a1 - b [length].",
    )
    return d
