"""Points inside each generated function's documented domain, for comparing languages.

Every emitted function has an entry in :data:`DOMAINS`, written from its documentation
(``formulas.json``: each argument's rule and the function's stated domain): a function with no
entry makes the comparison fail (:func:`sample` raises), and so does an entry for a function
that no longer exists, so a new function cannot be skipped silently.

Most quantities belong to one load cycle, so the points are drawn as physically consistent
steady partial-slip cycles of a Hertzian contact (the laws and multipliers computed here in
plain NumPy from the paper's (29) and (19), not from the code under test): forward slip
(lam > mu, so that the slip zone lies inside a1 and (17)'s denominator stays away from 0), a
small bulk tension, load changes dP/P1 from 1e-9 to 0.1.  Arguments that stand alone (a
modulus, a slope) get their own ranges.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping

import numpy as np

Points = dict[str, np.ndarray]


class Draw:
    """Random draws of ``n`` points, shared by the domain rules."""

    def __init__(self, n: int, seed: int) -> None:
        self.n = n
        self.rng = np.random.default_rng(seed)

    def uniform(self, low: float, high: float) -> np.ndarray:
        return self.rng.uniform(low, high, self.n)

    def log_uniform(self, low: float, high: float) -> np.ndarray:
        return np.exp(self.rng.uniform(math.log(low), math.log(high), self.n))

    def cycle(self) -> Points:
        """A steady partial-slip cycle of a Hertzian contact: loads, half-widths, multipliers."""
        R = self.log_uniform(0.1, 10.0)
        E_star = self.log_uniform(1.0, 1e3)
        P1 = self.log_uniform(1.0, 1e3)
        dP = P1 * self.log_uniform(1e-9, 0.1)
        mu = self.uniform(0.1, 1.0)
        lam = mu * self.uniform(1.05, 3.0)
        a1 = np.sqrt(4 * R * P1 / (np.pi * E_star))  # (29)
        a2 = np.sqrt(4 * R * (P1 + dP) / (np.pi * E_star))
        da = 4 * R * dP / (np.pi * E_star * (a1 + a2))  # a2 - a1 without cancellation
        # Bulk tension small enough that lam + pi eta a/4 - mu stays >= 0.02 mu at both states.
        eta = mu * self.uniform(-0.02, 0.02) / a2
        slope1 = np.pi * E_star * a1 / (2 * R)  # dP/da of (29)
        slope2 = np.pi * E_star * a2 / (2 * R)
        L_I1 = np.sqrt(2 / a1) * slope1 / np.pi  # (19)
        L_I2 = np.sqrt(2 / a2) * slope2 / np.pi
        L_II1 = (lam + np.pi * eta * a1 / 4) * L_I1  # (21)
        L_II2 = (lam + np.pi * eta * a2 / 4) * L_I2
        # b from (17) (the root of the consistency condition (16)), written here from the paper:
        # ((mu L_I2 - L_II2) a2 + (mu L_I1 + L_II1) a1) / ((mu L_I2 - L_II2) + (mu L_I1 + L_II1)).
        b = (a2 * (mu * L_I2 - L_II2) + a1 * (mu * L_I1 + L_II1)) / (
            mu * (L_I1 + L_I2) + L_II1 - L_II2
        )
        return {
            "R": R,
            "E_star": E_star,
            "P1": P1,
            "dP": dP,
            "mu": mu,
            "lam": lam,
            "eta": eta,
            "a1": a1,
            "a2": a2,
            "da": da,
            "L_I1": L_I1,
            "L_I2": L_I2,
            "L_II1": L_II1,
            "L_II2": L_II2,
            "b": b,
            "da_dP": a1 / (2 * P1),
            "P_K": P1 + dP * (mu - lam) / (2 * mu),
        }

    def no_tension_cycle(self) -> Points:
        points = self.cycle()
        points["eta"] = np.zeros(self.n)
        return points

    def law(self) -> Points:
        """Standalone law quantities: a half-width, a load, a modulus, a radius, slopes."""
        return {
            "a": self.log_uniform(0.01, 100.0),
            "P": self.log_uniform(0.01, 1e4),
            "R": self.log_uniform(0.1, 10.0),
            "E_star": self.log_uniform(1.0, 1e3),
            "dP_da": self.log_uniform(1e-3, 1e3),
            "dQ_da": self.uniform(-1e3, 1e3),
            "dsigma_da": self.uniform(-1e3, 1e3),
            "L_I": self.log_uniform(1e-2, 1e3),
            "lam": self.uniform(-3.0, 3.0),
            "eta": self.uniform(-1.0, 1.0),
        }

    def power_law(self) -> Points:
        """A power-law punch h = A |x|^n, n >= 1, with its shape factor K(n)."""
        n = self.uniform(1.0, 4.0)
        gamma = np.vectorize(math.gamma)
        K = n * math.sqrt(math.pi) / 2 * gamma((n + 1) / 2) / gamma(n / 2 + 1)
        a = self.log_uniform(0.01, 100.0)
        x = a * self.uniform(-1.2, 1.2)
        return {
            "n": n,
            "K": K,
            "A": self.log_uniform(0.01, 10.0),
            "E_star": self.log_uniform(1.0, 1e3),
            "a": a,
            "x": x,
            "P": self.log_uniform(0.01, 1e4),
            "P1": self.log_uniform(1.0, 1e3),
            "hypergeometric": self.uniform(0.5, 2.0),
        }

    def flat_rounded(self) -> Points:
        """A flat punch with rounded corners: a > c >= 0 (c/a up to 0.95, see its doc)."""
        a = self.log_uniform(0.01, 100.0)
        c = a * self.uniform(0.0, 0.95)
        chord = np.sqrt((a - c) * (a + c))  # D = sqrt(a^2 - c^2)
        return {
            "a": a,
            "c": c,
            "R": self.log_uniform(0.1, 10.0),
            "E_star": self.log_uniform(1.0, 1e3),
            "x": a * self.uniform(-1.2, 1.2),
            "D": chord,
            "psi": np.arctan2(chord, c),  # psi = arccos(c/a)
        }

    def away_from(self, points: np.ndarray, scale: np.ndarray, gap: float) -> np.ndarray:
        """``points`` with those closer than ``gap * scale`` to 0 moved out to that distance."""
        near = np.abs(points) < gap * scale
        return np.where(near, np.copysign(gap * scale, points), points)


def _cycle(draw: Draw) -> Points:
    return draw.cycle()


def _no_tension(draw: Draw) -> Points:
    return draw.no_tension_cycle()


def _law(draw: Draw) -> Points:
    return draw.law()


def _generic_slopes(draw: Draw) -> Points:
    """A cycle plus an arbitrary second derivative and L_I' (the generic-law coefficient)."""
    points = draw.no_tension_cycle()
    points["d2a_dP2"] = points["da_dP"] / points["P1"] * draw.uniform(-2.0, 2.0)
    points["dL_I_dP"] = points["L_I1"] / points["P1"] * draw.uniform(-2.0, 2.0)
    return points


def _second_order(draw: Draw) -> Points:
    """A cycle with tension, its slopes a'', L_I', and the other edge's slip (+1 or -1)."""
    points = draw.cycle()
    points["d2a_dP2"] = -points["da_dP"] / (2 * points["P1"])  # Hertz: a ~ P^(1/2)
    points["dL_I_dP"] = points["L_I1"] / (4 * points["P1"])  # (31): L_I ~ P^(1/4)
    points["other_edge"] = np.where(draw.uniform(0.0, 1.0) < 0.5, -1.0, 1.0)
    return points


def _second_order_groups(draw: Draw) -> Points:
    """The second-order width's dimensionless groups (its generated doc), from such a cycle."""
    points = _second_order(draw)
    mu, a1, dP = points["mu"], points["a1"], points["dP"]
    root = a1**1.5
    points["lam_mu"] = points["lam"] / mu
    points["eta_a1_mu"] = points["eta"] * a1 / mu
    points["growth"] = points["da_dP"] * dP / a1
    points["multiplier"] = points["L_I1"] * root / dP
    points["multiplier_slope"] = points["dL_I_dP"] * root
    return points


def _slip_direction(draw: Draw) -> Points:
    """Every direction: L_II2 from -3 mu L_I2 to 3 mu L_I2 (forward, none, backward)."""
    points = draw.cycle()
    points["L_II2"] = points["mu"] * points["L_I2"] * draw.uniform(-3.0, 3.0)
    return points


def _stated_accuracy(draw: Draw) -> Points:
    """da/a1 of a cycle and a width a1 - b of either sign (its doc), up to twice the slip zone."""
    points = draw.cycle()
    points["relative_growth"] = points["da"] / points["a1"]
    points["width"] = (points["a1"] - points["b"]) * draw.uniform(-1.0, 2.0)
    return points


def _disagreement_limit(draw: Draw) -> Points:
    """Two non-negative accuracies (lengths of the order of the slip zone) and a rounding share."""
    points = draw.cycle()
    width = np.abs(points["a1"] - points["b"])
    points["accuracy"] = width * draw.log_uniform(1e-9, 1.0)
    points["other_accuracy"] = width * draw.log_uniform(1e-9, 1.0)
    points["rounding"] = draw.log_uniform(1e-16, 1e-9)
    return points


def _in_slip_zone(draw: Draw) -> Points:
    """A cycle and x from below b (stick zone, where the result is 0) to just inside a2."""
    points = draw.cycle()
    b, a2 = points["b"], points["a2"]
    points["x"] = b + (a2 - b) * draw.uniform(-1.0, 1.0 - 1e-6)
    return points


def _traction_asymptote(draw: Draw) -> Points:
    """(49): x < a2 anywhere in the contact, b <= a1 (consistent or not), per its doc."""
    points = draw.cycle()
    a1, a2, b = points["a1"], points["a2"], points["b"]
    points["b"] = a1 - (a1 - b) * draw.uniform(0.0, 2.0)
    points["x"] = a2 * draw.uniform(-1.0, 1.0 - 1e-6)
    return points


def _hertz_traction(draw: Draw) -> Points:
    """Exact (47): any x, 0 < P_K < P1 from (33) of a forward-slip cycle."""
    points = draw.no_tension_cycle()
    points["x"] = points["a2"] * draw.uniform(-1.5, 1.5)
    return points


def _hertz_pressure(draw: Draw) -> Points:
    points = draw.law()
    a = np.sqrt(4 * points["R"] * points["P"] / (np.pi * points["E_star"]))
    points["x"] = a * draw.uniform(-1.5, 1.5)
    return points


def _pressures(draw: Draw) -> Points:
    """Hertz pressures at P2, P1 and P_K of a forward-slip cycle (each 0 outside its contact)."""
    points = draw.no_tension_cycle()
    x = points["a2"] * draw.uniform(-1.2, 1.2)
    R, E_star = points["R"], points["E_star"]
    for key, load in (
        ("p2", points["P1"] + points["dP"]),
        ("p1", points["P1"]),
        ("p_K", points["P_K"]),
    ):
        a = np.sqrt(4 * R * load / (np.pi * E_star))  # (29)
        points[key] = E_star / (2 * R) * np.sqrt(np.maximum(0.0, a**2 - x**2))  # (48)
    return points


def _fitted_law(draw: Draw) -> Points:
    """A law fitted as log a(log P): s' > 0 (where the fit increases), any curvature."""
    points = draw.law()
    points["ds"] = draw.uniform(0.1, 2.0)
    points["d2s"] = draw.uniform(-1.0, 1.0)
    return points


def _power_law(draw: Draw) -> Points:
    return draw.power_law()


def _power_law_growth(draw: Draw) -> Points:
    points = draw.power_law()
    points["dP"] = points["P1"] * draw.log_uniform(1e-12, 1.0)
    return points


def _wedge(draw: Draw) -> Points:
    """The wedge pressure: any x but the apex x = 0, a logarithmic singularity (its doc)."""
    points = draw.power_law()
    points["x"] = draw.away_from(points["x"], points["a"], 1e-6)
    return points


def _flat_rounded(draw: Draw) -> Points:
    return draw.flat_rounded()


def _influence(draw: Draw) -> Points:
    """Solver kernels: integer offsets k of a grid of up to 8000 elements, ell >= its length/4."""
    h = draw.log_uniform(1e-4, 1.0)
    return {
        "k": np.round(draw.uniform(-8000.0, 8000.0)),
        "h": h,
        "ell": h * draw.uniform(100, 20000),
        "E_star": draw.log_uniform(1.0, 1e3),
    }


def _tension(draw: Draw) -> Points:
    return {
        "x": draw.uniform(-100.0, 100.0),
        "sigma": draw.uniform(-1e3, 1e3),
        "E_star": draw.log_uniform(1.0, 1e3),
    }


def _tension_share(draw: Draw) -> Points:
    """The error map's axes: a tension share of either sign, half-widths, frictions."""
    return {
        "tau": draw.uniform(-3.0, 3.0),
        "eta": draw.uniform(-1.0, 1.0),
        "a1": draw.log_uniform(0.01, 100.0),
        "mu": draw.uniform(0.05, 1.0),
    }


def _asymmetric_edges(draw: Draw) -> Points:
    """One edge of an asymmetric contact: width, slopes and multipliers of both edges > 0; the
    moment of the increments about the centre within +-20 % of the load's (so L_I > 0)."""
    points = draw.law()
    points["w"] = draw.log_uniform(0.01, 200.0)
    points["da_dP"] = draw.log_uniform(1e-4, 1e2)
    points["dMc_da"] = points["dP_da"] * points["w"] * draw.uniform(-0.2, 0.2)
    for side in ("right", "left"):
        points[f"L_I_{side}"] = draw.log_uniform(1e-2, 1e3)
        points[f"da_dP_{side}"] = draw.log_uniform(1e-4, 1e2)
    return points


def _lab_transfer(draw: Draw) -> Points:
    """A forward-slipping cycle's edge (slip zone inside a1) and its width w = a1 - b > 0."""
    points = draw.cycle()
    # a1 - b of (17), written here from the paper: -A da/(A + C), A = mu L_I2 - L_II2 < 0,
    # C = mu L_I1 + L_II1.
    A = points["mu"] * points["L_I2"] - points["L_II2"]
    C = points["mu"] * points["L_I1"] + points["L_II1"]
    points["w"] = -A * points["da"] / (A + C)
    return points


def _flat_rounded_pair(draw: Draw) -> Points:
    """A rounded flat at two half-widths a2 > a1 > c, and a multiplier L_I to reproduce."""
    points = draw.flat_rounded()
    points["a1"] = points["a"]
    points["a2"] = points["a"] * (1 + draw.log_uniform(1e-9, 0.1))
    points["L_I"] = draw.log_uniform(1e-2, 1e3)
    return points


def _half_plane_element(draw: Draw) -> Points:
    """One linear traction element [t0, t1] and a point below the surface (y > 0) within a
    few element lengths of it, where the closed form is documented as well conditioned."""
    t0 = draw.uniform(-10.0, 10.0)
    length = draw.log_uniform(1e-3, 5.0)
    return {
        "x": t0 + length * draw.uniform(-3.0, 4.0),
        "y": length * draw.log_uniform(0.1, 3.0),
        "t0": t0,
        "t1": t0 + length,
        **{name: draw.uniform(-5.0, 5.0) for name in ("p0", "p1", "q0", "q1")},
    }


def _half_plane_node(draw: Draw) -> Points:
    """A point below the surface and a node: offset u, depth y > 0, and free sums."""
    return {
        "u": draw.uniform(-10.0, 10.0),
        "x": draw.uniform(-10.0, 10.0),
        "y": draw.log_uniform(1e-4, 10.0),
        "L": draw.uniform(-5.0, 3.0),
        "theta": draw.uniform(-math.pi, 0.0),
        "k": np.round(draw.uniform(2.0, 40.0)),
        **{
            name: draw.uniform(-10.0, 10.0)
            for name in ("A_L", "B_L", "A_theta", "B_theta", "A_1", "B_1")
        },
        **{
            name: draw.uniform(-10.0, 10.0)
            for name in ("Q_re", "Q_im", "P_im", "dQ_re", "dQ_im", "dP_re", "dP_im")
        },
    }


def _semi_ellipse(draw: Draw) -> Points:
    """Any point of the body (y >= 0, a tenth of them on the surface) and a half-width."""
    y = draw.log_uniform(1e-4, 10.0)
    y[: draw.n // 10] = 0.0
    return {"x": draw.uniform(-20.0, 20.0), "y": y, "a": draw.log_uniform(0.1, 10.0)}


def _edge_eigenfield(draw: Draw) -> Points:
    """The polar parts of a point below the surface (y > 0) seen from a load's edge, for the
    powers 1/2 and 3/2 of the edge expansions."""
    X = draw.uniform(-5.0, 5.0)
    y = draw.log_uniform(1e-4, 5.0)
    lam = np.where(draw.uniform(0.0, 1.0) < 0.5, 0.5, 1.5)
    rho, phi = np.hypot(X, y), np.arctan2(-y, X)
    return {
        "rho_lam": rho**lam,
        "cos_lam": np.cos(lam * phi),
        "sin_lam": np.sin(lam * phi),
        "sin_angle": y / rho,
        "cos_lam1": np.cos((lam - 1) * phi),
        "sin_lam1": np.sin((lam - 1) * phi),
        "lam_e": lam,
    }


def _edge_law(draw: Draw) -> Points:
    """A cycle's multipliers, a slope of L_I and a bulk-tension change."""
    points = draw.cycle()
    points["a"] = points["a1"]
    points["L_I"] = points["L_I1"]
    points["dL_I_da"] = points["L_I1"] / points["a1"] * draw.uniform(-2.0, 2.0)
    points["dsigma"] = draw.uniform(-1e3, 1e3)
    return points


def _plane(draw: Draw) -> Points:
    """A stress state, a plane, a material and a criterion's inputs."""
    return {
        **{name: draw.uniform(-1e3, 1e3) for name in ("sxx", "syy", "sxy")},
        "theta": draw.uniform(0.0, math.pi),
        "E": draw.log_uniform(1e3, 1e6),
        "nu": draw.uniform(0.05, 0.49),
        "tau_a": draw.log_uniform(1.0, 1e3),
        "sigma_n_max": draw.uniform(-1e3, 1e3),
        "k": draw.log_uniform(0.05, 2.0),
        "gamma_a": draw.log_uniform(1e-6, 1e-2),
        "sigma_y": draw.log_uniform(100.0, 2e3),
        "eps_a": draw.log_uniform(1e-6, 1e-2),
        "tau": draw.log_uniform(1.0, 1e3),
        "delta": draw.log_uniform(1e-6, 1e-1),
        "sigma_T": draw.uniform(-1e3, 1e3),
    }


#: Function name -> how to draw points inside its documented domain.
DOMAINS: Mapping[str, Callable[[Draw], Points]] = {
    # corrective_slip, validity: one steady partial-slip cycle
    "stick_boundary_proportional": _cycle,
    "stick_boundary_denominator": _cycle,
    "slip_zone_width_from_multipliers": _cycle,
    "stick_boundary_denominator_from_multipliers": _cycle,
    "slip_zone_width": _cycle,
    "stick_boundary": _cycle,
    "dislocation_density": _in_slip_zone,
    "slip_on_loading": _in_slip_zone,
    # edge_symmetry, stated_accuracy
    "slip_direction": _slip_direction,
    "stick_boundary_accuracy": _stated_accuracy,
    "paper_stick_boundary_accuracy": _stated_accuracy,
    "stick_boundary_accuracy_first_order": _stated_accuracy,
    "disagreement_limit": _disagreement_limit,
    "contact_growth_measure": _cycle,
    "relative_slip_zone_measure": _cycle,
    "multiplier_growth_measure": _generic_slopes,
    "slip_zone_growth_measure": _cycle,
    "stick_ratio_first_order": _cycle,
    "stick_ratio_first_order_from_multipliers": _cycle,
    "slip_zone_growth_measure_from_multipliers": _cycle,
    "slip_zone_width_first_order": _cycle,
    # corrective_stick
    "shear_intensity_rate": _law,
    "corrective_stick_slip_zone_width": _cycle,
    "hertz_stick_boundary_corrective_stick": _cycle,
    "hertz_slip_zone_width_corrective_stick": _cycle,
    # asymmetric_edges
    "shear_edge_multiplier_asymmetric": _asymmetric_edges,
    "normal_edge_multiplier_asymmetric": _asymmetric_edges,
    "edge_moment_factor": _asymmetric_edges,
    "edge_multiplier_balance": _asymmetric_edges,
    # edge_multipliers
    "normal_edge_multiplier": _law,
    "shear_edge_multiplier": _law,
    "shear_edge_multiplier_proportional": _law,
    # exact_solution (eta = 0, P_K > 0)
    "permanent_stick_load": _no_tension,
    "hertz_stick_boundary_exact": _no_tension,
    "hertz_slip_zone_width_exact": _no_tension,
    # method_agreement
    "hertz_slip_zone_width_first_order": _cycle,
    "corrective_slip_discrepancy_third_order": _no_tension,
    "corrective_stick_discrepancy_second_order": _no_tension,
    "corrective_stick_discrepancy_third_order": _no_tension,
    # generic_law
    "second_order_stick_boundary_gap": _generic_slopes,
    "second_order_stick_boundary_gap_from_multiplier": _generic_slopes,
    # second_order
    "slip_zone_width_second_order_from_multiplier": _second_order,
    "slip_zone_width_second_order_dimensionless": _second_order_groups,
    "slip_zone_width_second_order": _second_order,
    "stick_boundary_second_order": _second_order,
    "slip_zone_width_second_coefficient": _second_order,
    "paper_stick_boundary_error": _second_order,
    "paper_stick_boundary_error_from_multiplier": _second_order,
    # hertz
    "hertz_load": _law,
    "hertz_load_slope": _law,
    "hertz_half_width": _law,
    "hertz_normal_edge_multiplier": _law,
    "hertz_normal_edge_multiplier_slope": _law,
    "hertz_half_width_growth": _cycle,
    # tractions
    "hertz_pressure": _hertz_pressure,
    "hertz_shear_traction_difference": _hertz_traction,
    "shear_traction_difference": _traction_asymptote,
    "jaeger_ciavarella_traction_difference": _pressures,
    # table_law
    "normal_edge_multiplier_slope_loglog": _fitted_law,
    # flat_rounded
    "flat_rounded_load": _flat_rounded,
    "flat_rounded_load_slope": _flat_rounded,
    "flat_rounded_normal_edge_multiplier": _flat_rounded,
    "flat_rounded_normal_edge_multiplier_slope": _flat_rounded,
    "flat_rounded_pressure": _flat_rounded,
    "flat_rounded_chord": _flat_rounded,
    "flat_rounded_corner_angle": _flat_rounded,
    "flat_rounded_load_at_angle": _flat_rounded,
    "flat_rounded_load_slope_at_angle": _flat_rounded,
    "flat_rounded_normal_edge_multiplier_at_angle": _flat_rounded,
    "flat_rounded_normal_edge_multiplier_slope_at_angle": _flat_rounded,
    # power_law
    "power_law_load": _power_law,
    "power_law_load_slope": _power_law,
    "power_law_half_width": _power_law,
    "power_law_half_width_growth": _power_law_growth,
    "power_law_normal_edge_multiplier": _power_law,
    "power_law_normal_edge_multiplier_slope": _power_law,
    "power_law_hypergeometric_argument": _power_law,
    "power_law_pressure": _power_law,
    "wedge_pressure": _wedge,
    # the laws' profiles and the reference solver's kernels
    "hertz_profile": _hertz_pressure,
    "flat_rounded_profile": _flat_rounded,
    "power_law_profile": _power_law,
    "gap_opening_influence": _influence,
    "relative_slip_influence": _influence,
    "tension_relative_displacement": _tension,
    # lab_transfer: the laboratory match
    "peak_shear_change": _lab_transfer,
    "hertz_matched_half_width": _lab_transfer,
    "hertz_matched_radius": _lab_transfer,
    "matched_tension_slope": _lab_transfer,
    "matched_shear_slope": _lab_transfer,
    "flat_rounded_matched_radius": _flat_rounded_pair,
    "flat_rounded_multiplier_ratio": _flat_rounded_pair,
    # half_plane_stress
    **{f"half_plane_element_{c}": _half_plane_element for c in ("sxx", "syy", "sxy")},
    **{f"half_plane_potential_{c}": _half_plane_node for c in ("sxx", "syy", "sxy")},
    "half_plane_node_log_distance": _half_plane_node,
    "half_plane_node_angle": _half_plane_node,
    "half_plane_node_potential_real": _half_plane_node,
    "half_plane_node_potential_imag": _half_plane_node,
    "half_plane_node_sum_real": _half_plane_node,
    "half_plane_node_sum_imag": _half_plane_node,
    "half_plane_node_series_factor": _half_plane_node,
    **{
        f"edge_eigenfield_{load}_{c}": _edge_eigenfield
        for load in ("pressure", "shear")
        for c in ("sxx", "syy", "sxy")
    },
    "edge_uniform_sxx": _edge_law,
    **{
        name: _plane
        for name in (
            "plane_normal_stress",
            "plane_shear_stress",
            "plane_normal_strain",
            "plane_shear_strain",
            "findley_parameter",
            "fatemi_socie_parameter",
            "smith_watson_topper_parameter",
            "ruiz_frictional_work",
            "ruiz_parameter",
        )
    },
    "edge_shear_amplitude_state2": _edge_law,
    "edge_shear_amplitude_state1": _edge_law,
    "edge_shear_amplitude_stick": _edge_law,
    "edge_pressure_next_coefficient": _edge_law,
    "edge_shear_next_coefficient": _edge_law,
    **{
        f"semi_ellipse_{load}_{c}": _semi_ellipse
        for load in ("pressure", "shear")
        for c in ("sxx", "syy", "sxy")
    },
    # edge_drive (the error map's axes)
    "tension_share": _tension_share,
    "tension_slope_for_share": _tension_share,
}


class NoDomainError(LookupError):
    """A function has no domain rule: the comparison must not skip it."""


def sample(name: str, arguments: list[str], n: int, seed: int = 13) -> Points:
    """``n`` points inside ``name``'s domain, one array per argument, in argument order."""
    if name not in DOMAINS:
        raise NoDomainError(
            f"no domain for the generated function {name!r}: add it to tests/emit/domains.py "
            "from its documented argument rules"
        )
    points = DOMAINS[name](Draw(n, seed))
    missing = [arg for arg in arguments if arg not in points]
    if missing:
        raise NoDomainError(f"the domain of {name!r} draws no {', '.join(missing)}")
    return {arg: np.ascontiguousarray(points[arg], dtype=np.float64) for arg in arguments}
