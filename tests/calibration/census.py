"""The census of the edge fit's errors: true against reported, on traces of every built-in law.

The traces are the closed-form pressures of every built-in law (tests/calibration/helpers.py)
on uniform and graded meshes of 20, 35, 50, 100 and 200 nodes across the contact, fitted at
both edges, at a load drawn in [80, 125]:

* **exact** traces: the error is deterministic (truncation of the edge expansion and
  discretisation), so the claim is per fit -- the reported error covers the true one, and is
  within a factor of three of it.  Three seeds (mesh offsets, loads): 240 fits.
* **noisy** traces, 1 % Gaussian scatter, *relative* (of the local pressure) or *absolute* (of
  the peak pressure): the error is random, so per mesh (configuration) the reported error is
  compared with the RMS true error over many draws of the scatter (the RMS true over the
  median reported, within [1/3, 1]: within a factor of three), and the coverage is the
  fraction of all fits whose true error lies within the reported one (95 % is what the
  reported error states).

Each fit's errors are estimates or bounds (``EdgeFit.error_kind``); the census gives every
fit's distribution and the estimates' (for the noisy traces, over the configurations where at
least half of the draws are estimates).

Run ``python -m tests.calibration.census [DRAWS]`` to print the distributions the guide
quotes (docs/guide/calibration.md; 364 s of CPU time with 40 draws); the slow tests in
test_edge_fit.py assert them on fewer draws.
"""

from __future__ import annotations

import sys
import time
from collections.abc import Iterator
from dataclasses import dataclass

import numpy as np

from asymslip.calibration.edge_fit import fit_edge
from tests.calibration.helpers import LAWS, REFERENCE_LOAD, mesh, noisy

NODES = (20, 35, 50, 100, 200)
MESHES = ("uniform", "graded")
SIDES = ("right", "left")
NOISE_KINDS = ("relative", "absolute")


@dataclass(frozen=True)
class Fit:
    """One fit: the true and reported errors of a and L_I."""

    law: str
    mesh: str
    nodes: int
    side: str
    true_a: float
    reported_a: float
    true_L: float
    reported_L: float
    bound: bool  # the fit's errors are bounds, not estimates (EdgeFit.error_kind)


@dataclass(frozen=True)
class Distribution:
    """min, median, max of ratios, and the fraction of them <= 1 (and in [1/3, 1])."""

    minimum: float
    median: float
    maximum: float
    covered: float
    within_three: float
    count: int

    @classmethod
    def of(cls, ratios: np.ndarray) -> Distribution:
        return cls(
            float(ratios.min()),
            float(np.median(ratios)),
            float(ratios.max()),
            float(np.mean(ratios <= 1)),
            float(np.mean((ratios <= 1) & (ratios >= 1 / 3))),
            int(ratios.size),
        )

    def __str__(self) -> str:
        return (
            f"min {self.minimum:.3g}, median {self.median:.3g}, max {self.maximum:.3g}; "
            f"covered {self.covered:.1%}, within 3x {self.within_three:.1%} ({self.count})"
        )


def _fits(law_name: str, x: np.ndarray, p: np.ndarray, P: float, kind: str, nodes: int):
    law = LAWS[law_name]
    a, L_I = float(law.half_width(P)), float(law.normal_multiplier(P))
    for side, edge in (("right", a), ("left", -a)):
        fit = fit_edge(x, p, side, P)
        yield Fit(
            law_name,
            kind,
            nodes,
            side,
            fit.x_edge - edge,
            fit.a_error,
            fit.L_I - L_I,
            fit.L_I_error,
            fit.error_kind == "bound",
        )


def exact(seeds: int = 3) -> list[Fit]:
    """Every law, mesh and node count, ``seeds`` meshes and loads each, both edges."""
    found = []
    for seed in range(seeds):
        rng = np.random.default_rng(100 + seed)
        for name, law in LAWS.items():
            for kind in MESHES:
                for nodes in NODES:
                    P = REFERENCE_LOAD * rng.uniform(0.8, 1.25)
                    x = mesh(kind, float(law.half_width(REFERENCE_LOAD)), nodes, rng)
                    found += _fits(name, x, law.pressure(x, P), P, kind, nodes)
    return found


def noisy_configurations(
    noise_kind: str, draws: int, nodes_list: tuple[int, ...] = NODES
) -> Iterator[list[Fit]]:
    """For every law, mesh and node count: the fits of ``draws`` draws of 1 % scatter on one
    mesh and load (both edges), one list per configuration and edge."""
    for law_index, (name, law) in enumerate(LAWS.items()):
        for mesh_index, kind in enumerate(MESHES):
            for nodes in nodes_list:
                seed = [NOISE_KINDS.index(noise_kind), law_index, mesh_index, nodes]
                rng = np.random.default_rng(seed)
                P = REFERENCE_LOAD * rng.uniform(0.8, 1.25)
                x = mesh(kind, float(law.half_width(REFERENCE_LOAD)), nodes, rng)
                exact_p = law.pressure(x, P)
                by_side: dict[str, list[Fit]] = {side: [] for side in SIDES}
                for _ in range(draws):
                    p = noisy(exact_p, 0.01, rng, noise_kind)
                    for fit in _fits(name, x, p, P, kind, nodes):
                        by_side[fit.side].append(fit)
                yield from by_side.values()


def exact_distributions(fits: list[Fit], kind: str = "all") -> tuple[Distribution, Distribution]:
    """Of true / reported, for a and for L_I: of every fit (``kind`` "all") or of those whose
    errors are estimates ("estimate") or bounds ("bound")."""
    if kind != "all":
        fits = [f for f in fits if f.bound == (kind == "bound")]
    true_a = np.array([abs(f.true_a) / f.reported_a for f in fits])
    true_L = np.array([abs(f.true_L) / f.reported_L for f in fits])
    return Distribution.of(true_a), Distribution.of(true_L)


@dataclass(frozen=True)
class NoisySummary:
    """Per configuration: RMS true / median reported; over all fits: the coverage."""

    ratio_a: Distribution  # of RMS true / median reported over configurations
    ratio_L: Distribution
    coverage_a: float
    coverage_L: float
    fits: int


def noisy_summary(configurations: list[list[Fit]], kind: str = "all") -> NoisySummary:
    """Over every configuration's fits (``kind`` "all"), or over the fits whose errors are
    estimates ("estimate") in the configurations where at least half of them are."""
    ratio_a, ratio_L, covered_a, covered_L = [], [], [], []
    for fits in configurations:
        if kind == "estimate":
            estimates = [f for f in fits if not f.bound]
            if 2 * len(estimates) < len(fits):
                continue
            fits = estimates
        true_a = np.array([f.true_a for f in fits])
        true_L = np.array([f.true_L for f in fits])
        reported_a = np.array([f.reported_a for f in fits])
        reported_L = np.array([f.reported_L for f in fits])
        ratio_a.append(np.sqrt(np.mean(true_a**2)) / np.median(reported_a))
        ratio_L.append(np.sqrt(np.mean(true_L**2)) / np.median(reported_L))
        covered_a += list(np.abs(true_a) <= reported_a)
        covered_L += list(np.abs(true_L) <= reported_L)
    return NoisySummary(
        Distribution.of(np.array(ratio_a)),
        Distribution.of(np.array(ratio_L)),
        float(np.mean(covered_a)),
        float(np.mean(covered_L)),
        len(covered_a),
    )


def bound_share(fits: list[Fit]) -> float:
    """The fraction of fits whose errors are bounds, not estimates."""
    return float(np.mean([f.bound for f in fits]))


def main(draws: int = 40) -> None:
    start = time.process_time()
    fits = exact()
    print(f"exact traces, true / reported ({len(fits)} fits, {bound_share(fits):.1%} bounds):")
    for kind in ("all", "estimate", "bound"):
        a, L = exact_distributions(fits, kind)
        print(f"  {kind}:\n    a:   {a}\n    L_I: {L}")
    for noise_kind in NOISE_KINDS:
        configurations = list(noisy_configurations(noise_kind, draws))
        share = bound_share([f for fits in configurations for f in fits])
        print(f"1 % {noise_kind} scatter, {draws} draws per mesh and edge ({share:.1%} bounds):")
        for kind in ("all", "estimate"):
            summary = noisy_summary(configurations, kind)
            print(
                f"  {kind} ({summary.fits} fits):\n"
                f"    a:   coverage {summary.coverage_a:.1%}; RMS true / median reported per "
                f"configuration: {summary.ratio_a}\n"
                f"    L_I: coverage {summary.coverage_L:.1%}; RMS true / median reported per "
                f"configuration: {summary.ratio_L}"
            )
    print(f"CPU time {time.process_time() - start:.0f} s")


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 40)
