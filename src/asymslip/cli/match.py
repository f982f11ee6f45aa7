"""``asymslip match``: the laboratory rig cycle whose contact edge reproduces a prototype's."""

from __future__ import annotations

import argparse
import json
import math
import sys
from pathlib import Path

from ..errors import InputError
from ..match import FAMILIES, Available, MatchResult, Rig, SolverProblem, match, verify
from ..match.near_edge_stress import DEPTHS, FARTHEST, StressComparison
from .cycle_options import add_cycle_options, build_cycle
from .laws import add_law_options, build_law, parse_assignments
from .parser import number, whole_number

#: This command's API parameters -> the options that set them, for one-line errors.
OPTIONS = {
    "rig": "--rig",
    "rig_E_star": "--rig-E-star",
    "rig_mu": "--rig-mu",
    "rig_R": "--rig-R",
    "rig_c": "--rig-flat-half-width",
    "rig_max_P": "--rig-max-P",
    "rig_max_Q": "--rig-max-Q",
    "rig_max_sigma": "--rig-max-sigma",
    "verify": "--verify",
    "verify_profile": "--verify-profile",
    "verify_E_star": "--verify-E-star",
    "verify_path": "--verify-path",
    "verify_param": "--verify-param",
    "verify_profile_table": "--verify-profile-table",
    # The solver's profile errors name its own parameter; here it was set by these options.
    "profile": "--verify-profile",
    "profile_table": "--verify-profile-table",
}


def register(commands: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    parser = commands.add_parser(
        "match",
        help="the laboratory rig cycle whose contact edge reproduces a prototype's",
        description="Design the laboratory test (a Hertz pad or a rounded flat, with its loads, "
        "shear force and bulk tension) whose contact edge has the prototype's L_I1, L_I2, "
        "L_II1, L_II2 and a2 - a1, so that its slip zone, shear change and slip are the "
        "prototype's to leading order; exactly where the rig allows (second order for a "
        "rounded flat of free dimensions), else the closest by the stated edge-state "
        "mismatch.  The prototype is given as for slip-zone.",
    )
    add_law_options(parser)
    add_cycle_options(parser)
    parser.add_argument(
        "--edge", choices=["right", "left"], default="right", help="the prototype's edge"
    )
    rig = parser.add_argument_group("the rig")
    rig.add_argument("--rig", choices=FAMILIES, required=True, help="the rig's pad family")
    rig.add_argument(
        "--rig-E-star",
        dest="rig_E_star",
        type=number,
        help="the rig's plane-strain modulus E* (default: the prototype law's)",
    )
    rig.add_argument(
        "--rig-mu", dest="rig_mu", type=number, help="the rig's friction (default: --mu)"
    )
    rig.add_argument(
        "--rig-R",
        dest="rig_R",
        type=number,
        nargs="+",
        metavar="R",
        help="the radii available: the pad's (hertz) or its corners' (flat-rounded)",
    )
    rig.add_argument(
        "--rig-R-range",
        dest="rig_R_range",
        type=number,
        nargs=2,
        metavar=("LOW", "HIGH"),
        help="the radii available as a range (HIGH may be inf)",
    )
    rig.add_argument(
        "--rig-flat-half-width",
        dest="rig_c",
        type=number,
        nargs="+",
        metavar="C",
        help="the flat half-widths available (flat-rounded)",
    )
    rig.add_argument(
        "--rig-flat-half-width-range",
        dest="rig_c_range",
        type=number,
        nargs=2,
        metavar=("LOW", "HIGH"),
        help="the flat half-widths available as a range (flat-rounded)",
    )
    for name, text in (
        ("P", "the largest normal load"),
        ("Q", "the largest |shear force|"),
        ("sigma", "the largest |bulk tension|"),
    ):
        rig.add_argument(f"--rig-max-{name}", dest=f"rig_max_{name}", type=number, help=text)
    rig.add_argument(
        "--rig-no-tension", action="store_true", help="the rig cannot apply bulk tension"
    )
    check = parser.add_argument_group("verification by the reference solver")
    check.add_argument("--verify", action="store_true", help="solve both contacts and compare")
    check.add_argument(
        "--elements", type=whole_number, default=2000, help="the prototype's elements"
    )
    check.add_argument(
        "--verify-profile",
        dest="verify_profile",
        metavar="EXPR",
        help="the prototype's gap h(x), where its law has no profile (table, module, "
        "calibrated); parameters with --verify-param",
    )
    check.add_argument("--verify-param", dest="verify_param", action="append", metavar="NAME=VALUE")
    check.add_argument(
        "--verify-profile-table",
        dest="verify_profile_table",
        type=Path,
        metavar="FILE.csv",
        help="the prototype's gap h(x) tabulated (columns x, h), in place of --verify-profile",
    )
    check.add_argument("--verify-E-star", dest="verify_E_star", type=number)
    check.add_argument(
        "--verify-path",
        dest="verify_path",
        type=Path,
        metavar="PATH.csv",
        help="the prototype's load path P,Q[,sigma,M] (first two points: states 1 and 2), "
        "where a moment varies along it",
    )
    parser.add_argument("--json", action="store_true", help="print one JSON object")
    parser.set_defaults(run=run)


def _available(parameter: str, values: list[float] | None, span: list[float] | None) -> Available:
    if values is not None and span is not None:
        option = OPTIONS[parameter]
        raise InputError(parameter, f"give either {option} or {option}-range, not both")
    if values is not None:
        return Available.listed(parameter, values)
    if span is not None:
        return Available.between(parameter, span[0], span[1])
    return Available()


def _rig(args: argparse.Namespace, law: object) -> Rig:
    E_star = args.rig_E_star if args.rig_E_star is not None else getattr(law, "E_star", None)
    if E_star is None:
        raise InputError("rig_E_star", f"is required: the {args.law} law has no E*")
    if args.rig == "hertz" and (args.rig_c is not None or args.rig_c_range is not None):
        raise InputError("rig_c", "a flat half-width needs --rig flat-rounded")
    return Rig(
        args.rig,
        E_star,
        mu=args.rig_mu,
        radius=_available("rig_R", args.rig_R, args.rig_R_range),
        flat_half_width=_available("rig_c", args.rig_c, args.rig_c_range),
        max_P=math.inf if args.rig_max_P is None else args.rig_max_P,
        max_Q=math.inf if args.rig_max_Q is None else args.rig_max_Q,
        max_sigma=math.inf if args.rig_max_sigma is None else args.rig_max_sigma,
        tension=not args.rig_no_tension,
    )


def _prototype_problem(args: argparse.Namespace, law: object) -> SolverProblem | None:
    """The prototype for the solver: None (the law's own profile) or the given profile."""
    from ..solver import ExpressionProfile, LoadPath, TableProfile

    loading = LoadPath.from_csv(args.verify_path) if args.verify_path is not None else None
    given = [args.verify_profile is not None, args.verify_profile_table is not None]
    if all(given):
        raise InputError("verify_profile", "give either it or --verify-profile-table, not both")
    if not any(given):
        if not hasattr(law, "profile"):
            raise InputError(
                "verify_profile",
                f"is required with --verify: the {args.law} law has no profile for the solver "
                "(or give --verify-profile-table)",
            )
        return None if loading is None else SolverProblem(law, loading)
    if args.verify_E_star is None:
        raise InputError("verify_E_star", "is required with a --verify profile")
    if args.verify_profile is not None:
        parameters = parse_assignments("verify_param", args.verify_param)
        profile: object = ExpressionProfile(args.verify_profile, parameters)
    else:
        profile = TableProfile.from_csv(args.verify_profile_table)
    cycle = loading if loading is not None else build_cycle(args)
    return SolverProblem(profile, cycle, args.verify_E_star)


def _number(value: float) -> str:
    return f"{value:.10g}"


def format_answer(result: MatchResult) -> str:
    """The human-readable answer."""
    data = result.to_dict()
    rig = data["rig"]
    assert isinstance(rig, dict)
    pad = ", ".join(
        f"{key} = {value if isinstance(value, str) else _number(value)}"
        for key, value in rig.items()
    )
    lines = [f"Rig: {pad}", f"Cycle (edge {result.edge}):"]
    for key in ("P1", "Q1", "sigma1", "P2", "Q2", "sigma2"):
        lines.append(f"  {key:<8} {_number(float(getattr(result.cycle, key)))}")
    lines.append(
        f"Match: {result.order}{' (exact)' if result.exact else ''}; stated accuracy "
        f"of the slip-zone width {result.accuracy:.3g}; edge-state mismatch "
        f"{result.measure:.3g}; gross-sliding margin {result.margin:.3f}"
    )
    lines.append(f"  {'quantity':<18} {'prototype':>16} {'rig':>16}")
    for key, pair in result.matched.items():
        lines.append(f"  {key:<18} {_number(pair.prototype):>16} {_number(pair.rig):>16}")
    lines.append(
        f"  {'width accuracy':<18} {_number(result.width_accuracy.prototype):>16} "
        f"{_number(result.width_accuracy.rig):>16}"
    )
    lines.append(
        f"  {'peak shear change':<18} {_number(result.peak_shear_change.prototype):>16} "
        f"{_number(result.peak_shear_change.rig):>16}"
    )
    for key in ("eq24", "eq25", "eq26", "eq27"):
        lines.append(
            f"  {key:<18} {_number(float(result.prototype.validity[key])):>16} "
            f"{_number(float(result.rig_result.validity[key])):>16}"
        )
    if result.unmatched:
        lines.append("Not matched:")
        lines.extend(f"  - {text}" for text in result.unmatched)
    if result.verification is not None:
        check = result.verification
        lines.append("Verification (reference solver):")
        lines.append(
            f"  slip-zone width: prototype {_number(check.prototype.width)}, rig "
            f"{_number(check.rig.width)}, difference {check.width_difference:.3g} (allowed "
            f"{check.width_allowed:.3g}: {'agree' if check.widths_agree else 'DISAGREE'})"
        )
        lines.append(
            f"  largest difference over the slip zone: shear change "
            f"{check.shear_change_difference:.3g}, slip {check.slip_difference:.3g} (relative "
            f"to the prototype's largest, {check.compared_points} points; the edge expansions' "
            f"next terms reach {check.expansion_allowance:.3g} there)"
        )
        lines.append(
            f"  largest |q2 - q1|: prototype {_number(check.shear_change_peak.prototype)}, rig "
            f"{_number(check.shear_change_peak.rig)}; largest |slip|: prototype "
            f"{_number(check.slip_peak.prototype)}, rig {_number(check.slip_peak.rig)}"
        )
        lines.extend(_stress_lines(check.stress))
    lines.append("Warnings: " + ("none" if not result.warnings else ""))
    lines.extend(f"  - {text}" for text in result.warnings)
    return "\n".join(lines)


def _stress_lines(comparisons: tuple[StressComparison, ...]) -> list[str]:
    """The near-edge stress amplitude of both contacts, one line per source."""
    if not comparisons:
        return []
    first = comparisons[0]
    lines = [
        f"  near-edge stress amplitude (state 2 - state 1; {first.points} points within "
        f"{FARTHEST * first.unit:.3g} of each edge, {DEPTHS[0] * first.unit:.3g} deep or more; "
        "differences relative to the prototype's largest component there):"
    ]
    for item in comparisons:
        verdict = "within" if item.within_stated_accuracy else "OUTSIDE"
        text = (
            f"    {item.source:<9} largest |component|: prototype "
            f"{_number(item.largest.prototype)}, rig {_number(item.largest.rig)}; "
            f"largest difference {item.difference:.3g} ({verdict} the two "
            f"asymptotes' stated accuracy, {item.allowed:.3g})"
        )
        if item.explained is not None:
            text += (
                "; the asymptotes' difference accounts for it"
                if item.explained
                else "; NOT accounted for by the asymptotes' difference"
            )
        lines.append(text)
        if item.uniform_sxx is not None:
            lines.append(
                f"    uniform sxx of the amplitude (dsigma/2, not part of the edge match): "
                f"prototype {_number(item.uniform_sxx.prototype)}, rig "
                f"{_number(item.uniform_sxx.rig)}"
            )
        if not item.near_edge:
            lines.append("    (some points lie beyond the asymptote's near-edge range)")
    return lines


def run(args: argparse.Namespace) -> int:
    from ..solver import SolverError

    try:
        law = build_law(args)
        rig = _rig(args, law)
        result = match(law, build_cycle(args), args.mu, rig, edge=args.edge)
        if args.verify:
            from dataclasses import replace

            problem = _prototype_problem(args, law)
            result = replace(result, verification=verify(result, problem, elements=args.elements))
    except SolverError as error:  # not the input's fault: one line, and the failure status
        print(f"asymslip: error: the reference solver did not converge: {error}", file=sys.stderr)
        return 1
    except InputError as error:
        if error.parameter not in OPTIONS:
            raise
        raise InputError(OPTIONS[error.parameter], error.rule, error.value, error.where) from None
    if args.json:
        print(json.dumps(result.to_dict(), indent=2))
    else:
        print(format_answer(result))
    return 0
