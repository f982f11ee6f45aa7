"""The stress field in the lower half-plane under piecewise-linear surface tractions (issue 18).

Conventions (those of :mod:`asymslip.stress`): x along the surface, depth y >= 0 into the lower
body; the surface carries a pressure p (pushing into the body) and a shear traction q along +x,
both exerted by the indenter; stresses sxx, syy (normal to the surface), sxy, tension positive;
plane strain.  The starting point is Flamant's point-force field (``solver_influence``, F-1):
a normal force P and a tangential force F at the surface origin give, at (u, y),

    sxx = -(2/pi) (P y u^2 + F u^3) / r^4,   syy = -(2/pi) (P y^3 + F y^2 u) / r^4,
    sxy = -(2/pi) (P y^2 u + F y u^2) / r^4,     r^2 = u^2 + y^2.

HP-1  A linear load w0 -> w1 on one element [t0, t1] integrates in closed form (u = x - t): the
      integrals of u^k/r^4, k = 0..4, are atan and log terms.  Written with atan2(-y, u) in
      place of atan(u/y) - pi/2, the result stays finite as y -> 0.
HP-2  At the surface (y -> 0+) the element field tends to syy = -p(x), sxy = -q(x) inside the
      element and 0 outside, and sxx = -p(x) - (2/pi) PV int q(t)/(x - t) dt: the principal
      value, checked against SymPy's own PV integral of the linear load.
HP-3  The field of any surface load is a map of two Cauchy integrals and their derivatives,
      P(zeta) = int p(t)/(zeta - t) dt and Q(zeta) = int q(t)/(zeta - t) dt, zeta = x - i y:
      sxx + syy = -(2/pi) Re(Q - i P) and syy - sxx + 2 i sxy = (2/pi) (i y conj(Q' - i P') +
      conj(Q)).  Found by solving for the coefficients of an ansatz on the point-force field,
      then proved for every (u, y).
HP-4  For a continuous piecewise-linear load W with nodes t_j and slope jumps c_j (W'' =
      sum c_j delta(t - t_j)), int W(t)/(zeta - t) dt = sum_j c_j K(zeta - t_j) with
      K(v) = v log v - v (two integrations by parts; K'' = 1/v), so W' = sum c_j log(zeta -
      t_j).  One logarithm per (point, node) gives the whole field: this is what the
      evaluator sums.  Checked against the element closed form (HP-1) at 30 digits.
HP-5  Away from the nodes K is analytic: its Taylor coefficients K^(k)(v)/k! = (-1)^k /
      (k (k - 1)) v^(1 - k) for k >= 2 let the evaluator sum far nodes as a power series.
HP-6  The semi-elliptic load sqrt(a^2 - t^2) on (-a, a) -- Hertz's pressure and, times mu,
      the sliding shear of McEwen -- has S(zeta) = int sqrt(a^2 - t^2)/(zeta - t) dt =
      pi (zeta - sqrt(zeta - a) sqrt(zeta + a)): analytic off the contact, pi a^2/(2 zeta) at
      infinity, and with the load's jump across it (Liouville), checked by quadrature.  In
      polar form (rho_k, phi_k of zeta -+ a, phi_k in [-pi, 0]) the field is free of any
      division by zero: y / sqrt(rho_1 rho_2) = sqrt(sin(-phi_1) sin(-phi_2)).  The exact
      Hertz and Jaeger-Ciavarella fields are sums of these.
"""

from __future__ import annotations

import functools

import mpmath
import sympy

from asymslip.codegen import Argument, Derivation

from .solver_influence import flamant_normal, flamant_tangential
from .solver_influence import force as point_force
from .solver_influence import load as point_load
from .solver_influence import x as flamant_x
from .solver_influence import z as flamant_z

x = sympy.Symbol("x", real=True)
y = sympy.Symbol("y", positive=True)
u = sympy.Symbol("u", real=True)
t = sympy.Symbol("t", real=True)
t0, t1 = sympy.symbols("t0 t1", real=True)
p0, p1, q0, q1 = sympy.symbols("p0 p1 q0 q1", real=True)
log_r, angle = sympy.symbols("L theta", real=True)
# Weighted sums over nodes (HP-4): A_f = sum c_j f_j and B_f = sum c_j t_j f_j.
A_L, B_L, A_theta, B_theta, A_1, B_1 = sympy.symbols("A_L B_L A_theta B_theta A_1 B_1", real=True)
k_index = sympy.Symbol("k", integer=True, positive=True)
# Real and imaginary parts of the potentials and of their derivatives (HP-3).
Qr, Qi, Pr, Pi = sympy.symbols("Q_re Q_im P_re P_im", real=True)
dQr, dQi, dPr, dPi = sympy.symbols("dQ_re dQ_im dP_re dP_im", real=True)

COMPONENTS = ("sxx", "syy", "sxy")

POSITION = Argument(x, "Position along the surface, from the contact centre [length].")
DEPTH = Argument(
    y,
    "Depth below the surface into the lower body, y >= 0 [length]; y = 0 gives the surface "
    "limit (principal value).",
)
OFFSET = Argument(u, "Offset x - t_j of the point from the node t_j along the surface [length].")
ELEMENT = (
    Argument(t0, "Left end of the element [length]."),
    Argument(t1, "Right end of the element, t1 > t0 [length]."),
    Argument(p0, "Pressure at t0 (positive pushes into the lower body) [force/length^2]."),
    Argument(p1, "Pressure at t1 [force/length^2]."),
    Argument(q0, "Shear traction at t0, exerted by the indenter along +x [force/length^2]."),
    Argument(q1, "Shear traction at t1 [force/length^2]."),
)
LOG_DISTANCE = Argument(log_r, "L = log|zeta - t_j| = log(u^2 + y^2)/2 (node_log_distance).")
ANGLE = Argument(angle, "theta = arg(zeta - t_j) = atan2(-y, u), in [-pi, 0] (node_angle).")
POTENTIALS = (
    Argument(
        Qr, "Re Q: real part of the shear potential Q = int q(t)/(zeta - t) dt [force/length]."
    ),
    Argument(Qi, "Im Q [force/length]; its surface limit from the body is pi q(x)."),
    Argument(Pi, "Im P of the pressure potential P = int p(t)/(zeta - t) dt; pi p(x) at y = 0."),
    Argument(dQr, "Re dQ/dzeta [force/length^2]."),
    Argument(dQi, "Im dQ/dzeta [force/length^2]."),
    Argument(dPr, "Re dP/dzeta [force/length^2]."),
    Argument(dPi, "Im dP/dzeta [force/length^2]."),
    Argument(y, "Depth y >= 0 of the point [length] (multiplies the derivatives)."),
)


# --- HP-1: the element closed form -------------------------------------------------------------
def _point_kernels() -> dict[tuple[str, str], sympy.Expr]:
    """Unit point-force fields at offset u and depth y: (component, load) -> kernel."""
    swap = {flamant_x: u, flamant_z: y}
    normal = [s.subs(point_load, 1).subs(swap) for s in flamant_normal()]
    tangential = [s.subs(point_force, 1).subs(swap) for s in flamant_tangential()]
    return {
        **{(c, "p"): normal[i] for i, c in enumerate(COMPONENTS)},
        **{(c, "q"): tangential[i] for i, c in enumerate(COMPONENTS)},
    }


@functools.cache
def power_antiderivatives() -> tuple[tuple[sympy.Expr, sympy.Expr, sympy.Expr], ...]:
    """G_k(u) with G_k' = u^k / (u^2 + y^2)^2, k = 0..4, as (rational part, A_k, B_k).

    G_k = R_k(u) + A_k atan(u/y) + B_k log(u^2 + y^2) from an ansatz whose coefficients
    solve G_k' = u^k / r^4, each checked by differentiation.  In
    the element field atan(u/y) is used as atan2(-y, u) + pi/2 (equal for y > 0); the
    constant pi/2 drops out of every element integral G(upper) - G(lower).
    """
    # Ansatz: (alpha u + beta)/(u^2 + y^2) + gamma atan(u/y) + delta log(u^2 + y^2) + eps u,
    # the coefficients solved from G' = integrand (a polynomial identity in u).
    unknowns = sympy.symbols("alpha beta gamma delta epsilon")
    alpha, beta, gamma, delta, epsilon = unknowns
    ansatz = (alpha * u + beta) / (u**2 + y**2) + gamma * sympy.atan(u / y)
    ansatz += delta * sympy.log(u**2 + y**2) + epsilon * u
    results = []
    for k in range(5):
        integrand = u**k / (u**2 + y**2) ** 2
        residual = sympy.numer(sympy.together(sympy.diff(ansatz, u) - integrand))
        equations = sympy.Poly(sympy.expand(residual), u).coeffs()
        (solution,) = sympy.solve(equations, unknowns, dict=True)
        g = ansatz.subs({symbol: solution.get(symbol, 0) for symbol in unknowns})
        assert sympy.cancel(sympy.diff(g, u) - integrand) == 0, f"G_{k} is not an antiderivative"
        g = sympy.expand(g)
        atan_part = g.coeff(sympy.atan(u / y))
        log_part = g.coeff(sympy.log(u**2 + y**2))
        rational = sympy.cancel(
            g - atan_part * sympy.atan(u / y) - log_part * sympy.log(u**2 + y**2)
        )
        assert not rational.has(sympy.atan, sympy.log), f"G_{k} has other functions"
        results.append((rational, atan_part, log_part))
    return tuple(results)


# The element's ends seen from the point: u0 = x - t0, u1 = x - t1 (the length is u0 - u1).
end0, end1 = sympy.symbols("u0 u1", real=True)


@functools.cache
def element_field() -> dict[str, sympy.Expr]:
    """sxx, syy, sxy at (x, y) from the linear element (t0, p0, q0) -> (t1, p1, q1).

    The load at t = x - u is w0 + s (u0 - u), s = (w1 - w0)/(u0 - u1); each kernel times it
    is a polynomial in u over r^4, integrated term by term from u = u1 to u = u0.  Written in
    the offsets u0 = x - t0 and u1 = x - t1 of the ends from the point (no products of
    positions, which would cancel for an element far from the origin); the rational terms
    are cancelled one by one, so that no y^k / y^k is left for y -> 0, and the atan and log
    terms are gathered over one coefficient each.
    """
    G = power_antiderivatives()
    kernels = _point_kernels()
    field: dict[str, sympy.Expr] = {}
    for component in COMPONENTS:
        rational, angles, logs = sympy.S.Zero, sympy.S.Zero, sympy.S.Zero
        for load, (w0, w1) in (("p", (p0, p1)), ("q", (q0, q1))):
            slope = (w1 - w0) / (end0 - end1)
            density = sympy.expand(kernels[(component, load)] * (u**2 + y**2) ** 2)
            weight = w0 + slope * (end0 - u)
            numerator = sympy.Poly(sympy.expand(density * weight), u)
            for (power,), coefficient in numerator.terms():
                R, A, B = G[power]
                for sign, end in ((1, end0), (-1, end1)):
                    rational += sign * sympy.cancel(coefficient * R.subs(u, end))
                angles += coefficient * A
                logs += coefficient * B
        angle_term = sympy.factor(sympy.cancel(angles)) * (
            sympy.atan2(-y, end0) - sympy.atan2(-y, end1)
        )
        log_term = sympy.factor(sympy.cancel(logs)) * (
            sympy.log(end0**2 + y**2) - sympy.log(end1**2 + y**2)
        )
        total = sympy.factor(sympy.cancel(rational)) + angle_term + log_term
        field[component] = total.subs({end0: x - t0, end1: x - t1}, simultaneous=True)
    return field


@functools.cache
def _mp_element_field(component: str, xv: str, yv: str, ends: tuple[str, ...]) -> mpmath.mpf:
    """Independent reference: mpmath quadrature of the Flamant kernels over the element."""
    ta, tb, pa, pb, qa, qb = (mpmath.mpf(v) for v in ends)
    X, Y = mpmath.mpf(xv), mpmath.mpf(yv)
    kp, kq = _mp_kernels(component)

    def integrand(tv: mpmath.mpf) -> mpmath.mpf:
        fraction = (tv - ta) / (tb - ta)
        p = pa + (pb - pa) * fraction
        q = qa + (qb - qa) * fraction
        return p * kp(X - tv, Y) + q * kq(X - tv, Y)

    points = [ta, X, tb] if ta < X < tb else [ta, tb]
    return mpmath.quad(integrand, points)


@functools.cache
def _mp_kernels(component: str) -> tuple[object, object]:
    kernels = _point_kernels()
    return tuple(
        sympy.lambdify((u, y), kernels[(component, load)], "mpmath") for load in ("p", "q")
    )


# --- HP-2: the surface limit -------------------------------------------------------------------
@functools.cache
def surface_field() -> dict[str, sympy.Expr]:
    """The element field at y = 0 (x off the element ends): the limit y -> 0+.

    Every term of the closed form is continuous in y at y = 0 for x != t0, t1 (rational terms in
    y with denominators u^2 + y^2, log(u^2 + y^2), atan2(-y, u) with its limit -pi (u < 0) or 0
    (u > 0) from y > 0), so the limit is the value at y = 0 with atan2(-0, u) taken from above.
    """

    def limit_from_below(expr: sympy.Expr) -> sympy.Expr:
        # atan2(-y, w) -> -pi for w < 0 and 0 for w > 0 as y -> 0+ (SymPy's atan2(0, w) would
        # take the other side's pi).
        return expr.replace(
            lambda e: isinstance(e, sympy.atan2) and e.args[0] == -y,
            lambda e: -sympy.pi / 2 * (1 - sympy.sign(e.args[1])),
        )

    return {c: limit_from_below(e).subs(y, 0) for c, e in element_field().items()}


@functools.cache
def principal_value_shear() -> sympy.Expr:
    """-(2/pi) PV int_{t0}^{t1} q(t)/(x - t) dt for a point inside the element.

    q(t)/(x - t) = q(x)/(x - t) - s with s the load's slope, and the principal value of
    int dt/(x - t) is SymPy's symmetric limit e -> 0 of the integrals over (t0, x - e) and
    (x + e, t1).
    """
    e, below, above = sympy.symbols("e below above", positive=True)  # x - t0, t1 - x
    pole = sympy.integrate(1 / (below - t), (t, 0, below - e)) + sympy.integrate(
        1 / (below - t), (t, below + e, below + above)
    )
    pv = sympy.limit(pole, e, 0, "+").subs({below: x - t0, above: t1 - x})
    slope = (q1 - q0) / (t1 - t0)
    q_here = q0 + slope * (x - t0)
    return -2 / sympy.pi * (q_here * pv - slope * (t1 - t0))


# --- HP-3: stresses from the two potentials ----------------------------------------------------
@functools.cache
def potential_map() -> dict[str, sympy.Expr]:
    """sxx, syy, sxy in terms of Re/Im of Q, P and their derivatives, and the depth y.

    Ansatz on one point force W = q - i p at the origin (f = W/zeta, g = conj(W)/zeta, zeta =
    u - i y): syy - sxx + 2 i sxy = sum c_k b_k over b = (y f', y conj(f'), f, conj(f), g,
    conj(g), y g', y conj(g')); the trace is -(2/pi) Re f.  The complex coefficients c_k are
    solved (exactly, least squares over rationals) from ten sample points, and the identity
    is then proved for all (u, y, p, q).
    """
    pv, qv = sympy.symbols("p q", real=True)
    kernels = _point_kernels()
    sxx = pv * kernels[("sxx", "p")] + qv * kernels[("sxx", "q")]
    syy = pv * kernels[("syy", "p")] + qv * kernels[("syy", "q")]
    sxy = pv * kernels[("sxy", "p")] + qv * kernels[("sxy", "q")]
    W = qv - sympy.I * pv
    zeta = u - sympy.I * y
    f, g = W / zeta, sympy.conjugate(W) / zeta
    df, dg = -W / zeta**2, -sympy.conjugate(W) / zeta**2
    basis = [y * df, y * sympy.conjugate(df), f, sympy.conjugate(f)]
    basis += [g, sympy.conjugate(g), y * dg, y * sympy.conjugate(dg)]
    deviator = syy - sxx + 2 * sympy.I * sxy
    samples = [(3, 2, 1, 0), (-5, 1, 0, 1), (2, 7, -1, 2), (-1, 3, 2, -3), (4, 1, 1, 1)]
    samples += [(-3, 5, -2, 1), (6, 2, 3, -1), (1, 1, -1, -1), (-7, 4, 1, 2), (5, 3, 2, 2)]
    rows, rhs = [], []
    for uv, yv, pvalue, qvalue in samples:
        at = {u: uv, y: yv, pv: pvalue, qv: qvalue}
        values = [complex_parts(b.subs(at)) for b in basis]
        target = complex_parts(sympy.pi * deviator.subs(at))  # the 1/pi of the kernels
        rows.append([re for re, _ in values] + [-im for _, im in values])
        rows.append([im for _, im in values] + [re for re, _ in values])
        rhs += [target[0], target[1]]
    matrix, vector = sympy.Matrix(rows), sympy.Matrix(rhs)
    solution = (matrix.T * matrix).LUsolve(matrix.T * vector)
    n = len(basis)
    found = [(solution[i] + sympy.I * solution[n + i]) / sympy.pi for i in range(n)]
    # Proof for all (u, y, p, q): the residual's real and imaginary parts cancel identically.
    residual = sympy.expand_complex(
        deviator - sum(c * b for c, b in zip(found, basis, strict=True))
    )
    assert sympy.cancel(sympy.re(residual)) == 0 and sympy.cancel(sympy.im(residual)) == 0
    trace = sympy.expand_complex(sxx + syy + 2 / sympy.pi * sympy.re(f))
    assert sympy.cancel(trace) == 0
    # For a distributed load, f, g become F = Q - i P and G = Q + i P (Q, P the Cauchy
    # integrals of q and p); write the map in their real and imaginary parts.
    F = (Qr + sympy.I * Qi) - sympy.I * (Pr + sympy.I * Pi)
    G = (Qr + sympy.I * Qi) + sympy.I * (Pr + sympy.I * Pi)
    dF = (dQr + sympy.I * dQi) - sympy.I * (dPr + sympy.I * dPi)
    dG = (dQr + sympy.I * dQi) + sympy.I * (dPr + sympy.I * dPi)
    images = [y * dF, y * sympy.conjugate(dF), F, sympy.conjugate(F)]
    images += [G, sympy.conjugate(G), y * dG, y * sympy.conjugate(dG)]
    total = sympy.expand_complex(sum(c * b for c, b in zip(found, images, strict=True)))
    difference, shear2 = sympy.re(total), sympy.im(total)
    trace_value = -2 / sympy.pi * sympy.re(sympy.expand_complex(F))
    return {
        "sxx": sympy.expand((trace_value - difference) / 2),
        "syy": sympy.expand((trace_value + difference) / 2),
        "sxy": sympy.expand(shear2 / 2),
    }


def complex_parts(value: sympy.Expr) -> tuple[sympy.Expr, sympy.Expr]:
    """(Re, Im) of an exact complex number."""
    expanded = sympy.expand_complex(value)
    return sympy.re(expanded), sympy.im(expanded)


# --- HP-4: the node kernel ---------------------------------------------------------------------
def node_kernel(v: sympy.Expr) -> sympy.Expr:
    """K(v) = v log v - v, the second antiderivative of 1/v."""
    return v * sympy.log(v) - v


@functools.cache
def node_kernel_parts() -> tuple[sympy.Expr, sympy.Expr]:
    """Re and Im of K(zeta - t_j) in terms of u = x - t_j, y, L = log|v| and theta = arg v."""
    v = u - sympy.I * y
    value = sympy.expand(v * (log_r + sympy.I * angle) - v)
    return sympy.re(value), sympy.im(value)


def _mp_node_field(component: str, xv: str, yv: str, ends: tuple[str, ...]) -> mpmath.mpf:
    """The element field by HP-3 and HP-4: slope jumps of the element's load, summed over K."""
    ta, tb, pa, pb, qa, qb = (mpmath.mpf(v) for v in ends)
    zeta = mpmath.mpc(mpmath.mpf(xv), -mpmath.mpf(yv))

    def potentials(wa: mpmath.mpf, wb: mpmath.mpf) -> tuple[mpmath.mpc, mpmath.mpc]:
        # The element's load as a ramp sum: slope jumps and value jumps at the two ends.  A
        # value jump w at a node contributes w (log v) to the potential (the integral of a
        # step), which the ends of a lone element carry.
        slope = (wb - wa) / (tb - ta)
        value = slope * node_kernel_mp(zeta - ta) - slope * node_kernel_mp(zeta - tb)
        value += wa * mpmath.log(zeta - ta) - wb * mpmath.log(zeta - tb)
        derivative = slope * (mpmath.log(zeta - ta) - mpmath.log(zeta - tb))
        derivative += wa / (zeta - ta) - wb / (zeta - tb)
        return value, derivative

    Q, dQ = potentials(qa, qb)
    P, dP = potentials(pa, pb)
    values = {
        Qr: Q.real,
        Qi: Q.imag,
        Pi: P.imag,
        dQr: dQ.real,
        dQi: dQ.imag,
        dPr: dP.real,
        dPi: dP.imag,
        y: mpmath.mpf(yv),
    }
    expression = potential_map()[component]
    return sympy.lambdify(list(values), expression, "mpmath")(*values.values())


def node_kernel_mp(v: mpmath.mpc) -> mpmath.mpc:
    return v * mpmath.log(v) - v


@functools.cache
def node_sums() -> tuple[sympy.Expr, sympy.Expr]:
    """Re and Im of sum_j c_j K(zeta - t_j) in the weighted sums of L_j and theta_j.

    With u_j = x - t_j the node kernel's parts are linear in u_j, so the sum over nodes needs
    only A_f = sum c_j f_j and B_f = sum c_j t_j f_j for f = L, theta and 1: two matrix
    products instead of four kernel evaluations per (point, node).  Proved by summing three
    symbolic nodes.
    """
    real, imaginary = node_kernel_parts()
    real_sum = x * A_L - B_L + y * A_theta - x * A_1 + B_1
    imaginary_sum = x * A_theta - B_theta - y * A_L + y * A_1
    nodes = sympy.symbols("s0:3", real=True)
    weights = sympy.symbols("w0:3", real=True)
    logs = sympy.symbols("l0:3", real=True)
    angles = sympy.symbols("h0:3", real=True)
    sums = {
        A_L: sum(w * lv for w, lv in zip(weights, logs, strict=True)),
        B_L: sum(w * s * lv for w, s, lv in zip(weights, nodes, logs, strict=True)),
        A_theta: sum(w * h for w, h in zip(weights, angles, strict=True)),
        B_theta: sum(w * s * h for w, s, h in zip(weights, nodes, angles, strict=True)),
        A_1: sum(weights),
        B_1: sum(w * s for w, s in zip(weights, nodes, strict=True)),
    }
    for part, total in ((real, real_sum), (imaginary, imaginary_sum)):
        direct = sum(
            w * part.subs({u: x - s, log_r: lv, angle: h})
            for w, s, lv, h in zip(weights, nodes, logs, angles, strict=True)
        )
        assert sympy.expand(direct - total.subs(sums)) == 0, "node sums disagree"
    return real_sum, imaginary_sum


# --- HP-5: the far-field series ------------------------------------------------------------------
@functools.cache
def series_factor() -> sympy.Expr:
    """K^(k)(v)/k! = factor(k) v^(1 - k) for k >= 2: factor(k) = (-1)^k / (k (k - 1))."""
    return (-1) ** k_index / (k_index * (k_index - 1))


# --- HP-6: the semi-elliptic load ---------------------------------------------------------------
half_width = sympy.Symbol("a", positive=True)
rho1, rho2 = sympy.symbols("rho1 rho2", nonnegative=True)
phi1, phi2 = sympy.symbols("phi1 phi2", real=True)


@functools.cache
def semi_ellipse_polar() -> dict[str, sympy.Expr]:
    """Re and Im of S and of y S' in the polar coordinates of zeta - a and zeta + a.

    sqrt(zeta - a) sqrt(zeta + a) = sqrt(rho1 rho2) exp(i (phi1 + phi2)/2) (principal roots:
    both angles in [-pi, 0] below the surface), and y S' = pi (y - zeta y / R) with
    y / |R| = sqrt(sin(-phi1) sin(-phi2)) (y = rho_k sin(-phi_k) for k = 1, 2).
    """
    zeta = x - sympy.I * y
    half = (phi1 + phi2) / 2
    root = sympy.sqrt(rho1 * rho2) * (sympy.cos(half) + sympy.I * sympy.sin(half))
    S = sympy.pi * (zeta - root)
    ratio = sympy.Symbol("ratio", nonnegative=True)  # y / |R|, real: expanded as a symbol
    y_slope = sympy.pi * (y - zeta * ratio * (sympy.cos(half) - sympy.I * sympy.sin(half)))
    S, y_slope = sympy.expand_complex(S), sympy.expand_complex(y_slope)
    # sin(-phi_k) >= 0 for phi_k in [-pi, 0]: the product's root is real.
    value = sympy.sqrt(sympy.sin(-phi1) * sympy.sin(-phi2))
    return {
        "S_re": sympy.re(S),
        "S_im": sympy.im(S),
        "yS_re": sympy.re(y_slope).subs(ratio, value),
        "yS_im": sympy.im(y_slope).subs(ratio, value),
    }


def _polar_values(xv: mpmath.mpf, yv: mpmath.mpf, av: mpmath.mpf) -> dict[sympy.Symbol, object]:
    return {
        rho1: mpmath.hypot(xv - av, yv),
        rho2: mpmath.hypot(xv + av, yv),
        phi1: mpmath.atan2(-yv, xv - av),
        phi2: mpmath.atan2(-yv, xv + av),
    }


def polar_coordinates() -> dict[sympy.Symbol, sympy.Expr]:
    """rho_k and phi_k as functions of (x, y, a), for the emitted code.

    The angles are kept unevaluated: SymPy would otherwise rewrite sin(atan2(-y, X)) as
    -y / rho and bring back the division by zero at the load's ends that the polar form
    avoids.
    """
    return {
        rho1: sympy.sqrt((x - half_width) ** 2 + y**2),
        rho2: sympy.sqrt((x + half_width) ** 2 + y**2),
        phi1: sympy.UnevaluatedExpr(sympy.atan2(-y, x - half_width)),
        phi2: sympy.UnevaluatedExpr(sympy.atan2(-y, x + half_width)),
    }


@functools.cache
def semi_ellipse_fields() -> dict[tuple[str, str], sympy.Expr]:
    """(component, load) -> the field of the load sqrt(a^2 - t^2) as pressure or shear."""
    parts = semi_ellipse_polar()
    mapping = potential_map()
    fields = {}
    for load in ("p", "q"):
        if load == "p":  # P = S, Q = 0
            values = {Qr: 0, Qi: 0, Pi: parts["S_im"], dQr: 0, dQi: 0}
            values |= {dPr: parts["yS_re"] / y, dPi: parts["yS_im"] / y}
        else:  # Q = S, P = 0
            values = {Qr: parts["S_re"], Qi: parts["S_im"], Pi: 0, dPr: 0, dPi: 0}
            values |= {dQr: parts["yS_re"] / y, dQi: parts["yS_im"] / y}
        for component in COMPONENTS:
            expr = sympy.expand(mapping[component].subs(values))
            assert not expr.has(1 / y), "the depth did not cancel"
            fields[(component, load)] = expr.subs(polar_coordinates())
    return fields


def _mp_semi_ellipse_potential(xv: str, yv: str, av: str, part: str) -> mpmath.mpf:
    """Independent reference: S and y S' by quadrature of the Cauchy integrals."""
    X, Y, A = mpmath.mpf(xv), mpmath.mpf(yv), mpmath.mpf(av)
    zeta = mpmath.mpc(X, -Y)
    if part.startswith("S"):
        value = mpmath.quad(lambda tv: mpmath.sqrt(A**2 - tv**2) / (zeta - tv), [-A, A])
    else:  # y S' = -y int sqrt(a^2 - t^2)/(zeta - t)^2 dt
        value = -Y * mpmath.quad(lambda tv: mpmath.sqrt(A**2 - tv**2) / (zeta - tv) ** 2, [-A, A])
    return value.real if part.endswith("re") else value.imag


def _mp_semi_ellipse_polar(xv: str, yv: str, av: str, part: str) -> mpmath.mpf:
    values = _polar_values(mpmath.mpf(xv), mpmath.mpf(yv), mpmath.mpf(av))
    values.update({x: mpmath.mpf(xv), y: mpmath.mpf(yv)})
    expr = semi_ellipse_polar()[part]
    return sympy.lambdify(list(values), expr, "mpmath")(*values.values())


SAMPLE_ELEMENTS = [
    ("0.3", "0.2", ("-0.4", "0.9", "1.3", "0.7", "0.25", "-0.6")),
    ("2.5", "0.05", ("-0.4", "0.9", "1.3", "0.7", "0.25", "-0.6")),
    ("-1.7", "1.9", ("0.1", "0.35", "-2", "3", "0.5", "0.125")),
    ("0.2", "0.001", ("0.1", "0.35", "-2", "3", "0.5", "0.125")),
]


def derive() -> Derivation:
    d = Derivation(__file__)
    d.describe_module(
        "half_plane_stress",
        "The plane-strain stress field of the lower half-plane (depth y >= 0) under surface "
        "tractions exerted by the indenter -- pressure p into the body, shear q along +x -- "
        "from Flamant's point-force solution: the closed form of one linear element, its "
        "surface limit (principal value), and the potential form the evaluator of "
        "asymslip.stress sums (beyond the paper; issue 18).",
    )
    field = element_field()
    with d.equation("HP-1", "Field of a linear surface-traction element") as eq:
        eq.beyond_paper(
            "Flamant's point-force fields (F-1) integrated over a linear load on [t0, t1] in "
            "closed form: the integrals of u^k/(u^2 + y^2)^2, k = 0..4, each checked by "
            "differentiation, with atan(u/y) written as atan2(-y, u) + pi/2",
            derived=field["sxx"],
        )
        for component in COMPONENTS:
            function = sympy.lambdify((x, y, t0, t1, p0, p1, q0, q1), field[component], "mpmath")
            eq.matches_numerically(
                lambda xv, yv, ends, f=function: f(
                    mpmath.mpf(xv), mpmath.mpf(yv), *(mpmath.mpf(v) for v in ends)
                ),
                lambda xv, yv, ends, c=component: _mp_element_field(c, xv, yv, ends),
                [{"xv": a, "yv": b, "ends": e} for a, b, e in SAMPLE_ELEMENTS],
                how=f"{component}: mpmath quadrature of the point-force kernels over the element",
                digits=16,
                symbolic=True,
            )
    surface = surface_field()
    with d.equation("HP-2", "Surface limit of the element field (principal value)") as eq:
        inside = {t0: -1, t1: 2, x: sympy.Rational(1, 3)}
        fraction = (x - t0) / (t1 - t0)
        p_here = (p0 + (p1 - p0) * fraction).subs(inside)
        q_here = (q0 + (q1 - q0) * fraction).subs(inside)
        eq.holds(
            surface["syy"].subs(inside) + p_here,
            how="inside the element syy -> -p(x) as y -> 0+",
        )
        eq.holds(
            surface["sxy"].subs(inside) + q_here,
            how="inside the element sxy -> -q(x) as y -> 0+",
        )
        eq.holds(
            surface["sxx"].subs(inside) + p_here - principal_value_shear().subs(inside),
            how="inside the element sxx -> -p(x) - (2/pi) PV int q(t)/(x - t) dt (SymPy's "
            "symmetric principal value of the linear load)",
        )
        outside = {t0: -1, t1: 2, x: 5}
        eq.holds(surface["syy"].subs(outside), how="outside the element syy -> 0")
        eq.holds(surface["sxy"].subs(outside), how="outside the element sxy -> 0")
        q_line = q0 + (q1 - q0) * (t - t0) / (t1 - t0)
        ordinary = (
            -2 / sympy.pi * sympy.integrate(q_line.subs({t0: -1, t1: 2}) / (5 - t), (t, -1, 2))
        )
        eq.holds(
            surface["sxx"].subs(outside) - ordinary,
            how="outside the element sxx -> -(2/pi) int q(t)/(x - t) dt (an ordinary integral)",
        )
        depth_small = sympy.lambdify((x, y, t0, t1, p0, p1, q0, q1), field["sxx"], "mpmath")
        at_surface = sympy.lambdify((x, t0, t1, p0, p1, q0, q1), surface["sxx"], "mpmath")
        with mpmath.workdps(40):
            gap = abs(
                depth_small(mpmath.mpf("0.3"), mpmath.mpf("1e-25"), -1, 2, 1, 3, 2, -1)
                - at_surface(mpmath.mpf("0.3"), -1, 2, 1, 3, 2, -1)
            )
        assert gap < mpmath.mpf("1e-20"), f"the y -> 0 limit is not continuous: {gap}"
        eq.details.append(
            "the closed form at y = 1e-25 equals its value at y = 0 to 1e-20 (40 digits)"
        )
    mapping = potential_map()
    with d.equation("HP-3", "Stresses from the pressure and shear potentials") as eq:
        eq.beyond_paper(
            "syy - sxx + 2 i sxy = (2/pi) (i y conj(Q' - i P') + conj(Q)), sxx + syy = "
            "-(2/pi) Re(Q - i P), Q and P the Cauchy integrals of q and p at zeta = x - i y: "
            "coefficients solved from an ansatz on the point-force field and proved for "
            "every (u, y, p, q)",
            derived=mapping["sxx"],
        )
        eq.holds(
            mapping["syy"].subs(y, 0) + Pi / sympy.pi,
            how="at y = 0, syy = -Im P/pi = -p (Im P -> pi p from the body's side)",
        )
        eq.holds(
            mapping["sxy"].subs(y, 0) + Qi / sympy.pi,
            how="at y = 0, sxy = -Im Q/pi = -q",
        )
    with d.equation("HP-4", "Node potentials of a piecewise-linear load") as eq:
        v = sympy.Symbol("v", positive=True)
        eq.holds(
            sympy.diff(node_kernel(v), v, 2) - 1 / v,
            how="K(v) = v log v - v has K'' = 1/v, so int W/(zeta - t) dt = sum_j c_j "
            "K(zeta - t_j) for W'' = sum_j c_j delta(t - t_j) (two integrations by parts)",
            derived=node_kernel(v),
        )
        for component in COMPONENTS:
            eq.matches_numerically(
                lambda xv, yv, ends, c=component: _mp_node_field(c, xv, yv, ends),
                lambda xv, yv, ends, c=component: _mp_element_field(c, xv, yv, ends),
                [{"xv": a, "yv": b, "ends": e} for a, b, e in SAMPLE_ELEMENTS],
                how=f"{component} from the node potentials (HP-3, HP-4) against quadrature",
                digits=16,
                symbolic=True,
            )
        real_sum, imaginary_sum = node_sums()
        eq.details.append(
            "sum_j c_j K(zeta - t_j) = (x A_L - B_L + y A_theta - x A_1 + B_1) + i (x A_theta "
            "- B_theta - y A_L + y A_1), A_f = sum c_j f_j, B_f = sum c_j t_j f_j: proved by "
            "summing three symbolic nodes"
        )
    with d.equation("HP-5", "Taylor coefficients of the node kernel") as eq:
        v = sympy.Symbol("v", positive=True)
        for order in range(2, 8):
            derivative = sympy.diff(node_kernel(v), v, order) / sympy.factorial(order)
            eq.holds(
                derivative - series_factor().subs(k_index, order) * v ** (1 - order),
                how=f"K^({order})(v)/{order}! = factor({order}) v^{1 - order}",
            )
        eq.holds(
            sympy.powsimp(
                sympy.diff(series_factor() * v ** (1 - k_index), v)
                - (k_index + 1) * series_factor().subs(k_index, k_index + 1) * v ** (-k_index)
            ),
            how="d/dv of the order-k term is (k + 1) times the order-(k + 1) term: the "
            "pattern holds for every k >= 2",
            derived=series_factor(),
        )
    with d.equation("HP-6", "Field of a semi-elliptic surface load") as eq:
        parts = semi_ellipse_polar()
        big = sympy.Symbol("R_big", positive=True)
        far = {rho1: big, rho2: big, phi1: 0, phi2: 0, x: big, y: 0}
        eq.beyond_paper(
            "S(zeta) = int sqrt(a^2 - t^2)/(zeta - t) dt = pi (zeta - sqrt(zeta - a) sqrt(zeta + "
            "a)), analytic off (-a, a) and O(1/zeta) at infinity; its boundary value from "
            "below has Im S = pi sqrt(a^2 - x^2) on the load and 0 off it (the Sokhotski jump "
            "of the load), so by Liouville it is the Cauchy integral",
            derived=parts["S_re"],
        )
        third = half_width / 3  # a point inside the load
        inside = {rho1: half_width - third, rho2: half_width + third, phi1: -sympy.pi}
        inside |= {phi2: 0, y: 0, x: third}
        eq.holds(
            parts["S_im"].subs(inside) - sympy.pi * sympy.sqrt(half_width**2 - third**2),
            how="on the surface inside the load, Im S = pi sqrt(a^2 - x^2) (the load)",
        )
        outside = {rho1: x - half_width, rho2: x + half_width, phi1: 0, phi2: 0, y: 0}
        eq.holds(parts["S_im"].subs(outside), how="on the surface beyond x = a, Im S = 0")
        eq.holds(
            parts["S_re"].subs(far),
            how="the zeta term cancels at infinity (S = O(1/zeta))",
        )
        for part in ("S_re", "S_im", "yS_re", "yS_im"):
            eq.matches_numerically(
                lambda xv, yv, av, p=part: _mp_semi_ellipse_polar(xv, yv, av, p),
                lambda xv, yv, av, p=part: _mp_semi_ellipse_potential(xv, yv, av, p),
                [
                    {"xv": "0.3", "yv": "0.2", "av": "1"},
                    {"xv": "-1.6", "yv": "0.7", "av": "1.25"},
                    {"xv": "0.99", "yv": "0.003", "av": "1"},
                ],
                how=f"{part} in polar form against quadrature of the Cauchy integral",
                digits=16,
                symbolic=True,
            )
    arguments = (POSITION, DEPTH, *ELEMENT)
    names = {"sxx": "sxx, along the surface", "syy": "syy, normal to it", "sxy": "sxy"}
    for component in COMPONENTS:
        d.emit(
            name=f"half_plane_element_{component}",
            args=arguments,
            expr=field[component],
            equations=("F-1", "HP-1", "HP-2"),
            summary=f"Stress {names[component]}, at (x, y) from one linear traction element.",
            doc="The lower half-plane under a pressure p and a shear traction q varying linearly "
            "from (p0, q0) at t0 to (p1, q1) at t1, both exerted by the indenter; tension "
            "positive, plane strain.  Valid for y > 0, and at y = 0 (the surface limit, "
            "principal value) for x != t0, t1; well conditioned within a few element lengths "
            "of the element, while far from it the terms of its two ends cancel.  For many "
            "elements use the node potentials (asymslip.stress sums them).",
            module="half_plane_stress",
            returns=f"{component} [force/length^2].",
        )
    node_arguments = (OFFSET, DEPTH)
    d.emit(
        name="half_plane_node_log_distance",
        args=node_arguments,
        expr=sympy.log(u**2 + y**2) / 2,
        equations=("HP-4",),
        summary="L = log|zeta - t_j| of a node, zeta = x - i y.",
        doc="Real part of log(zeta - t_j); infinite at the node itself on the surface (u = y "
        "= 0), where every term it enters vanishes (the evaluator passes a finite value there).",
        module="half_plane_stress",
        returns="L [log of a length].",
    )
    d.emit(
        name="half_plane_node_angle",
        args=node_arguments,
        expr=sympy.atan2(-y, u),
        equations=("HP-4",),
        summary="theta = arg(zeta - t_j) of a node, in [-pi, 0].",
        doc="Imaginary part of log(zeta - t_j), zeta = x - i y: -pi for a surface point left "
        "of the node (u < 0, y = +0), 0 right of it: the limit from inside the body.  y must "
        "be +0.0 on the surface, not -0.0.",
        module="half_plane_stress",
        returns="theta [rad].",
    )
    real_part, imaginary_part = node_kernel_parts()
    for part, expr in (("real", real_part), ("imag", imaginary_part)):
        d.emit(
            name=f"half_plane_node_potential_{part}",
            args=(OFFSET, DEPTH, LOG_DISTANCE, ANGLE),
            expr=expr,
            equations=("HP-4",),
            summary=f"{'Re' if part == 'real' else 'Im'} K(zeta - t_j), K(v) = v log v - v.",
            doc="The node kernel of a piecewise-linear load: its potential is sum_j c_j K(zeta "
            "- t_j) with c_j the load's slope jump at node t_j; L and theta from "
            "half_plane_node_log_distance and half_plane_node_angle.",
            module="half_plane_stress",
            returns="[length].",
        )
    sum_arguments = {
        A_L: Argument(A_L, "A_L = sum_j c_j L_j over the nodes summed [force/length]."),
        B_L: Argument(B_L, "B_L = sum_j c_j t_j L_j [force]."),
        A_theta: Argument(A_theta, "A_theta = sum_j c_j theta_j [force/length]."),
        B_theta: Argument(B_theta, "B_theta = sum_j c_j t_j theta_j [force]."),
        A_1: Argument(A_1, "A_1 = sum_j c_j [force/length]."),
        B_1: Argument(B_1, "B_1 = sum_j c_j t_j [force]."),
    }
    point = Argument(x, "Position of the point, in the frame of the node positions t_j [length].")
    for part, expr, sum_names in (
        ("real", real_sum, (A_L, B_L, A_theta, A_1, B_1)),
        ("imag", imaginary_sum, (A_theta, B_theta, A_L, A_1)),
    ):
        d.emit(
            name=f"half_plane_node_sum_{part}",
            args=(point, DEPTH, *(sum_arguments[n] for n in sum_names)),
            expr=expr,
            equations=("HP-4",),
            summary=f"{'Re' if part == 'real' else 'Im'} sum_j c_j K(zeta - t_j) from weighted "
            "sums over the nodes.",
            doc="The potential of a piecewise-linear load (slope jumps c_j at nodes t_j) at zeta "
            "= x - i y, from A_f = sum c_j f_j and B_f = sum c_j t_j f_j with f = L_j = "
            "log|zeta - t_j|, theta_j = arg(zeta - t_j) and 1.  Keep x and t_j small (a local "
            "origin near the point): x A_L - B_L cancels where |x - t_j| << |t_j|.",
            module="half_plane_stress",
            returns="[force/length].",
        )
    for component in COMPONENTS:
        d.emit(
            name=f"half_plane_potential_{component}",
            args=POTENTIALS,
            expr=mapping[component],
            equations=("F-1", "HP-3"),
            summary=f"Stress {names[component]}, from the pressure and shear potentials.",
            doc="Q = int q(t)/(zeta - t) dt and P = int p(t)/(zeta - t) dt at zeta = x - i y "
            "(tractions exerted by the indenter on the lower body): the whole plane-strain "
            "field at depth y >= 0, tension positive.  Re P does not enter.",
            module="half_plane_stress",
            returns=f"{component} [force/length^2].",
        )
    ellipse = semi_ellipse_fields()
    loads = {"p": "pressure", "q": "shear traction"}
    for (component, load), expr in ellipse.items():
        d.emit(
            name=f"semi_ellipse_{loads[load].split()[0]}_{component}",
            args=(
                Argument(x, "Position along the surface from the load's centre [length]."),
                DEPTH,
                Argument(half_width, "Half-width a > 0 of the load [length]."),
            ),
            expr=expr,
            equations=("HP-3", "HP-6", "48"),
            summary=f"Stress {names[component]}, under the {loads[load]} sqrt(a^2 - x^2).",
            doc=f"The lower half-plane under the semi-elliptic {loads[load]} sqrt(a^2 - t^2) on "
            "(-a, a), exerted by the indenter (per unit amplitude: Hertz's (48) is p0/a times "
            "it, McEwen's sliding shear mu p0/a times it); tension positive, plane strain; "
            "any y >= 0, finite everywhere (polar form).",
            module="half_plane_stress",
            returns=f"{component} per unit load amplitude [length].",
        )
    d.emit(
        name="half_plane_node_series_factor",
        args=(Argument(k_index, "Order k >= 2 of the Taylor term."),),
        expr=series_factor(),
        equations=("HP-5",),
        summary="K^(k)(v)/k! divided by v^(1 - k): (-1)^k / (k (k - 1)).",
        doc="Taylor coefficients of the node kernel about a far centre v0: K(v0 + d) = K(v0) + "
        "log(v0) d + sum_{k >= 2} factor(k) v0^(1 - k) d^k, convergent for |d| < |v0|.",
        module="half_plane_stress",
        returns="The factor (dimensionless).",
    )
    return d
