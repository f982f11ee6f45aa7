"""The stress field's generated functions against 50-digit references written by hand.

Independent of the derivations: Flamant's point-force fields (Johnson, Contact Mechanics, Sec.
2.2) integrated by mpmath quadrature over the loads, and the node kernel K(v) = v log v - v in
mpmath's complex arithmetic.  The harness's problems feed positions and lengths: x = x_contact
(log-uniform in its distance from the edge a2), the depth a2 - x_contact (so that points
crowd the surface near the edge, the hardest place), and the half-widths a1, a2 as scales.
"""

from __future__ import annotations

import mpmath
import numpy as np

from .registry import Quantity, register_quantity

pi = mpmath.pi
COMPONENTS = ("sxx", "syy", "sxy")
ARGS = ("x=x_contact", "a1", "a2")


def _flamant(load, lo, hi, x, y, component: str) -> mpmath.mpf:
    """The field of the surface load ``load(t)`` (a pair p, q) on (lo, hi) at (x, y)."""
    index = COMPONENTS.index(component)

    def integrand(t):
        u = x - t
        p, q = load(t)
        kernels = (
            y * p * u * u + q * u**3,
            y**3 * p + y * y * q * u,
            y * y * p * u + y * q * u * u,
        )
        return -2 / pi * kernels[index] / (u * u + y * y) ** 2

    return mpmath.quad(integrand, [lo, x, hi] if lo < x < hi else [lo, hi])


def _element(a1, a2):
    """A linear element of the problem's scale: (t0, t1, p0, p1, q0, q1)."""
    return a1 / 2, a1, a2, a1, a1 - a2, a2 / 3


def _element_compose(component: str):
    def compose(x, a1, a2):
        from asymslip_gen import half_plane_stress

        function = getattr(half_plane_stress, f"half_plane_element_{component}")
        return function(x, a2 - x, *_element(a1, a2))

    return compose


def _element_reference(component: str):
    def reference(x, a1, a2):
        t0, t1, p0, p1, q0, q1 = _element(a1, a2)

        def load(t):
            f = (t - t0) / (t1 - t0)
            return p0 + (p1 - p0) * f, q0 + (q1 - q0) * f

        return _flamant(load, t0, t1, x, a2 - x, component)

    return reference


for _component in COMPONENTS:
    register_quantity(
        Quantity(
            f"half_plane_stress.half_plane_element_{_component}",
            ARGS,
            _element_reference(_component),
            ("HP-1",),
            laws=("hertz",),
            compose=_element_compose(_component),
            every=4,
            costly=True,
        )
    )


def _kernel(v):
    return v * mpmath.log(v) - v


def _node_point(x, a1, a2):
    """A node offset u and a depth y from the problem."""
    return x - a1 / 2, a2 - x


def _log_distance_compose(x, a1, a2):
    from asymslip_gen import half_plane_stress as g

    return g.half_plane_node_log_distance(*_node_point(x, a1, a2))


def _angle_compose(x, a1, a2):
    from asymslip_gen import half_plane_stress as g

    return g.half_plane_node_angle(*_node_point(x, a1, a2))


def _node_value(x, a1, a2) -> mpmath.mpc:
    u, y = _node_point(x, a1, a2)
    return mpmath.mpc(u, -y)


register_quantity(
    Quantity(
        "half_plane_stress.half_plane_node_log_distance",
        ARGS,
        lambda x, a1, a2: mpmath.log(abs(_node_value(x, a1, a2))),
        ("HP-4",),
        compose=_log_distance_compose,
    )
)
register_quantity(
    Quantity(
        "half_plane_stress.half_plane_node_angle",
        ARGS,
        lambda x, a1, a2: mpmath.arg(_node_value(x, a1, a2)),
        ("HP-4",),
        compose=_angle_compose,
    )
)


def _node_potential(part: str):
    def compose(x, a1, a2):
        from asymslip_gen import half_plane_stress as g

        u, y = _node_point(x, a1, a2)
        L, theta = g.half_plane_node_log_distance(u, y), g.half_plane_node_angle(u, y)
        return getattr(g, f"half_plane_node_potential_{part}")(u, y, L, theta)

    def reference(x, a1, a2):
        u, y = _node_point(x, a1, a2)
        value = _kernel(mpmath.mpc(u, -y))
        return value.real if part == "real" else value.imag

    return compose, reference


for _part in ("real", "imag"):
    _compose, _reference = _node_potential(_part)
    register_quantity(
        Quantity(
            f"half_plane_stress.half_plane_node_potential_{_part}",
            ARGS,
            _reference,
            ("HP-4",),
            compose=_compose,
        )
    )


def _hat(a1, a2):
    """A hat load on three nodes: nodes, pressures, shears (zero at both ends)."""
    return (a1 / 5, 3 * a1 / 5, a1), (0, a2, 0), (0, -a1 / 3, 0)


def _slope_jumps(nodes, values):
    s1 = (values[1] - values[0]) / (nodes[1] - nodes[0])
    s2 = (values[2] - values[1]) / (nodes[2] - nodes[1])
    return (s1, s2 - s1, -s2)


def _hat_sums(x, y, a1, a2, which: str):
    """The weighted sums A_f, B_f of the hat's shear (or pressure) at (x, y), in doubles,
    with the origin at the point (as the evaluator takes it, near the points: x = 0)."""
    from asymslip_gen import half_plane_stress as g

    nodes, pressure, shear = _hat(a1, a2)
    c = _slope_jumps(nodes, shear if which == "q" else pressure)
    sums = dict.fromkeys(("A_L", "B_L", "A_theta", "B_theta", "A_1", "B_1"), 0.0)
    for node, weight in zip(nodes, c, strict=True):
        t = node - x  # the node from the point
        L, theta = g.half_plane_node_log_distance(-t, y), g.half_plane_node_angle(-t, y)
        sums["A_L"] = sums["A_L"] + weight * L
        sums["B_L"] = sums["B_L"] + weight * t * L
        sums["A_theta"] = sums["A_theta"] + weight * theta
        sums["B_theta"] = sums["B_theta"] + weight * t * theta
        sums["A_1"] = sums["A_1"] + weight
        sums["B_1"] = sums["B_1"] + weight * t
    return sums


def _hat_potential_mp(x, y, a1, a2, which: str) -> tuple[mpmath.mpc, mpmath.mpc]:
    """sum c_j K(zeta - t_j) and sum c_j log(zeta - t_j) of the hat, in mpmath."""
    nodes, pressure, shear = _hat(a1, a2)
    c = _slope_jumps(nodes, shear if which == "q" else pressure)
    zeta = mpmath.mpc(x, -y)
    value = sum(w * _kernel(zeta - t) for t, w in zip(nodes, c, strict=True))
    slope = sum(w * mpmath.log(zeta - t) for t, w in zip(nodes, c, strict=True))
    return value, slope


def _node_sum(part: str):
    def compose(x, a1, a2):
        from asymslip_gen import half_plane_stress as g

        s = _hat_sums(x, a2 - x, a1, a2, "q")
        zero = np.zeros_like(x)  # the point is the origin
        if part == "real":
            return g.half_plane_node_sum_real(
                zero, a2 - x, s["A_L"], s["B_L"], s["A_theta"], s["A_1"], s["B_1"]
            )
        return g.half_plane_node_sum_imag(
            zero, a2 - x, s["A_theta"], s["B_theta"], s["A_L"], s["A_1"]
        )

    def reference(x, a1, a2):
        value, _ = _hat_potential_mp(x, a2 - x, a1, a2, "q")
        return value.real if part == "real" else value.imag

    return compose, reference


for _part in ("real", "imag"):
    _compose, _reference = _node_sum(_part)
    register_quantity(
        Quantity(
            f"half_plane_stress.half_plane_node_sum_{_part}",
            ARGS,
            _reference,
            ("HP-4",),
            compose=_compose,
        )
    )


def _potential_stress(component: str):
    def compose(x, a1, a2):
        from asymslip_gen import half_plane_stress as g

        y = a2 - x
        zero = np.zeros_like(x)  # the point is the origin
        parts = {}
        for which in ("q", "p"):
            s = _hat_sums(x, y, a1, a2, which)
            parts[which] = (
                g.half_plane_node_sum_real(
                    zero, y, s["A_L"], s["B_L"], s["A_theta"], s["A_1"], s["B_1"]
                ),
                g.half_plane_node_sum_imag(zero, y, s["A_theta"], s["B_theta"], s["A_L"], s["A_1"]),
                s["A_L"],
                s["A_theta"],
            )
        (Qr, Qi, dQr, dQi), (_, Pi, dPr, dPi) = parts["q"], parts["p"]
        function = getattr(g, f"half_plane_potential_{component}")
        return function(Qr, Qi, Pi, dQr, dQi, dPr, dPi, y)

    def reference(x, a1, a2):
        nodes, pressure, shear = _hat(a1, a2)

        def hat(values):
            def value(t):
                if t <= nodes[1]:
                    return values[1] * (t - nodes[0]) / (nodes[1] - nodes[0])
                return values[1] * (nodes[2] - t) / (nodes[2] - nodes[1])

            return value

        p, q = hat(pressure), hat(shear)
        y = a2 - x
        return sum(
            _flamant(lambda t: (p(t), q(t)), lo, hi, x, y, component)
            for lo, hi in ((nodes[0], nodes[1]), (nodes[1], nodes[2]))
        )

    return compose, reference


for _component in COMPONENTS:
    _compose, _reference = _potential_stress(_component)
    register_quantity(
        Quantity(
            f"half_plane_stress.half_plane_potential_{_component}",
            ARGS,
            _reference,
            ("HP-3", "HP-4"),
            laws=("hertz",),
            compose=_compose,
            every=4,
            costly=True,
        )
    )


def _series_order(x, a1) -> int:
    """An order k in 2..31 picked from the problem (reproducibly)."""
    return 2 + int(float(x) / float(a1) * 1e6) % 30


def _series_compose(x, a1, a2):
    from asymslip_gen import half_plane_stress as g

    k = np.array([_series_order(xv, av) for xv, av in zip(np.ravel(x), np.ravel(a1), strict=True)])
    return g.half_plane_node_series_factor(k)


def _series_reference(x, a1, a2):
    k = _series_order(x, a1)
    v = mpmath.mpc(1, -1)
    coefficient = mpmath.taylor(_kernel, v, k)[k]  # K^(k)(v)/k!
    return (coefficient / v ** (1 - k)).real


register_quantity(
    Quantity(
        "half_plane_stress.half_plane_node_series_factor",
        ARGS,
        _series_reference,
        ("HP-5",),
        laws=("hertz",),
        compose=_series_compose,
        every=5,
        costly=True,
    )
)


def _semi_ellipse(load: str, component: str):
    def compose(x, a1, a2):
        from asymslip_gen import half_plane_stress as g

        return getattr(g, f"semi_ellipse_{load}_{component}")(x, a2 - x, a1)

    def reference(x, a1, a2):
        def traction(t):
            s = mpmath.sqrt(max(mpmath.mpf(0), a1 * a1 - t * t))
            return (s, 0) if load == "pressure" else (0, s)

        return _flamant(traction, -a1, a1, x, a2 - x, component)

    return compose, reference


for _load in ("pressure", "shear"):
    for _component in COMPONENTS:
        _compose, _reference = _semi_ellipse(_load, _component)
        register_quantity(
            Quantity(
                f"half_plane_stress.semi_ellipse_{_load}_{_component}",
                ARGS,
                _reference,
                ("HP-6",),
                laws=("hertz",),
                compose=_compose,
                every=4,
                costly=True,
            )
        )


# ---------------------------------------------------------------------------------------------
# The edge asymptote (derivations/stress_edge_asymptote.py).  The eigenfields against the
# potential of a square-root load, -pi w^lam / sin(pi lam), put through the potential relations
# (Muskhelishvili's, for a half-plane loaded on its surface: sxx + syy = -(2/pi) Re(Q - i P),
# syy - sxx + 2 i sxy = (2/pi) (i y conj(Q' - i P') + conj(Q))) in mpmath; the amplitudes of
# (49) as the paper's slip-zone tractions; the next coefficients of the edge expansions by
# quadrature of Mossakovskii's superposition and numerical differentiation in s = a - x.
# ---------------------------------------------------------------------------------------------


def _edge_point(x, a1, a2):
    """An offset from a load's edge and a depth, both up to the problem's scale."""
    return x - a2 + (a2 - x) / 3, a2 - x


def _edge_parts(offset, y, power):
    """The polar parts of w = offset - i y (the generated fields' arguments), in doubles."""
    rho = np.hypot(offset, y)
    phi = np.arctan2(-y, offset)
    sine = np.divide(y, rho, out=np.zeros_like(rho), where=rho > 0)
    angle, slope = power * phi, (power - 1) * phi
    return rho**power, np.cos(angle), np.sin(angle), sine, np.cos(slope), np.sin(slope)


def _potential_stress(component, Q, dQ, P, dP, y):
    """The stress from the potentials (Muskhelishvili), in mpmath."""
    F, dF = Q - 1j * P, dQ - 1j * dP
    trace = -2 / pi * F.real
    deviator = 2 / pi * (1j * y * mpmath.conj(dF) + mpmath.conj(Q))
    return {
        "sxx": (trace - deviator.real) / 2,
        "syy": (trace + deviator.real) / 2,
        "sxy": deviator.imag / 2,
    }[component]


def _eigenfield(load: str, component: str, power: float):
    def compose(x, a1, a2):
        from asymslip_gen import edge_stress

        offset, y = _edge_point(x, a1, a2)
        function = getattr(edge_stress, f"edge_eigenfield_{load}_{component}")
        return function(*_edge_parts(offset, y, power), power)

    def reference(x, a1, a2):
        offset, y = _edge_point(x, a1, a2)
        lam = mpmath.mpf(power)
        w = mpmath.mpc(offset, -y)
        F = -pi * w**lam / mpmath.sin(pi * lam)
        dF = -pi * lam * w ** (lam - 1) / mpmath.sin(pi * lam)
        zero = mpmath.mpc(0)
        if load == "pressure":
            return _potential_stress(component, zero, zero, F, dF, y)
        return _potential_stress(component, F, dF, zero, zero, y)

    return compose, reference


for _load in ("pressure", "shear"):
    for _component in COMPONENTS:
        for _power, _label in ((0.5, ""), (1.5, " (lam = 3/2)")):
            _compose, _reference = _eigenfield(_load, _component, _power)
            register_quantity(
                Quantity(
                    f"edge_stress.edge_eigenfield_{_load}_{_component}",
                    ARGS,
                    _reference,
                    ("EA-1", "EA-2"),
                    compose=_compose,
                    label=f"edge_eigenfield_{_load}_{_component}{_label}",
                )
            )

register_quantity(
    Quantity(
        "edge_stress.edge_uniform_sxx",
        ("dsigma",),
        lambda dsigma: dsigma / 2,  # half the bulk change is left where the bodies stick
        ("EA-3",),
    )
)
register_quantity(
    Quantity(
        "edge_stress.edge_shear_amplitude_state2",
        ("L_I2", "mu"),
        lambda L_I2, mu: mu * L_I2,  # (8): q2 = mu p2 in the slip zone
        ("49", "EA-4"),
    )
)
register_quantity(
    Quantity(
        "edge_stress.edge_shear_amplitude_state1",
        ("L_I1", "mu"),
        lambda L_I1, mu: mu * L_I1,  # (11): q1 = -mu p1 in the slip zone
        ("49", "EA-4"),
    )
)
register_quantity(
    Quantity(
        "edge_stress.edge_shear_amplitude_stick",
        ("L_I1", "L_I2", "L_II1", "L_II2", "mu"),
        # Far inside the stick zone (49) is the full-stick change (6): the three amplitudes
        # sum to L_II2 - L_II1.
        lambda L_I1, L_I2, L_II1, L_II2, mu: L_II2 - L_II1 - mu * (L_I1 + L_I2),
        ("49", "EA-4"),
    )
)


def _next_coefficient(kernel, a, slope, curvature):
    """d/ds at s = 0 of int_{a-s}^a kernel(c, x) dc / sqrt(c^2 - x^2) / sqrt(s), x = a - s,
    with P'(c) = slope + curvature (c - a): the s^(3/2) coefficient of the edge expansion."""

    def scaled(s):
        x = a - s

        def integrand(v):  # c = x + s v^2
            c = x + s * v * v
            return 2 * kernel(slope + curvature * (c - a), x) / mpmath.sqrt(2 * x + s * v * v)

        return mpmath.quad(integrand, [0, 1])

    return mpmath.diff(scaled, 0)


def _law_slopes(dP_da1, d2a_dP2):
    """P'(a1) and P''(a1) from the problem (a'' = -P''/P'^3)."""
    return dP_da1, -d2a_dP2 * dP_da1**3


register_quantity(
    Quantity(
        "edge_stress.edge_pressure_next_coefficient",
        ("a=a1", "L_I=L_I1", "dL_I_dP", "dP_da1", "d2a_dP2"),
        lambda a, L_I, dL_I_dP, dP_da1, d2a_dP2: _next_coefficient(
            lambda Pp, x: Pp / pi, a, *_law_slopes(dP_da1, d2a_dP2)
        ),
        ("4", "EA-6"),
        compose=lambda a, L_I, dL_I_dP, dP_da1, d2a_dP2: __import__(
            "asymslip_gen.edge_stress", fromlist=["_"]
        ).edge_pressure_next_coefficient(a, L_I, dL_I_dP * dP_da1),
        every=4,
        costly=True,
    )
)
register_quantity(
    Quantity(
        "edge_stress.edge_shear_next_coefficient",
        ("a=a1", "lam", "eta", "L_I=L_I1", "dL_I_dP", "dP_da1", "d2a_dP2"),
        lambda a, lam, eta, L_I, dL_I_dP, dP_da1, d2a_dP2: _next_coefficient(
            lambda Pp, x: lam * Pp / pi + eta * Pp * x / 4, a, *_law_slopes(dP_da1, d2a_dP2)
        ),
        ("5", "21", "EA-6"),
        compose=lambda a, lam, eta, L_I, dL_I_dP, dP_da1, d2a_dP2: __import__(
            "asymslip_gen.edge_stress", fromlist=["_"]
        ).edge_shear_next_coefficient(a, lam, eta, L_I, dL_I_dP * dP_da1),
        every=4,
        costly=True,
    )
)


# ---------------------------------------------------------------------------------------------
# Crack nucleation (derivations/nucleation_criteria.py): the traction on a plane by rotating
# the stress tensor, plane-strain Hooke's law in three dimensions, the criteria as defined.
# The harness feeds a stress state and a plane from the problem's numbers.
# ---------------------------------------------------------------------------------------------

PLANE = ("sxx=L_I1", "syy=L_II1", "sxy=L_II2", "theta=mu")


def _rotated(sxx, syy, sxy, theta):
    s = mpmath.matrix([[sxx, sxy], [sxy, syy]])
    n = mpmath.matrix([mpmath.cos(theta), mpmath.sin(theta)])
    t = mpmath.matrix([-mpmath.sin(theta), mpmath.cos(theta)])
    return (n.T * s * n)[0], (t.T * s * n)[0]


def _strained(sxx, syy, sxy, theta, E, nu):
    szz = nu * (sxx + syy)
    trace = sxx + syy + szz
    eps = mpmath.matrix(
        [
            [((1 + nu) * sxx - nu * trace) / E, (1 + nu) * sxy / E],
            [(1 + nu) * sxy / E, ((1 + nu) * syy - nu * trace) / E],
        ]
    )
    n = mpmath.matrix([mpmath.cos(theta), mpmath.sin(theta)])
    t = mpmath.matrix([-mpmath.sin(theta), mpmath.cos(theta)])
    return (n.T * eps * n)[0], 2 * (t.T * eps * n)[0]


def _with_nu(function):
    """Feed nu = 0.3 (the problems carry no Poisson's ratio)."""

    def compose(**kwargs):
        import asymslip_gen.nucleation as g

        kwargs["nu"] = np.full_like(kwargs["E"], 0.3)
        return getattr(g, function)(**kwargs)

    return compose


for _name, _index in (("plane_normal_stress", 0), ("plane_shear_stress", 1)):
    register_quantity(
        Quantity(
            f"nucleation.{_name}",
            PLANE,
            lambda sxx, syy, sxy, theta, i=_index: _rotated(sxx, syy, sxy, theta)[i],
            ("NC-1",),
        )
    )
for _name, _index in (("plane_normal_strain", 0), ("plane_shear_strain", 1)):
    register_quantity(
        Quantity(
            f"nucleation.{_name}",
            (*PLANE, "E=E_star"),
            lambda sxx, syy, sxy, theta, E, i=_index: _strained(
                sxx, syy, sxy, theta, E, mpmath.mpf("0.3")
            )[i],
            ("NC-2",),
            compose=_with_nu(_name),
        )
    )
register_quantity(
    Quantity(
        "nucleation.findley_parameter",
        ("tau_a=L_I1", "sigma_n_max=L_II1", "k=mu"),
        lambda tau_a, sigma_n_max, k: tau_a + k * sigma_n_max,  # Findley (1959)
        ("NC-3",),
    )
)
register_quantity(
    Quantity(
        "nucleation.fatemi_socie_parameter",
        ("gamma_a=mu", "sigma_n_max=L_II1", "k=mu", "sigma_y=L_I2"),
        lambda gamma_a, sigma_n_max, k, sigma_y: gamma_a * (1 + k * sigma_n_max / sigma_y),
        ("NC-3",),
    )
)
register_quantity(
    Quantity(
        "nucleation.smith_watson_topper_parameter",
        ("sigma_n_max=L_II1", "eps_a=mu"),
        lambda sigma_n_max, eps_a: max(sigma_n_max, 0) * eps_a,  # SWT (1970)
        ("NC-3",),
    )
)
register_quantity(
    Quantity(
        "nucleation.ruiz_frictional_work",
        ("tau=L_I1", "delta=da"),
        lambda tau, delta: tau * delta,  # Ruiz et al. (1984)
        ("NC-3",),
    )
)
register_quantity(
    Quantity(
        "nucleation.ruiz_parameter",
        ("sigma_T=L_II1", "tau=L_I1", "delta=da"),
        lambda sigma_T, tau, delta: max(sigma_T, 0) * tau * delta,
        ("NC-3",),
    )
)
