"""The slip-zone core: one scalar call against its kernel, and 10^6 cycles law against law.

(s) One ``slip_zone(law, cycle, mu, edge="both")`` on the paper's Fig. 5 cycle (Hertz,
    R = E* = 1, P1 = 100, Q1 = 0, P2 = 105, Q2 = 1, mu = 0.1), against one call of the
    generated kernel of its headline width (b to second order,
    ``slip_zone_width_second_order_from_multiplier`` of ``asymslip_gen.scalar``, the ``math``
    backend the core uses for one cycle) on the same cycle's Python floats --
    the two interleaved in one process.  Also ``evaluate`` alone (the core without the result
    objects), to show where the time goes.
(l) 10^6 cycles, both edges, through :func:`asymslip.slip_zones.evaluate`, law against Hertz:
    the rounded flat (a(P) by Newton), the table law (a monotone log-log cubic through 20 FE-like
    points of the rounded flat) and the power law n = 1.5 (closed form).  Every law sees cycles
    of the same shape: contact half-widths a1 from 1.1 to 3 (the flat's half-width is 1), load
    steps dP/P1 from 1e-4 to 0.05, both slip directions and no-slip cycles, no bulk tension
    (so that the exact b = a(P_K) is computed too: the costliest path for a law without a
    closed-form inverse; the targets are judged here).  The same with bulk tension, where no
    exact b exists, for information.
"""

from __future__ import annotations

import sys
from collections.abc import Callable
from pathlib import Path

import numpy as np

import asymslip_gen
from asymslip import FlatRoundedLaw, HertzLaw, LoadCycle, PowerLaw, TableLaw, slip_zone
from asymslip.slip_zones import evaluate
from asymslip_gen.scalar import slip_zone_width_second_order_from_multiplier

from .timing import Row, duration, interleaved, times, verdict
from .timing import count as number

SCALAR_TARGET = 30e-6  # seconds
LAW_TARGETS = {"flat-rounded": 3.0, "table": 2.0}


def generated_calls(function: Callable[[], object]) -> int:
    """How many calls into ``asymslip_gen`` one call of ``function`` makes (a profile hook)."""
    folder = str(Path(asymslip_gen.__file__).parent)
    count = 0

    def hook(frame, event, argument) -> None:  # noqa: ANN001
        nonlocal count
        if event == "call" and frame.f_code.co_filename.startswith(folder):
            count += 1

    sys.setprofile(hook)
    try:
        function()
    finally:
        sys.setprofile(None)
    return count


def bench_scalar(rounds: int, calls: int) -> list[Row]:
    law = HertzLaw(R=1.0, E_star=1.0)
    cycle = LoadCycle(P1=100.0, Q1=0.0, P2=105.0, Q2=1.0)
    mu = 0.1
    result = slip_zone(law, cycle, mu, edge="both")
    # The headline kernel's arguments for this cycle, as the core passes them: Python floats
    # (the left edge slips backward, so the other edge's factor is +1).
    state = law.cycle_state(100.0, 5.0)
    arguments = (
        mu,
        result.lam,
        result.eta,
        result.a1,
        float(state.a_slope1),
        result.L_I1,
        float(state.L_I_slope1),
        5.0,
        1.0,
    )
    width = slip_zone_width_second_order_from_multiplier(*arguments)
    if not np.isclose(width, result.slip_zone_width, rtol=1e-12):
        raise RuntimeError(
            f"the headline kernel gives {width}, slip_zone "
            f"{result.slip_zone_width}: the core wraps another kernel now"
        )
    kernel_calls = generated_calls(lambda: slip_zone(law, cycle, mu, edge="both"))
    # With bulk tension the left edge no longer mirrors the right one: both edges are computed
    # (one generated program for the two).
    tension = LoadCycle(P1=100.0, Q1=0.0, P2=105.0, Q2=1.0, sigma1=0.0, sigma2=0.5)
    measured = interleaved(
        {
            "slip_zone": lambda: slip_zone(law, cycle, mu, edge="both"),
            "tension": lambda: slip_zone(law, tension, mu, edge="both"),
            "evaluate": lambda: evaluate(law, cycle, mu),
            "kernel": lambda: slip_zone_width_second_order_from_multiplier(*arguments),
        },
        rounds,
        calls=calls,
    )
    t = {name: measured.best(name) for name in ("slip_zone", "tension", "evaluate", "kernel")}
    return [
        Row(
            'one scalar `slip_zone(HertzLaw(1, 1), LoadCycle(100, 0, 105, 1), 0.1, edge="both")`',
            duration(t["slip_zone"]),
            "",
            "",
            f"<= {SCALAR_TARGET * 1e6:g} µs",
            verdict(t["slip_zone"] <= SCALAR_TARGET),
            f"{measured.clock_words(calls)}; the paper's Fig. 5 "
            "cycle, both edges, result objects built",
        ),
        Row(
            "same, against the generated kernel of its headline width (`asymslip_gen.scalar."
            "slip_zone_width_second_order_from_multiplier`, one call on Python floats)",
            duration(t["slip_zone"]),
            duration(t["kernel"]),
            times(measured.ratio("slip_zone", "kernel")),
            "(information)",
            "-",
            measured.how("slip_zone", "kernel", calls) + f"; one `slip_zone` makes "
            f"{kernel_calls} calls into `asymslip_gen` (counted by a profile hook)",
        ),
        Row(
            "same cycle with bulk tension (sigma2 = 0.5): the left edge no longer mirrors the "
            "right one, so both edges are computed (one generated program for the two)",
            duration(t["tension"]),
            duration(t["slip_zone"]),
            times(measured.ratio("tension", "slip_zone")),
            "(information)",
            "-",
            measured.how("tension", "slip_zone", calls),
        ),
        Row(
            "the core alone (`asymslip.core.evaluation.evaluate`, no result objects) on the "
            "Fig. 5 cycle: the one edge pipeline on Python floats, both edges",
            duration(t["evaluate"]),
            duration(t["slip_zone"]),
            times(measured.ratio("evaluate", "slip_zone")),
            "(information)",
            "-",
            measured.how("evaluate", "slip_zone", calls),
        ),
    ]


# --- 10^6 cycles, law against law ---------------------------------------------------------------
def laws() -> dict[str, object]:
    """The laws compared, each with half-widths of the same size for the same cycles."""
    flat = FlatRoundedLaw(c=1.0, R=10.0, E_star=1.0)
    # An FE-like table: 20 loads, geometric, spanning every load the cycles reach.
    loads = np.geomspace(float(flat.load(1.05)), float(flat.load(3.3)), 20)
    return {
        "hertz": HertzLaw(R=10.0, E_star=1.0),
        "flat-rounded": flat,
        "table": TableLaw(loads, flat.half_width(loads)),
        "power": PowerLaw(A=0.1, n=1.5, E_star=1.0),
    }


def cycles_for(
    law: object, count: int, mu: float, tension: bool = False, seed: int = 0
) -> LoadCycle:
    """Valid cycles of ``law``: a1 in (1.1, 3), dP/P1 in (1e-4, 0.05), |dQ/dP| < 1.5 mu; with
    ``tension``, a bulk-tension slope eta = dsigma/dP in (-0.02, 0.02) (no exact b then)."""
    rng = np.random.default_rng(seed)
    a1 = rng.uniform(1.1, 3.0, count)
    P1 = np.asarray(law.load(a1), dtype=np.float64)
    dP = P1 * 10.0 ** rng.uniform(-4.0, np.log10(0.05), count)
    Q1 = rng.uniform(-0.3, 0.3, count) * mu * P1
    Q2 = Q1 + rng.uniform(-1.5, 1.5, count) * mu * dP
    sigma2 = rng.uniform(-0.02, 0.02, count) * dP if tension else 0.0
    return LoadCycle(P1, Q1, P1 + dP, Q2, 0.0, sigma2)


def bench_laws(count: int, rounds: int, mu: float = 0.3) -> list[Row]:
    work = {}
    for name, law in laws().items():
        work[name] = (law, cycles_for(law, count, mu))
        if name != "power":
            work[name + " tension"] = (law, cycles_for(law, count, mu, tension=True))
    for name, (law, cycle) in work.items():
        evaluation = evaluate(law, cycle, mu)
        valid = int(np.count_nonzero(evaluation.verdict.valid))
        if valid != count:
            raise RuntimeError(
                f"{name}: {count - valid} of {count} benchmark cycles invalid: "
                f"{evaluation.verdict.messages()[0]}"
            )
    measured = interleaved(
        {
            name: (lambda law=law, cycle=cycle: evaluate(law, cycle, mu))
            for name, (law, cycle) in work.items()
        },
        rounds,
    )
    hertz = measured.best("hertz")
    rows = [
        Row(
            f"{number(count)} cycles, both edges, `evaluate`: Hertz",
            duration(hertz),
            "",
            "",
            "(information)",
            "-",
            f"{measured.clock_words()}; every cycle valid; no bulk "
            "tension, so the exact b = a(P_K) is computed too",
        )
    ]
    described = {
        "flat-rounded": "rounded flat (c = 1, R = 10) / Hertz",
        "table": "table law (20 points of the rounded flat) / Hertz",
        "power": "power law (n = 1.5) / Hertz",
        "flat-rounded tension": "with bulk tension (no exact b to solve for): rounded flat / Hertz",
        "table tension": "with bulk tension: table law / Hertz",
    }
    for name, words in described.items():
        baseline = "hertz tension" if name.endswith("tension") else "hertz"
        ratio = measured.ratio(name, baseline)
        target = None if name.endswith("tension") else LAW_TARGETS.get(name)
        rows.append(
            Row(
                f"same: {words}",
                duration(measured.best(name)),
                duration(measured.best(baseline)),
                times(ratio),
                f"<= {target:g}x" if target else "(information)",
                verdict(ratio <= target) if target else "-",
                measured.how(name, baseline),
            )
        )
    return rows
