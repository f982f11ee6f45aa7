"""Edge multipliers of an asymmetric contact whose loads P, Q, sigma and moment M vary together.

The paper derives (19)-(21) for a symmetric contact with M = 0: the pressure is Mossakovskii's
superposition of centred flat punches, the full-stick shear that of centred bonded strips.
Here the contact is (c_l, c_r), both edges moving as the load grows along its path, centre
m = (c_l + c_r)/2, width w = c_r - c_l.  Each increment of the path is carried by the contact
as it then is:

* normal: a rigid flat punch on (c_l, c_r), translated and tilted, carrying dP and the moment
  dM_c = dM - m dP about the contact's current centre (M about a fixed point):
      dp = [dP/pi + 2 dM_c (x - m)/(pi h^2)] / sqrt((c_r - x)(x - c_l)),   h = w/2;
* tangential: a bonded strip on (c_l, c_r) under dQ and d sigma (uncoupled, elastically
  similar bodies, so the moment does not enter):
      dq = [dQ/pi + d sigma (x - m)/4] / sqrt((c_r - x)(x - c_l)).

Integrating the stages whose right edge lies beyond x and letting c_r - x -> 0 gives, with the
path parametrised by the right edge's own position a = c_r (steps AS1, AS2 below),

    L_I  = (2/(pi sqrt w)) (dP/da + (4/w) dM_c/da),                       (AS1; (19) if symmetric)
    L_II = (2/(pi sqrt w)) (dQ/da + (pi w/8) d sigma/da),                 (AS2; (20) if symmetric)

and on the proportional path dQ = lam dP, d sigma = eta dP, with a'(P) the slope of this
edge's own law along the path,

    L_II = (2/(pi sqrt w a'(P))) (lam + pi eta w/8).                      (AS3)

What changes against the paper:

* (21), L_II = (lam + pi eta a/4) L_I, holds only when the increments carry no moment about
  the contact centre (dM_c = 0) *and* a is measured from that centre.  In general the ratio is
  L_II/L_I = (lam + pi eta w/8)/f with the *moment factor* f = 1 + (4/w) dM_c/dP
  = (pi sqrt w/2) L_I a'(P) (AS4).  So L_II must be computed from the edge's own slope a'(P)
  and the width w (both edges' laws), not from L_I: (AS3).  f = 1 exactly when the rotation of
  the punch is the same all along the path (AS5): a rotating contact has f != 1.
* Whatever M does, the two edges' data obey L_I,r a_r' + L_I,l a_l' = 4/(pi sqrt w) (AS6),
  with a_l = -c_l: a check of calibrated data that needs no knowledge of M.
* The local analysis (1)-(17) is unchanged: it is local to one edge and needs only that edge's
  a1, a2 and multipliers, with b measured from any fixed point along the edge's outward
  direction ((17) is a weighted mean, so the origin drops out).  What it needs is that the
  edge *advances* as P grows (a'(P) > 0 along the path): an edge that recedes under a moment
  leaves stuck material behind, and (6), in which the state-2 contact contains the state-1
  contact near the edge, fails.
* b_exact = a(P_K) (Jaeger-Ciavarella) does not carry over.  The corrective pressure of the
  exact solution must satisfy the stick condition against p1 + p2, which fixes its rotation at
  the mean (theta1 + theta2)/2 of the two states, not at a point of the load path: the exact
  stick zone is the contact of the same profile at load P_K and that mean rotation (AS7).  It is
  a(P_K) only when the rotation is the same at both states (f = 1); calibrated edge laws, known
  only along the path, cannot give it otherwise.  To first order in dP it equals (17) with
  (AS3) -- and not (17) with (21) (AS7) -- which is the independent check of (AS3).

(AS1) is checked against the closed-form pressure of an asymmetric profile
h = x^2/(2R) + k x^3 with any rotation (the bounded inversion of the half-plane equation done in
Chebyshev moments): its edge multiplier equals (AS1) for every direction of the path in
(c_l, c_r) (AS1, AS5 and the Jaeger-Ciavarella partials).
"""

from __future__ import annotations

import functools

import sympy

from asymslip.codegen import Argument, Derivation

from ._glossary import L_I, a, arguments, da_dP, eta, lam, mu
from .section2_calibrations import normal_multiplier, shear_multiplier
from .section2_consistency import stick_boundary

delta, v = sympy.symbols("delta v", positive=True)  # delta = a - x; v maps (x, a) onto (0, 1)
width = sympy.Symbol("w", positive=True)
L_I_right, L_I_left = sympy.symbols("L_I_right L_I_left", positive=True)
da_dP_right, da_dP_left = sympy.symbols("da_dP_right da_dP_left", positive=True)
dP_da_edge = sympy.Symbol("dP_da", positive=True)
dMc_da = sympy.Symbol("dMc_da", real=True)

left_edge = sympy.Function("c_l")  # left edge position as a function of the right one
load_slope = sympy.Function("Pprime")  # dP/dc_r along the path
moment_slope = sympy.Function("Mprime")  # dM_c/dc_r: moment of the increment about the centre
shear_slope = sympy.Function("Qprime")
tension_slope = sympy.Function("sigmaprime")

WIDTH = Argument(
    width,
    "Contact width w = a_right + a_left (both edges' distances from one "
    "point inside the contact) at the load considered [length].",
)
EDGE_SLOPE = Argument(
    da_dP,
    "Slope a'(P) of this edge's own law along the load path, > 0 "
    "(the edge advances) [length^2/force].",
)
EDGE_MULTIPLIER = Argument(
    L_I, "Normal edge multiplier L_I of this edge, p ~ L_I sqrt(a - x) (4) [force/length^(5/2)]."
)


def _edge_multiplier(increment, values: dict) -> sympy.Expr:
    """lim p/sqrt(delta) of int_x^a increment(c, x) dc / sqrt((c - x)(x - c_l(c))).

    With c = x + delta v the integral is sqrt(delta) int_0^1 increment / sqrt(v (x - c_l)) dv;
    the integrand is regular at delta = 0, so the limit is its value there, integrated.
    ``values`` names the path's slopes at the edge (functions of a -> symbols).
    """
    x_ = a - delta
    c_ = x_ + delta * v
    integrand = increment(c_, x_) / sympy.sqrt(v * (x_ - left_edge(c_)))
    at_edge = integrand.subs(delta, 0).subs(left_edge(a), a - width).subs(values)
    return sympy.factor(sympy.integrate(at_edge, (v, 0, 1)))


def _centre(c_: sympy.Expr) -> tuple[sympy.Expr, sympy.Expr]:
    return (c_ + left_edge(c_)) / 2, (c_ - left_edge(c_)) / 2


@functools.cache
def normal_multiplier_asymmetric() -> sympy.Expr:
    """(AS1) in terms of dP/da, dM_c/da and the width w."""

    def increment(c_, x_):
        centre, half = _centre(c_)
        return load_slope(c_) / sympy.pi + 2 * moment_slope(c_) * (x_ - centre) / (
            sympy.pi * half**2
        )

    return _edge_multiplier(increment, {load_slope(a): dP_da_edge, moment_slope(a): dMc_da})


@functools.cache
def shear_multiplier_asymmetric_slopes() -> sympy.Expr:
    """(AS2) in terms of dQ/da, dsigma/da and the width w."""

    def increment(c_, x_):
        centre, _ = _centre(c_)
        return shear_slope(c_) / sympy.pi + tension_slope(c_) * (x_ - centre) / 4

    dQ, dsigma = sympy.symbols("dQ_da dsigma_da", real=True)
    return _edge_multiplier(increment, {shear_slope(a): dQ, tension_slope(a): dsigma}), dQ, dsigma


@functools.cache
def shear_multiplier_asymmetric() -> sympy.Expr:
    """(AS3): (AS2) on the proportional path, dQ/da = lam / a'(P), dsigma/da = eta / a'(P)."""
    expr, dQ, dsigma = shear_multiplier_asymmetric_slopes()
    return sympy.factor(expr.subs({dQ: lam / da_dP, dsigma: eta / da_dP}))


@functools.cache
def moment_factor() -> sympy.Expr:
    """(AS4): f = L_I / (L_I with dM_c = 0), in terms of L_I, a'(P) and w."""
    untilted = normal_multiplier_asymmetric().subs(dMc_da, 0).subs(dP_da_edge, 1 / da_dP)
    return sympy.simplify(L_I / untilted)


@functools.cache
def multiplier_balance() -> sympy.Expr:
    """(AS6): (pi sqrt w / 4)(L_I,r a_r' + L_I,l a_l'), identically 1."""
    return sympy.sqrt(width) * sympy.pi / 4 * (L_I_right * da_dP_right + L_I_left * da_dP_left)


# --- the closed-form check: an asymmetric profile, any rotation --------------------------------
s_, y_ = sympy.symbols("s y", real=True)
centre_, theta_, k_ = sympy.symbols("m theta k", real=True)
half_, R_, E_ = sympy.symbols("h R E_star", positive=True)


def _chebyshev_first(polynomial: sympy.Expr) -> sympy.Expr:
    """int_{-1}^{1} polynomial(s) / sqrt(1 - s^2) ds, term by term (s^j -> pi (j-1)!!/j!!)."""
    total = sympy.S.Zero
    for (power,), coefficient in sympy.Poly(sympy.expand(polynomial), s_).terms():
        if power % 2 == 0:
            total += coefficient * sympy.pi * sympy.factorial2(power - 1) / sympy.factorial2(power)
    return total


def _chebyshev_second(polynomial: sympy.Expr) -> sympy.Expr:
    """int_{-1}^{1} polynomial(y) sqrt(1 - y^2) dy (y^j -> pi (j-1)!!/(j+2)!!)."""
    total = sympy.S.Zero
    for (power,), coefficient in sympy.Poly(sympy.expand(polynomial), y_).terms():
        if power % 2 == 0:
            total += (
                coefficient * sympy.pi * sympy.factorial2(power - 1) / sympy.factorial2(power + 2)
            )
    return total


@functools.cache
def asymmetric_profile_contact() -> dict[str, sympy.Expr]:
    """Pressure moments and edge multiplier of h = x^2/(2R) + k x^3 on (m - h, m + h).

    The half-plane equation (1/pi) PV int p(t)/(x - t) dt = (E*/2)(h'(x) - theta) has the
    solution bounded at both ends
        p = (E*/(2 pi)) sqrt(1 - y^2) PV int G(s)/(sqrt(1 - s^2)(s - y)) ds,
    G(s) = h'(m + h s) - theta, x = m + h y, provided int G/sqrt(1 - s^2) ds = 0 (which fixes
    the rotation theta).  For a polynomial G the principal value is the Chebyshev moment of the
    polynomial (G(s) - G(y))/(s - y), since PV int 1/(sqrt(1 - s^2)(s - y)) ds = 0.
    """
    position = sympy.Symbol("X", real=True)
    profile = position**2 / (2 * R_) + k_ * position**3
    gradient = sympy.diff(profile, position).subs(position, centre_ + half_ * s_) - theta_
    (rotation,) = sympy.solve(_chebyshev_first(gradient), theta_)
    gradient = gradient.subs(theta_, rotation)
    quotient = sympy.cancel((gradient - gradient.subs(s_, y_)) / (s_ - y_))
    shape = E_ / (2 * sympy.pi) * _chebyshev_first(quotient)  # p = shape(y) sqrt(1 - y^2)
    load = sympy.expand(half_ * _chebyshev_second(shape))
    moment = sympy.expand(half_ * _chebyshev_second(shape * (centre_ + half_ * y_)))
    # p / sqrt(c_r - x) = shape sqrt(1 + y) / sqrt(h) -> shape(1) sqrt(2/h) at the right edge.
    right = sympy.simplify(shape.subs(y_, 1) * sympy.sqrt(2 / half_))
    return {"theta": rotation, "P": load, "M": moment, "L_I_right": right}


def _along_right(f: sympy.Expr) -> sympy.Expr:
    """d/dc_r at fixed c_l: m and h both move by half."""
    return (sympy.diff(f, centre_) + sympy.diff(f, half_)) / 2


def _along_left(f: sympy.Expr) -> sympy.Expr:
    """d/dc_l at fixed c_r."""
    return (sympy.diff(f, centre_) - sympy.diff(f, half_)) / 2


def derive() -> Derivation:
    d = Derivation(__file__)
    d.describe_module(
        "asymmetric_edges",
        "Beyond the paper: edge multipliers of an asymmetric contact whose loads (P, Q, sigma "
        "and the moment M) vary together, for edges calibrated one at a time.",
    )
    contact = asymmetric_profile_contact()
    w_profile = 2 * half_
    with d.equation("AS1", "Normal edge multiplier of an asymmetric, tilting contact") as eq:
        eq.beyond_paper(
            "Mossakovskii's superposition of translated and tilted flat punches on the current "
            "contact, expanded at the right edge: L_I = (2/(pi sqrt w))(dP/da + (4/w) dM_c/da)",
            derived=normal_multiplier_asymmetric(),
        )
        eq.holds(
            normal_multiplier_asymmetric().subs({width: 2 * a, dMc_da: 0}) - normal_multiplier(),
            how="reduces to (19) for a symmetric contact (w = 2a, no moment about the centre)",
        )
        load, moment = contact["P"], contact["M"]
        by_right = normal_multiplier_asymmetric().subs(
            {
                width: w_profile,
                dP_da_edge: _along_right(load),
                dMc_da: _along_right(moment) - centre_ * _along_right(load),
            }
        )
        eq.holds(
            by_right - contact["L_I_right"],
            how="equals the edge multiplier of the closed-form pressure of the asymmetric "
            "profile x^2/(2R) + k x^3 (bounded inversion, any rotation) when the right edge "
            "moves",
        )
        eq.holds(
            _along_left(load) + 4 / w_profile * (_along_left(moment) - centre_ * _along_left(load)),
            how="and the left edge's motion adds nothing to it: dP + (4/w) dM_c vanishes when "
            "only c_l moves, so (AS1) holds for every direction of the path",
        )
    with d.equation("AS2", "Full-stick shear edge multiplier of an asymmetric contact") as eq:
        expr, dQ, dsigma = shear_multiplier_asymmetric_slopes()
        eq.beyond_paper(
            "bonded strips on the current contact under dQ and dsigma, expanded at the right "
            "edge: L_II = (2/(pi sqrt w))(dQ/da + (pi w/8) dsigma/da)",
            derived=expr,
        )
        glossary_slopes = sympy.symbols("dQ_da dsigma_da", real=True)
        symmetric = shear_multiplier().subs(dict(zip(glossary_slopes, (dQ, dsigma), strict=True)))
        eq.holds(
            expr.subs(width, 2 * a) - symmetric,
            how="reduces to (20) for a symmetric contact (w = 2a)",
        )
    with d.equation("AS3", "L_II on the proportional path from the edge's own law") as eq:
        eq.beyond_paper(
            "(AS2) with dQ = lam dP, dsigma = eta dP: L_II = 2 (lam + pi eta w/8)/(pi sqrt(w) "
            "a'(P)); it needs this edge's slope a'(P) and the width w, not L_I",
            derived=shear_multiplier_asymmetric(),
        )
        symmetric_21 = (lam + sympy.pi * eta * a / 4) * normal_multiplier().subs(
            sympy.Symbol("dP_da", positive=True), 1 / da_dP
        )
        eq.holds(
            shear_multiplier_asymmetric().subs(width, 2 * a) - symmetric_21,
            how="reduces to (21) with L_I from (19) for a symmetric contact",
        )
    with d.equation("AS4", "Moment factor: L_II/L_I = (lam + pi eta w/8)/f") as eq:
        eq.beyond_paper(
            "f = (pi sqrt w/2) L_I a'(P) = 1 + (4/w) dM_c/dP: (21) holds iff f = 1",
            derived=moment_factor(),
        )
        general = normal_multiplier_asymmetric().subs(dP_da_edge, 1 / da_dP)
        moment_per_load = sympy.Symbol("dMc_dP", real=True)
        eq.holds(
            moment_factor().subs(L_I, general.subs(dMc_da, moment_per_load / da_dP))
            - (1 + 4 * moment_per_load / width),
            how="with L_I from (AS1): f = 1 + (4/w) dM_c/dP",
        )
        eq.holds(
            shear_multiplier_asymmetric() / L_I * moment_factor()
            - (lam + sympy.pi * eta * width / 8),
            how="L_II = (lam + pi eta w/8) L_I / f",
        )
    with d.equation("AS5", "f = 1 exactly when the rotation is the same along the path") as eq:
        eq.beyond_paper("(21) holds at an asymmetric edge only on a path of constant rotation")
        rotation = contact["theta"]
        # The direction (dm, dh) of the path that keeps the rotation fixed.
        dm, dh = sympy.diff(rotation, half_), -sympy.diff(rotation, centre_)
        dP_ = sympy.diff(contact["P"], centre_) * dm + sympy.diff(contact["P"], half_) * dh
        dM_ = sympy.diff(contact["M"], centre_) * dm + sympy.diff(contact["M"], half_) * dh
        eq.holds(
            dM_ - centre_ * dP_,
            how="for the profile x^2/(2R) + k x^3, increments at constant rotation carry no "
            "moment about the contact centre (dM_c = 0, f = 1)",
        )
        # ... while any other direction changes the rotation, so f != 1 there.
        assert sympy.simplify(sympy.diff(rotation, centre_)) != 0
    with d.equation("AS6", "Both edges' multipliers balance whatever M does") as eq:
        eq.beyond_paper(
            "a check of calibrated data that needs no knowledge of M", derived=multiplier_balance()
        )
        right_edge_value = normal_multiplier_asymmetric().subs(dP_da_edge, 1 / da_dP_right)
        # The left edge is the right edge of the mirrored contact: M (hence dM_c) changes sign.
        left_edge_value = normal_multiplier_asymmetric().subs(dP_da_edge, 1 / da_dP_left)
        moment_per_load = sympy.Symbol("dMc_dP", real=True)
        balance = multiplier_balance().subs(
            {
                L_I_right: right_edge_value.subs(dMc_da, moment_per_load / da_dP_right),
                L_I_left: left_edge_value.subs(dMc_da, -moment_per_load / da_dP_left),
            }
        )
        eq.holds(
            balance - 1,
            how="(pi sqrt w/4)(L_I,r a_r' + L_I,l a_l') = 1 for every moment increment",
        )
    with d.equation("AS7", "Jaeger-Ciavarella for an asymmetric contact, against (17)") as eq:
        eq.beyond_paper(
            "the exact stick zone is the contact at P_K and the mean rotation of the two "
            "states, off the load path: b_exact = a(P_K) only when the rotation is constant; to "
            "first order in dP it equals (17) with (AS3), not (17) with (21)"
        )
        dP = sympy.Symbol("dP", positive=True)
        at_fixed_rotation = sympy.Symbol("r_P", positive=True)  # dc_r/dP at fixed rotation
        by_rotation = sympy.Symbol("r_theta", real=True)  # dc_r/dtheta at fixed load
        rotation_rate = sympy.Symbol("theta_P", real=True)  # dtheta/dP along the path
        path_slope = at_fixed_rotation + by_rotation * rotation_rate
        # P_K of (33) and the mean rotation (theta1 + theta2)/2: first-order shift of c_r.
        exact_shift = at_fixed_rotation * (dP / 2 - lam * dP / (2 * mu)) + by_rotation * (
            rotation_rate * dP / 2
        )
        # (AS1) at fixed rotation (dM_c = 0, AS5): L_I = 2 / (pi sqrt(w) r_P).
        multiplier = normal_multiplier_asymmetric().subs(
            {dMc_da: 0, dP_da_edge: 1 / at_fixed_rotation}
        )
        a1_, growth = sympy.symbols("a1 da", positive=True)
        shear = shear_multiplier_asymmetric().subs({eta: 0, da_dP: path_slope})
        b17 = stick_boundary().subs(
            {
                sympy.Symbol("a1", positive=True): a1_,
                sympy.Symbol("a2", positive=True): a1_ + growth,
                sympy.Symbol("L_I1", positive=True): multiplier,
                sympy.Symbol("L_I2", positive=True): multiplier,
                sympy.Symbol("L_II1", real=True): shear,
                sympy.Symbol("L_II2", real=True): shear,
            }
        )
        first_order = sympy.diff(b17.subs(growth, path_slope * dP), dP).subs(dP, 0) * dP
        eq.holds(
            first_order - exact_shift,
            how="(17) with (AS3) and the multipliers at P1: b - a1 = the first-order shift of "
            "the exact stick edge c_r(P_K, (theta1 + theta2)/2), for any rotation rate",
        )
        naive = stick_boundary().subs(
            {
                sympy.Symbol("a1", positive=True): a1_,
                sympy.Symbol("a2", positive=True): a1_ + growth,
                sympy.Symbol("L_I1", positive=True): multiplier,
                sympy.Symbol("L_I2", positive=True): multiplier,
                sympy.Symbol("L_II1", real=True): lam * multiplier,
                sympy.Symbol("L_II2", real=True): lam * multiplier,
            }
        )
        naive_first = sympy.diff(naive.subs(growth, path_slope * dP), dP).subs(dP, 0) * dP
        gap = sympy.factor(naive_first - exact_shift)
        eq.holds(
            gap + (lam / mu) * by_rotation * rotation_rate * dP / 2,
            how="(17) with (21) instead misses it by -(lam/mu) (dc_r/dtheta)(dtheta/dP) dP/2, "
            "zero only at constant rotation",
            derived=gap,
        )
        rotation_pair = contact["theta"]
        r_P_profile = sympy.simplify(
            (sympy.diff(rotation_pair, half_) - sympy.diff(rotation_pair, centre_))
            / (
                sympy.diff(contact["P"], centre_) * sympy.diff(rotation_pair, half_)
                - sympy.diff(contact["P"], half_) * sympy.diff(rotation_pair, centre_)
            )
        )
        eq.holds(
            multiplier.subs({at_fixed_rotation: r_P_profile, width: w_profile})
            - contact["L_I_right"],
            how="the profile x^2/(2R) + k x^3 confirms L_I = 2/(pi sqrt(w) dc_r/dP|_theta)",
        )

    d.emit(
        name="shear_edge_multiplier_asymmetric",
        args=(*arguments(lam, eta), WIDTH, EDGE_SLOPE),
        expr=shear_multiplier_asymmetric(),
        equations=("20", "21"),
        summary="Full-stick shear edge multiplier L_II of one edge of an asymmetric contact.",
        doc="2 (lam + pi eta w/8) / (pi sqrt(w) a'(P)) on the proportional path, from bonded "
        "strips on the current contact (AS3 of derivations/asymmetric_edge_multipliers.py).  "
        "Valid for any moment history; it reduces to (21) with (19) for a symmetric contact.  "
        "For the left edge pass lam -> -lam (the mirror image).",
        module="asymmetric_edges",
        returns="L_II [force/length^(5/2)].",
    )
    d.emit(
        name="normal_edge_multiplier_asymmetric",
        args=(
            WIDTH,
            Argument(
                dP_da_edge,
                "Load slope dP/da along the path, with a this edge's position [force/length^2].",
            ),
            Argument(
                dMc_da,
                "Slope dM_c/da of the moment of the increments about the "
                "current contact centre (positive towards this edge) [force].",
            ),
        ),
        expr=normal_multiplier_asymmetric(),
        equations=("19",),
        summary="Normal edge multiplier L_I of one edge of an asymmetric, tilting contact.",
        doc="(2/(pi sqrt w))(dP/da + (4/w) dM_c/da): tilted flat punches on the current "
        "contact (AS1).  (19) when the contact is symmetric.",
        module="asymmetric_edges",
        returns="L_I [force/length^(5/2)].",
    )
    d.emit(
        name="edge_moment_factor",
        args=(WIDTH, EDGE_MULTIPLIER, EDGE_SLOPE),
        expr=moment_factor(),
        equations=("19", "21"),
        summary="Moment factor f = 1 + (4/w) dM_c/dP of one edge from its L_I, a'(P) and w.",
        doc="(pi sqrt w/2) L_I a'(P) (AS4).  1 when the contact's rotation does not change "
        "along the path (then (21) and b_exact = a(P_K) hold); L_II/L_I = (lam + pi eta w/8)/f.",
        module="asymmetric_edges",
        returns="f, dimensionless.",
    )
    d.emit(
        name="edge_multiplier_balance",
        args=(
            WIDTH,
            Argument(L_I_right, "Normal edge multiplier of the right edge."),
            Argument(da_dP_right, "Slope a'(P) of the right edge's law."),
            Argument(L_I_left, "Normal edge multiplier of the left edge."),
            Argument(
                da_dP_left, "Slope a'(P) of the left edge's law (its distance, growing leftwards)."
            ),
        ),
        expr=multiplier_balance(),
        equations=("19",),
        summary="(pi sqrt w/4)(L_I,r a_r' + L_I,l a_l'), which is exactly 1 for any contact.",
        doc="(AS6): the moment drops out of the sum of the two edges' multipliers, so calibrated "
        "data of both edges can be checked against 1 without knowing M.",
        module="asymmetric_edges",
        returns="Dimensionless; 1 for consistent data.",
    )
    return d
