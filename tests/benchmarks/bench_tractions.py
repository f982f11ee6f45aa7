"""The closed-form traction difference (49) against Cauchy-weighted quadrature of (15).

The paper's Fig. 5 problem (R = E* = 1, mu = 0.1, lam = 0.2, P1 = 100, dP = 5, b from (17)).
The baseline integrates the dislocation density (15) with QUADPACK's Cauchy-weighted rule
(``scipy.integrate.quad(weight="cauchy")``, QAWC, relative tolerance 1e-12), split at a1 where
the density has a square-root kink: what one would do without the closed form.  Both are
evaluated at the same points (spread over 0 <= x < a2, avoiding the breakpoints b and a1), in
interleaved rounds, best of N; the closed form is also timed on 10^6 points, where it is
vectorised, and compared per point with the quadrature.
"""

from __future__ import annotations

import numpy as np

from asymslip_gen.corrective_slip import dislocation_density, stick_boundary
from asymslip_gen.hertz import hertz_half_width, hertz_normal_edge_multiplier
from asymslip_gen.tractions import shear_traction_difference

from .timing import Row, duration, interleaved, times, verdict
from .timing import count as number

SPEED_TARGET = 1e4
AGREEMENT_TARGET = 1e-10
CLOSED_FORM_ARGUMENTS = ("b", "a1", "a2", "mu", "L_I1", "L_I2", "L_II1", "L_II2")


def fig5_problem() -> dict[str, float]:
    """The paper's Fig. 5 example, eta = 0, b from (17)."""
    R, E_star, mu, lam, P1, dP = 1.0, 1.0, 0.1, 0.2, 100.0, 5.0
    a1, a2 = hertz_half_width(P1, R, E_star), hertz_half_width(P1 + dP, R, E_star)
    L_I1 = hertz_normal_edge_multiplier(P1, R, E_star)
    L_I2 = hertz_normal_edge_multiplier(P1 + dP, R, E_star)
    L_II1, L_II2 = lam * L_I1, lam * L_I2  # (21) with eta = 0
    b = stick_boundary(mu, a1, a2, L_I1, L_I2, L_II1, L_II2)
    values = {
        "b": b,
        "a1": a1,
        "a2": a2,
        "mu": mu,
        "L_I1": L_I1,
        "L_I2": L_I2,
        "L_II1": L_II1,
        "L_II2": L_II2,
        "E_star": E_star,
    }
    return {key: float(value) for key, value in values.items()}


def quad_traction_difference(x: float, p: dict[str, float]) -> float:
    """(49) with the density (15) integrated by QUADPACK's Cauchy-weighted rule (QAWC).

    q = L_II2 sqrt(a2 - x) - L_II1 H(a1 - x) sqrt(a1 - x)
        - E*/(2 pi sqrt(a2 - x)) PV int_b^a2 sqrt(a2 - t) B(t) dt / (t - x),
    the integral split at a1, where B has a square-root kink.
    """
    from scipy.integrate import quad

    density_args = tuple(p[k] for k in ("b", "a1", "mu", "L_I1", "L_I2", "L_II1", "L_II2"))

    def weighted(t: float) -> float:
        density = dislocation_density(t, *density_args, p["E_star"])
        return float(np.sqrt(max(p["a2"] - t, 0.0)) * density)

    integral = 0.0
    for low, high in ((p["b"], p["a1"]), (p["a1"], p["a2"])):
        options = {"epsabs": 0.0, "epsrel": 1e-12, "limit": 200}
        if low < x < high:
            value, _ = quad(weighted, low, high, weight="cauchy", wvar=x, **options)
        else:
            value, _ = quad(lambda t: weighted(t) / (t - x), low, high, **options)
        integral += value
    edge = p["L_II2"] * np.sqrt(p["a2"] - x) - p["L_II1"] * np.sqrt(max(p["a1"] - x, 0.0))
    return float(edge - p["E_star"] / (2 * np.pi * np.sqrt(p["a2"] - x)) * integral)


def points(count: int, a2: float) -> np.ndarray:
    """``count`` points over 0 <= x < a2, cell midpoints (never b, a1 or a2 exactly)."""
    return np.linspace(0.0, a2, count, endpoint=False) + 0.5 * a2 / count


def bench_tractions(count: int, sample: int, rounds: int) -> list[Row]:
    try:
        import scipy  # noqa: F401
    except ImportError:
        return [
            Row(
                'closed-form (49) vs `scipy.integrate.quad(weight="cauchy")`',
                "skipped: SciPy not installed (the bench extra)",
                target=">= 1e4x",
            )
        ]
    p = fig5_problem()
    arguments = [p[name] for name in CLOSED_FORM_ARGUMENTS]
    many = points(count, p["a2"])
    x = many[:: max(1, count // sample)][:sample].copy()  # a subset of the same points
    x_list = x.tolist()
    quadrature = np.empty(len(x))

    def quad_at_points() -> None:
        quadrature[:] = [quad_traction_difference(xi, p) for xi in x_list]

    measured = interleaved(
        {
            "quad": quad_at_points,
            "closed": lambda: shear_traction_difference(many, *arguments),
            "closed_sample": lambda: shear_traction_difference(x, *arguments),
        },
        rounds,
        warm_up=False,
    )
    closed = shear_traction_difference(x, *arguments)
    # Relative to the traction's scale: q_diff passes through zero inside the contact.
    agreement = float(np.max(np.abs(closed - quadrature)) / np.max(np.abs(quadrature)))
    per_point_quad = measured.best("quad") / len(x)
    per_point_closed = measured.best("closed") / count
    speedup = per_point_quad / per_point_closed
    clock = measured.clock_words()
    return [
        Row(
            f"(49) closed form `shear_traction_difference` on {number(count)} points vs "
            f'`scipy.integrate.quad(weight="cauchy")` of (15) on {len(x)} of them, per point',
            duration(per_point_closed),
            duration(per_point_quad),
            f"{times(speedup)} faster",
            f">= {SPEED_TARGET:.0e}x".replace("e+0", "e"),
            verdict(speedup >= SPEED_TARGET),
            f"{clock}; per point: closed form {duration(measured.best('closed'))} for "
            f"{number(count)} points, quad {duration(measured.best('quad'))} for {len(x)}; "
            "Fig. 5 problem, b from (17)",
        ),
        Row(
            f"same, both on the same {len(x)} points (the closed form's call overhead dominates)",
            duration(measured.best("closed_sample")),
            duration(measured.best("quad")),
            f"{times(measured.ratio('quad', 'closed_sample'))} faster",
            "(information)",
            "-",
            measured.how("quad", "closed_sample"),
        ),
        Row(
            f"agreement at the {len(x)} points: max abs(closed - quad) / max abs(quad)",
            f"{agreement:.1e}",
            "",
            "",
            f"<= {AGREEMENT_TARGET:.0e}",
            verdict(agreement <= AGREEMENT_TARGET),
            "quad at relative tolerance 1e-12",
        ),
    ]
