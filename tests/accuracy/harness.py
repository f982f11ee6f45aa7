"""Accuracy harness: every generated quantity against an independent 50-digit mpmath evaluation.

``python -m tests.accuracy.harness --samples 20000 --seed 1`` (``make accuracy``) draws random
valid problems over wide ranges -- mu in [0.05, 1.5], lambda and eta of both signs, dP/P1
log-uniform in [1e-12, 0.3], every registered contact law -- evaluates each registered generated
function on the problems' doubles, evaluates the paper's equation transcribed by hand in mpmath
(``references.py``) on the exact values of the same doubles, and prints the largest relative
error per quantity.  ``tests/test_accuracy.py`` runs a small sample of the same in a few seconds.

Target: 1e-12 relative.  An error above it is explained by the conditioning of the problem when
it is within ``CONDITION_ALLOWANCE`` units of roundoff times the componentwise condition number

    kappa = sum_i |x_i df/dx_i| / |f|

computed from the reference at 50 digits: no implementation in double precision can do better
than about u * kappa on such inputs (e.g. the slip-zone width is proportional to
mu - lam - pi eta a1 / 4, so it is ill-conditioned when that nearly cancels).  A fifth of the
problems are drawn close to that cancellation on purpose, to show the distinction.
"""

from __future__ import annotations

import argparse
import importlib
import inspect
import math
import sys
import time
import warnings
from collections.abc import Callable, Iterable
from dataclasses import dataclass, field

import mpmath
import numpy as np

from . import references, references_stress  # noqa: F401  (register laws and quantities)
from .registry import LAWS, QUANTITIES, LawCase, Quantity

DIGITS = 50
TARGET = 1e-12
UNIT_ROUNDOFF = 2.0**-53
# Errors up to this many units of roundoff per unit of condition number are the problem's.
CONDITION_ALLOWANCE = 64.0
SMALL_LOAD_CHANGE = 1e-9  # the report's "small dP/P1" column
MIN_RELATIVE_LOAD_CHANGE, MAX_RELATIVE_LOAD_CHANGE = 1e-12, 0.3
NEAR_CANCELLATION_SHARE = 0.2

Problem = dict[str, float]


# ---------------------------------------------------------------------------------------------
# Problems
# ---------------------------------------------------------------------------------------------


def normal_multiplier(law: LawCase, P: mpmath.mpf, parameters) -> mpmath.mpf:
    """(19) on the law: L_I(P) = (1/pi) sqrt(2/a) dP/da at a = a(P)."""
    a = law.half_width(P, parameters)
    return mpmath.sqrt(2 / a) * law.load_slope(a, parameters) / mpmath.pi


def draw_problem(
    rng: np.random.Generator,
    law: LawCase,
    *,
    relative_load_change: float | None = None,
    near_cancellation: bool = False,
) -> Problem | None:
    """One random problem as doubles, or None when the draw is not a valid partial-slip cycle.

    Derived values (a1, a2, da, multipliers, b, ...) are computed exactly (50 digits) from the
    drawn doubles and then rounded once, so every input is as accurate as a double can be.
    """
    parameters = law.parameters(rng)
    mu = rng.uniform(0.05, 1.5)
    P1 = float(10.0 ** rng.uniform(0.0, 6.0))
    if relative_load_change is None:
        low, high = math.log10(MIN_RELATIVE_LOAD_CHANGE), math.log10(MAX_RELATIVE_LOAD_CHANGE)
        relative_load_change = float(10.0 ** rng.uniform(low, high))
    dP = P1 * relative_load_change

    mp = {key: mpmath.mpf(value) for key, value in parameters.items()}
    P1_, dP_, mu_ = mpmath.mpf(P1), mpmath.mpf(dP), mpmath.mpf(mu)
    a1 = law.half_width(P1_, mp)
    a2 = law.half_width(P1_ + dP_, mp)
    # pi eta a1 / (4 mu) and lam / mu of order one, both signs.
    eta = float(4 * mu_ * rng.uniform(-1.5, 1.5) / (mpmath.pi * a1))
    eta_ = mpmath.mpf(eta)
    if near_cancellation:
        # lam/mu + pi eta a1/(4 mu) = 1 +- 10^-k: the slip-zone width nearly vanishes.
        offset = rng.choice([-1.0, 1.0]) * 10.0 ** -rng.uniform(2.0, 12.0)
        lam = float(mu_ * (1 + offset) - mpmath.pi * eta_ * a1 / 4)
    else:
        # Both signs; lam/mu + pi eta a1/(4 mu) > 1 (slip zone inside a1) about half the time.
        lam = float(mu_ * rng.uniform(-2.0, 4.0))
    lam_ = mpmath.mpf(lam)

    L_I1 = normal_multiplier(law, P1_, mp)
    L_I2 = normal_multiplier(law, P1_ + dP_, mp)
    L_II1 = (lam_ + mpmath.pi * eta_ * a1 / 4) * L_I1  # (21)
    L_II2 = (lam_ + mpmath.pi * eta_ * a2 / 4) * L_I2
    c1, c2 = mu_ * L_I1 + L_II1, mu_ * L_I2 - L_II2
    if c1 + c2 <= 0:
        return None
    b = (c2 * a2 + c1 * a1) / (c1 + c2)  # (17)
    # Valid: a slip zone b < x < a2 exists, and growth and slip zone are small (Section 2.2).
    if not (b < a2 and abs(a1 - b) <= a1 / 2 and a2 - a1 <= a1 / 5):
        return None
    dP_da1 = law.load_slope(a1, mp)
    # P''(a1) by differentiating the law's slope (no root finding): a''(P) = -P''/P'^3 and,
    # from (19) by the product rule, dL_I/dP = sqrt(2/a) (P'' - P'/(2a)) / (pi P').
    d2P_da2 = mpmath.diff(lambda a: law.load_slope(a, mp), a1)
    dL_I_dP = mpmath.sqrt(2 / a1) * (d2P_da2 - dP_da1 / (2 * a1)) / (mpmath.pi * dP_da1)

    x_slip = b + mpmath.mpf(rng.uniform(0.02, 0.98)) * (a2 - b)
    # From the edge to the centre, log-uniform in the distance from a2.
    distance = (a2 - b) * mpmath.mpf(10.0 ** rng.uniform(-1.0, math.log10(float(a2 / (a2 - b)))))
    x_contact = a2 - min(distance, a2 * mpmath.mpf("0.999"))

    exact = {
        "a1": a1,
        "a2": a2,
        "da": a2 - a1,
        "L_I1": L_I1,
        "L_I2": L_I2,
        "L_II1": L_II1,
        "L_II2": L_II2,
        "b": b,
        "width": a1 - b,
        "relative_growth": (a2 - a1) / a1,
        "dP_da1": dP_da1,
        "da_dP": 1 / dP_da1,
        "dL_I_dP": dL_I_dP,
        "d2a_dP2": -d2P_da2 / dP_da1**3,
        "dQ_da": lam_ * dP_da1,
        "dsigma_da": eta_ * dP_da1,
        "x_slip": x_slip,
        "x_contact": x_contact,
        # the dimensionless groups of second_order.slip_zone_width_second_order_dimensionless
        "lam_mu": lam_ / mu_,
        "eta_a1_mu": eta_ * a1 / mu_,
        "growth": dP_ / (dP_da1 * a1),
        "multiplier": L_I1 * a1 ** mpmath.mpf(1.5) / dP_,
        "multiplier_slope": dL_I_dP * a1 ** mpmath.mpf(1.5),
        "P_K": P1_ + dP_ * (mu_ - lam_) / (2 * mu_),
        # s = log a against u = log P: s' = P a'/a, s'' = s' + P^2 a''/a - s'^2.
        "log_slope1": P1_ / (dP_da1 * a1),
        "log_curvature1": P1_ / (dP_da1 * a1)
        + P1_**2 * (-d2P_da2 / dP_da1**3) / a1
        - (P1_ / (dP_da1 * a1)) ** 2,
    }
    if law.extras is not None:
        exact.update(law.extras(a1, mp))
    problem = {key: float(value) for key, value in exact.items()}
    problem.update(parameters)
    problem.update(mu=mu, lam=lam, eta=eta, P1=P1, dP=dP, P2=P1 + dP)
    problem.update(load_cycle(rng, problem))
    problem["relative_load_change"] = dP / P1
    problem["near_cancellation"] = float(near_cancellation)
    # the other edge's relative slip direction (second_order), +-1 without a further draw
    problem["other_edge"] = 1.0 if lam >= 0 else -1.0
    return problem


def load_cycle(rng: np.random.Generator, problem: Problem) -> Problem:
    """The problem as a user states it to ``asymslip.slip_zone``: doubles P1, Q1, sigma1 and
    the changes dP_cycle, dQ, dsigma whose sums P2, Q2, sigma2 are exact.

    The API forms P2 - P1, Q2 - Q1 and sigma2 - sigma1; with exact differences the only
    roundings before the law are those of lam = dQ/dP and eta = dsigma/dP, which the
    condition numbers in (dQ, dsigma) account for.  P2 - P1 is exact (Sterbenz: P2 < 2 P1).
    """
    P1, P2 = problem["P1"], problem["P2"]
    dP_cycle = P2 - P1
    assert mpmath.mpf(P2) - mpmath.mpf(P1) == dP_cycle
    cycle = {"dP_cycle": dP_cycle}
    for start, change, slope, scale in (
        ("Q1", "dQ", problem["lam"], problem["mu"] * P1),
        ("sigma1", "dsigma", problem["eta"], abs(problem["eta"]) * P1),
    ):
        first = float(scale * rng.uniform(-0.5, 0.5))
        second = first + slope * dP_cycle
        if mpmath.mpf(second) - mpmath.mpf(first) != second - first:
            first, second = 0.0, slope * dP_cycle  # the difference is then exact
        cycle[start], cycle[change] = first, second - first
    return cycle


def draw_problems(
    count: int,
    seed: int,
    *,
    laws: Iterable[str] | None = None,
    relative_load_change: float | None = None,
    near_cancellation_share: float = NEAR_CANCELLATION_SHARE,
) -> list[tuple[str, Problem]]:
    """``count`` valid problems per law, as (law name, problem) pairs, reproducible by seed."""
    rng = np.random.default_rng(seed)
    problems: list[tuple[str, Problem]] = []
    with mpmath.workdps(DIGITS):
        for name in laws or LAWS:
            law, made = LAWS[name], 0
            while made < count:
                near = rng.uniform() < near_cancellation_share
                problem = draw_problem(
                    rng, law, relative_load_change=relative_load_change, near_cancellation=near
                )
                if problem is not None:
                    problems.append((name, problem))
                    made += 1
    return problems


# ---------------------------------------------------------------------------------------------
# Evaluation
# ---------------------------------------------------------------------------------------------


@dataclass
class QuantityResult:
    """Errors of one quantity over the problems it applies to."""

    quantity: Quantity
    status: str  # "checked" or why not
    samples: int = 0
    errors: list[float] = field(default_factory=list)
    conditions: list[float] = field(default_factory=list)  # nan where not computed
    load_changes: list[float] = field(default_factory=list)
    laws: list[str] = field(default_factory=list)  # the law of each sample

    @property
    def max_error(self) -> float:
        return max(self.errors, default=math.nan)

    @property
    def max_error_small_load_change(self) -> float:
        pairs = zip(self.errors, self.load_changes, strict=True)
        small = [error for error, change in pairs if change <= SMALL_LOAD_CHANGE]
        return max(small, default=math.nan)

    def max_error_by_law(self) -> dict[str, float]:
        worst: dict[str, float] = {}
        for error, law in zip(self.errors, self.laws, strict=True):
            worst[law] = max(worst.get(law, 0.0), error)
        return worst

    @property
    def max_condition(self) -> float:
        known = [c for c in self.conditions if not math.isnan(c)]
        return max(known, default=math.nan)

    def normalised(self) -> list[float]:
        """Errors in units of roundoff per unit of condition (nan where kappa not computed)."""
        pairs = zip(self.errors, self.conditions, strict=True)
        return [error / (UNIT_ROUNDOFF * max(kappa, 1.0)) for error, kappa in pairs]

    @property
    def max_normalised(self) -> float:
        known = [n for n in self.normalised() if not math.isnan(n)]
        return max(known, default=math.nan)

    @property
    def over_target(self) -> int:
        return sum(e > TARGET for e in self.errors)

    @property
    def unexplained(self) -> int:
        """Samples over the target that conditioning does not account for."""
        return sum(
            e > TARGET and not (n <= CONDITION_ALLOWANCE)
            for e, n in zip(self.errors, self.normalised(), strict=True)
        )

    @property
    def verdict(self) -> str:
        if self.status != "checked":
            return self.status
        if self.over_target == 0:
            return "meets 1e-12"
        if self.unexplained == 0:
            return f"within conditioning ({self.over_target} ill-conditioned samples)"
        return f"FAILS ({self.unexplained} samples unexplained)"


def resolve(quantity: Quantity) -> Callable[..., object] | str:
    """The generated function, or a reason it cannot be checked."""
    module_name, function_name = quantity.function.rsplit(".", 1)
    try:
        module = importlib.import_module(f"asymslip_gen.{module_name}")
    except ModuleNotFoundError:
        return "not generated yet"
    function = getattr(module, function_name, None)
    if function is None:
        return "not generated yet"
    expected = [parameter for parameter, _ in quantity.parameters]
    if quantity.compose is None:
        actual = list(inspect.signature(function).parameters)
        if actual != expected:
            # Reported per quantity (and fails its tests) rather than stopping the whole run.
            return (
                f"SIGNATURE CHANGED: generated ({', '.join(actual)}), registered "
                f"({', '.join(expected)}); update tests/accuracy/references.py"
            )
        return function
    return quantity.compose


def condition_number(
    reference: Callable[..., mpmath.mpf], arguments: dict[str, mpmath.mpf], value: mpmath.mpf
) -> float:
    """Componentwise relative condition number of ``reference`` at ``arguments``.

    Forward differences with relative step 1e-20 at 50 digits: accurate to ~1e-20 relative,
    far more than the two digits a condition number needs.
    """
    if value == 0:
        return math.inf
    step = mpmath.mpf(10) ** -20
    total = mpmath.mpf(0)
    for name, x in arguments.items():
        if x == 0:
            continue
        shifted = dict(arguments)
        shifted[name] = x * (1 + step)
        total += abs(reference(**shifted) - value) / step
    return float(total / abs(value))


def evaluate(
    quantity: Quantity,
    problems: list[tuple[str, Problem]],
    *,
    progress: Callable[[int, int], None] | None = None,
    every_condition: bool = True,
) -> QuantityResult:
    """Errors of one generated quantity against its reference on the applicable problems.

    Condition numbers cost one reference per argument.  They are computed for every sample
    over the target; for the others only with ``every_condition`` (the report's "Max kappa"
    column) and never for costly or thinned-out references.  Without them the verdicts are
    the same: a sample that meets the target needs no explanation (its kappa is nan).
    """
    function = resolve(quantity)
    if isinstance(function, str):
        return QuantityResult(quantity, function)
    chosen_with_law = [
        (law, problem)
        for law, problem in problems
        if (not quantity.laws or law in quantity.laws)
        and (quantity.where is None or quantity.where(problem))
    ][:: quantity.every]
    chosen = [problem for _, problem in chosen_with_law]
    result = QuantityResult(quantity, "checked", samples=len(chosen))
    result.laws = [law for law, _ in chosen_with_law]
    if not chosen:
        result.status = "no applicable problems"
        return result
    keywords = {
        parameter: np.array([problem[key] for problem in chosen], dtype=np.float64)
        for parameter, key in quantity.parameters
    }
    # Valid input must not raise NumPy warnings (the test suite runs with -W error anyway).
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        computed = np.broadcast_to(
            np.asarray(function(**keywords), dtype=np.float64), (len(chosen),)
        )
    # Condition numbers cost one reference per argument: skip them for quadrature references
    # unless the error needs explaining.
    always_condition = every_condition and quantity.every == 1 and not quantity.costly
    with mpmath.workdps(DIGITS):
        for index, problem in enumerate(chosen):
            arguments = {
                parameter: mpmath.mpf(problem[key]) for parameter, key in quantity.parameters
            }
            exact = quantity.reference(**arguments)
            if exact == 0:
                error = abs(float(computed[index]))
            else:
                error = float(abs((mpmath.mpf(float(computed[index])) - exact) / exact))
            condition = math.nan
            if always_condition or error > TARGET:
                condition = condition_number(quantity.reference, arguments, exact)
            result.errors.append(error)
            result.conditions.append(condition)
            result.load_changes.append(problem["relative_load_change"])
            if progress is not None and (index + 1) % 200 == 0:
                progress(index + 1, len(chosen))
    return result


def unchecked_generated_functions() -> list[str]:
    """Generated functions that no registered quantity checks."""
    import asymslip_gen

    checked = {quantity.function.rsplit(".", 1)[-1] for quantity in QUANTITIES.values()}
    return sorted(name for name in asymslip_gen.__all__ if name not in checked)


def run(
    samples: int,
    seed: int,
    *,
    select: str = "",
    relative_load_change: float | None = None,
    near_cancellation_share: float = NEAR_CANCELLATION_SHARE,
    verbose: bool = False,
    every_condition: bool = True,
) -> list[QuantityResult]:
    """Draw ``samples`` problems per law and evaluate every registered quantity on them.

    ``select`` keeps the quantities whose name contains it; ``relative_load_change`` fixes
    dP/P1 instead of drawing it; ``every_condition=False`` computes condition numbers only
    where an error is over the target (same verdicts, about a third of the time).
    """
    start = time.perf_counter()
    problems = draw_problems(
        samples,
        seed,
        relative_load_change=relative_load_change,
        near_cancellation_share=near_cancellation_share,
    )
    if verbose:
        print(
            f"drew {len(problems)} problems in {time.perf_counter() - start:.1f} s", file=sys.stderr
        )
    chosen = [q for q in QUANTITIES.values() if select in q.name]
    results = []
    for number, quantity in enumerate(chosen, start=1):
        started = time.perf_counter()

        def progress(done: int, total: int, number=number, name=quantity.name) -> None:
            print(
                f"\r[{number}/{len(chosen)}] {name}: {done}/{total} samples",
                end="",
                file=sys.stderr,
                flush=True,
            )

        result = evaluate(
            quantity,
            problems,
            progress=progress if verbose else None,
            every_condition=every_condition,
        )
        results.append(result)
        if verbose:
            print(
                f"\r[{number}/{len(chosen)}] {quantity.name}: {result.samples} samples, "
                f"max rel. error {result.max_error:.1e}, {time.perf_counter() - started:.1f} s",
                file=sys.stderr,
                flush=True,
            )
    return results


# ---------------------------------------------------------------------------------------------
# Report
# ---------------------------------------------------------------------------------------------


def _number(value: float) -> str:
    return "-" if math.isnan(value) else f"{value:.1e}"


def report(
    results: list[QuantityResult],
    samples: int,
    seed: int,
    *,
    relative_load_change: float | None = None,
    near_cancellation_share: float = NEAR_CANCELLATION_SHARE,
) -> str:
    laws = ", ".join(LAWS)
    load_change = (
        f"dP/P1 = {relative_load_change:g}"
        if relative_load_change is not None
        else f"dP/P1 log-uniform in [{MIN_RELATIVE_LOAD_CHANGE:g}, {MAX_RELATIVE_LOAD_CHANGE:g}]"
    )
    lines = [
        f"Accuracy against {DIGITS}-digit mpmath: {samples} problems per law ({laws}), seed "
        f"{seed}; {load_change}, {near_cancellation_share:.0%} drawn near "
        "lam/mu + pi eta a1/(4 mu) = 1.",
        f"Target {TARGET:g} relative; errors above it are explained when <= "
        f"{CONDITION_ALLOWANCE:g} u kappa (u = 2^-53, kappa = componentwise condition number).",
        "",
        f"| Quantity | Eqs | Samples | Max rel. error | at dP/P1 <= {SMALL_LOAD_CHANGE:g} | "
        "Max kappa | Max error / (u max(kappa, 1)) | Verdict |",
        "| --- | --- | ---: | ---: | ---: | ---: | ---: | --- |",
    ]
    for result in results:
        q = result.quantity
        lines.append(
            f"| {q.name} | {', '.join(q.equations)} | {result.samples} | "
            f"{_number(result.max_error)} | {_number(result.max_error_small_load_change)} | "
            f"{_number(result.max_condition)} | {_number(result.max_normalised)} | "
            f"{result.verdict} |"
        )
    names = list(LAWS)
    lines += [
        "",
        "Max rel. error by contact law (- : not applicable):",
        "",
        "| Quantity | " + " | ".join(names) + " |",
        "| --- |" + " ---: |" * len(names),
    ]
    for result in results:
        by_law = result.max_error_by_law()
        cells = [_number(by_law.get(name, math.nan)) for name in names]
        lines.append(f"| {result.quantity.name} | " + " | ".join(cells) + " |")
    unchecked = unchecked_generated_functions()
    lines += [
        "",
        "Generated functions without a registered reference: "
        + (", ".join(unchecked) if unchecked else "none"),
    ]
    return "\n".join(lines)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(
        prog="python -m tests.accuracy.harness", description=__doc__.split("\n\n")[0]
    )
    parser.add_argument("--samples", type=int, default=2000, help="problems per contact law")
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--select", default="", help="only quantities whose name contains this")
    parser.add_argument(
        "--dP-over-P1",
        type=float,
        default=None,
        dest="relative_load_change",
        help="fix dP/P1 (e.g. 1e-12) instead of drawing it",
    )
    parser.add_argument(
        "--near-cancellation",
        type=float,
        default=NEAR_CANCELLATION_SHARE,
        help="share of problems drawn near lam/mu + pi eta a1/(4 mu) = 1",
    )
    parser.add_argument("--quiet", action="store_true", help="no progress lines on stderr")
    args = parser.parse_args(argv)
    results = run(
        args.samples,
        args.seed,
        select=args.select,
        relative_load_change=args.relative_load_change,
        near_cancellation_share=args.near_cancellation,
        verbose=not args.quiet,
    )
    print(
        report(
            results,
            args.samples,
            args.seed,
            relative_load_change=args.relative_load_change,
            near_cancellation_share=args.near_cancellation,
        )
    )
    failed = [
        r
        for r in results
        if (r.status == "checked" and r.unexplained) or r.status.startswith("SIGNATURE")
    ]
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
