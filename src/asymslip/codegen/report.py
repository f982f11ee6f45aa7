"""Render the derivation report, ``generated/report/derivation.md``, from the derivation records.

The report is built from the same :class:`EquationCheck` and :class:`Formula` records that the
code generator turns into ``asymslip_gen``, so it cannot drift from the code: every numbered
equation of the paper, in order, as printed and as derived, how it was obtained or verified and
its status; equations no derivation covers are listed as missing.  Then the errata (status
ERRATUM, any label) and the results beyond the paper (status BEYOND, any label), and, when the
committed error map (``generated/report/error_map.csv``, written by ``make error-map``) is
given, its summary: the code generator does not import the API that computes the map, so it
reads the committed data, whose columns are those of ``asymslip.solver.error_map.COLUMNS``.

Nothing here needs registering when a derivation adds an equation or a result: the report
picks up every record.  The only tables in this module are cosmetic (LaTeX names of symbols).

The file is committed and freshness-checked, so it holds no timestamps, timings or tool versions,
and its bytes must not depend on ``PYTHONHASHSEED`` (records keep the scripts' fixed order).
"""

from __future__ import annotations

import csv
import io
import re
from collections import defaultdict
from collections.abc import Iterable, Mapping, Sequence

import sympy

from .derivation_run import DerivationRun
from .formula import EquationCheck, Formula, Status

PAPER = "Moore, Hills et al., Theoretical and Applied Fracture Mechanics 2022, 103457"
NUMBERED_EQUATIONS = tuple(str(number) for number in range(1, 52))

# How symbol names print in LaTeX.  Cosmetic only; unknown names keep SymPy's own rendering.
SYMBOL_LATEX: dict[str, str] = {
    "lam": r"\lambda",
    "E_star": r"E^{*}",
    "L_I": r"L_{I}",
    "L_I1": r"L_{I,1}",
    "L_I2": r"L_{I,2}",
    "L_II": r"L_{II}",
    "L_II1": r"L_{II,1}",
    "L_II2": r"L_{II,2}",
    "da": r"\Delta a",
    "dP": r"\Delta P",
    "dQ": r"\Delta Q",
    "dsigma": r"\Delta \sigma",
    "da_dP": r"a'(P)",
    "dL_I_dP": r"L_{I}'(P)",
    "dP_da": r"\frac{dP}{da}",
    "dQ_da": r"\frac{dQ}{da}",
    "dsigma_da": r"\frac{d\sigma}{da}",
    "P_K": r"P_{K}",
    "K_II": r"K_{II}",
    "q_diff": r"q_{\mathrm{diff}}",
}

_STATUS_ORDER = (Status.GIVEN, Status.DERIVED, Status.NUMERIC, Status.ERRATUM, Status.BEYOND)


def equation_key(label: str) -> tuple[int, str]:
    """Sort key: paper numbers numerically, other labels ("conclusion", "B1") after them."""
    match = re.match(r"(\d+)", label)
    return (int(match.group(1)) if match else 10_000, label)


def latex(expr: sympy.Basic) -> str:
    """SymPy's LaTeX with the project's symbol names (lam -> lambda, L_I1 -> L_{I,1}, ...)."""
    names = {
        symbol: SYMBOL_LATEX[symbol.name]
        for symbol in expr.free_symbols
        if isinstance(symbol, sympy.Symbol) and symbol.name in SYMBOL_LATEX
    }
    return str(sympy.latex(expr, symbol_names=names))


def markdown_text(text: str) -> str:
    """Plain prose safe in Markdown: ``*``, ``_`` and friends are shown, not interpreted."""
    text = text.replace("\\", "\\\\")
    for character in "*_`[]|#":
        text = text.replace(character, "\\" + character)
    return text.replace("<", "&lt;").replace(">", "&gt;")


def display_math(tex: str) -> list[str]:
    """A ``$$ ... $$`` block that GitHub and common Markdown viewers render."""
    # Blank lines inside a display block end it on GitHub; collapse all whitespace runs.
    return ["", "$$", re.sub(r"\s+", " ", tex).strip(), "$$", ""]


def anchor(label: str) -> str:
    return "eq-" + re.sub(r"[^a-z0-9]+", "-", label.lower()).strip("-")


def _source_link(source: str) -> str:
    # The report sits in generated/report/, two levels below the repository root.
    return f"[`{source}`](../../{source})"


def _implementing(formulas: Sequence[Formula], label: str) -> list[str]:
    return [
        f"`asymslip_gen.{formula.module}.{formula.name}`"
        for formula in formulas
        if label in formula.equations
    ]


def _check_block(check: EquationCheck, printed: str | None, code: list[str]) -> list[str]:
    lines = [
        f"**Status:** {check.status.value} · **Derivation:** {_source_link(check.source)}"
        + (f" · **Code:** {', '.join(code)}" if code else ""),
        "",
    ]
    if printed is not None:
        lines += ["As printed in the paper:", *display_math(printed)]
    if check.derived is not None:
        lines += ["As derived here:", *display_math(latex(check.derived))]
    elif check.status is Status.GIVEN:
        lines += ["", "As derived here: nothing to derive (taken as given).", ""]
    else:
        lines += ["", "As derived here: no expression recorded; see how it was verified.", ""]
    lines.append("How it was obtained or verified:")
    lines.append("")
    lines += [f"- {markdown_text(item)}" for item in (check.how, *check.details) if item]
    lines.append("")
    return lines


def _summary(by_label: Mapping[str, list[EquationCheck]], missing: list[str]) -> list[str]:
    per_status: dict[Status, list[str]] = defaultdict(list)
    for label in sorted(by_label, key=equation_key):
        for status in dict.fromkeys(check.status for check in by_label[label]):
            per_status[status].append(label)
    lines = ["| Status | Count | Equations |", "| --- | ---: | --- |"]
    for status in _STATUS_ORDER:
        labels = per_status.get(status, [])
        if labels:
            links = ", ".join(f"[({label})](#{anchor(label)})" for label in labels)
            lines.append(f"| {status.value} | {len(labels)} | {links} |")
    links = ", ".join(f"[({label})](#{anchor(label)})" for label in missing) or "none"
    lines.append(f"| **missing** (no derivation yet) | {len(missing)} | {links} |")
    return lines


def _labelled_section(
    title: str,
    checks: Iterable[EquationCheck],
    printed: Mapping[str, str] | None,
    formulas: Sequence[Formula],
    empty: str,
    anchored: set[str],
) -> list[str]:
    """Errata or beyond-the-paper results; ``printed`` None shows only a check's own form."""
    lines = [f"## {title}", ""]
    found = False
    for check in sorted(checks, key=lambda c: equation_key(c.equation)):
        found = True
        label = check.equation
        if label not in anchored:
            anchored.add(label)
            lines += [f'<a id="{anchor(label)}"></a>', ""]
        number = f"({label})" if label in NUMBERED_EQUATIONS else label
        lines += [f"### {number} {markdown_text(check.title)}", ""]
        shown = check.printed or (printed.get(label) if printed is not None else None)
        lines += _check_block(check, shown, _implementing(formulas, label))
    if not found:
        lines += [empty, ""]
    return lines


# --- the error map ------------------------------------------------------------------------------
#: The estimates of the error map (columns ``<name>_elements``, ``<name>_fraction``), as shown.
ERROR_MAP_ESTIMATES = {
    "b": "`b` (b2)",
    "b_paper": "(22) `b_paper`",
    "b_first_order": "(28) `b_first_order`",
    "b_corrective_stick": "(40) `b_corrective_stick`",
    "b_exact": "a(P\\_K) `b_exact`",
}
#: How the map's law names print (cosmetic; an unknown name prints as it is).
ERROR_MAP_LAWS = {
    "hertz": "Hertz",
    "flat-rounded": "rounded flat",
    "power-1.5": "power n = 1.5",
    "power-3": "power n = 3",
}


def _rows(text: str) -> list[dict[str, str]]:
    body = "\n".join(line for line in text.splitlines() if line and not line.startswith("#"))
    return list(csv.DictReader(io.StringIO(body)))


def _largest(rows: Sequence[Mapping[str, str]], column: str, scale: str | None = None) -> float:
    """max |row[column]| (over the rows that have it), divided by row[scale] if given."""
    values = [
        abs(float(row[column])) / (float(row[scale]) if scale else 1.0)
        for row in rows
        if row.get(column)
    ]
    return max(values) if values else float("nan")


def _cell(rows: Sequence[Mapping[str, str]], name: str) -> str:
    elements = _largest(rows, f"{name}_elements")
    if elements != elements:  # NaN: the estimate does not exist for these rows
        return "-"
    fraction = _largest(rows, f"{name}_fraction")
    return f"{elements:.2f} ({100 * fraction:.1f} %)"


def _bounds(value: float) -> str:
    """A number of solver bounds in words."""
    return f"within {value:.2f} bounds" if value <= 1 else f"up to {value:.1f} bounds"


def _covered(row: Mapping[str, str]) -> bool:
    """b's error within its stated accuracy plus the solver's bound."""
    return abs(float(row["b_elements"])) <= float(row["b_accuracy_elements"]) + float(
        row["b_error_elements"]
    )


def error_map_section(text: str) -> list[str]:
    """The report's summary of the committed error map (its CSV text)."""
    rows = _rows(text)
    if not rows:
        return [
            "## The error map: every estimate against the reference solver",
            "",
            "The committed error map is empty: run `make error-map`.",
            "",
        ]
    slipping = [row for row in rows if row["slip_direction"] != "0"]
    sticking = [row for row in rows if row["slip_direction"] == "0"]
    laws = list(dict.fromkeys(row["law"] for row in rows))
    ratios = ", ".join(dict.fromkeys(row["a2_a1"] for row in rows))
    cycles = len({(row["law"], row["a2_a1"], row["lam_mu"], row["tau"]) for row in rows})
    pairs = len({(row["lam_mu"], row["tau"]) for row in rows})
    elements = ", ".join(sorted({row["elements"] for row in rows}))
    agree = sum(row["slip_direction"] == row["solver_slip_direction"] for row in rows)
    lines = [
        "## The error map: every estimate against the reference solver",
        "",
        "From [`error_map.csv`](error_map.csv), written by `make error-map` "
        "(`asymslip.solver.error_map`) and checked by `asymslip figure error-map --check "
        "generated/report`; drawn in [`error_map.png`](../figures/error_map.png).  The "
        f"reference solver (N = {elements} elements) on {cycles} cycles -- "
        f"{len(laws)} laws ({', '.join(ERROR_MAP_LAWS.get(law, law) for law in laws)}), "
        f"a2/a1 = {ratios}, {pairs} pairs of lambda/mu and pi eta a1/(4 mu) in which the other "
        "edge slips the same way, the opposite way or not at all -- and at each of the "
        f"{len(slipping)} slipping edges the error (estimate - solver) of every estimate of "
        "`slip_zone`.  The solver's bound is at most "
        f"{_largest(rows, 'b_error_elements'):.2f} elements (one element, plus the load-step "
        "extrapolation where an edge does not slip).  `slip_zone` and the solver agree on the "
        f"slip direction at {agree} of the {len(rows)} edges; at the {len(sticking)} edges that "
        f"do not slip the solver's boundary is a1 within {_largest(sticking, 'b_elements'):.2f} "
        "elements.",
        "",
        "Largest \\|error\\| in solver elements over the slipping edges (in brackets: the "
        "largest as a fraction of the slip-zone width a1 - b, not necessarily at the same "
        "edge):",
        "",
        "| law | bulk tension | slipping edges | "
        + " | ".join(ERROR_MAP_ESTIMATES.values())
        + " |",
        "| --- | --- | ---: | " + " | ".join("---:" for _ in ERROR_MAP_ESTIMATES) + " |",
    ]
    for law in laws:
        for tension in (False, True):
            chosen = [
                row for row in slipping if row["law"] == law and (float(row["tau"]) != 0) == tension
            ]
            cells = " | ".join(_cell(chosen, name) for name in ERROR_MAP_ESTIMATES)
            lines.append(
                f"| {ERROR_MAP_LAWS.get(law, law)} | {'yes' if tension else 'no'} | "
                f"{len(chosen)} | {cells} |"
            )
    quiet = [row for row in slipping if row["validity_warning"] == "0"]
    warned = [row for row in slipping if row["validity_warning"] != "0"]
    groups = {
        "no tension, no validity warning": [r for r in quiet if float(r["tau"]) == 0],
        "tension, no validity warning": [r for r in quiet if float(r["tau"]) != 0],
        "a validity warning": warned,
    }
    lines += [
        "",
        "Largest \\|error\\| in units of the solver's bound, over the slipping edges where "
        "`slip_zone` gives no validity warning (eq24-eq27 all at most 0.1) and where it does:",
        "",
        "| estimate | "
        + " | ".join(f"{name} ({len(group)} edges)" for name, group in groups.items())
        + " |",
        "| --- | " + " | ".join("---:" for _ in groups) + " |",
    ]
    for name, label in ERROR_MAP_ESTIMATES.items():
        largest: list[str] = []
        for group in groups.values():
            value = _largest(group, f"{name}_elements", "b_error_elements")
            largest.append("-" if value != value else f"{value:.2f}")
        lines.append(f"| {label} | " + " | ".join(largest) + " |")
    no_tension, with_tension = (
        groups["no tension, no validity warning"],
        groups["tension, no validity warning"],
    )
    exact = _largest(
        [r for r in slipping if float(r["tau"]) == 0], "b_exact_elements", "b_error_elements"
    )
    paper = max(with_tension, key=lambda r: abs(float(r["b_paper_elements"])), default=None)
    uncovered = [row for row in slipping if not _covered(row)]
    uncovered_warned = sum(row["validity_warning"] != "0" for row in uncovered)
    sentence = (
        f"What it shows: without tension a(P\\_K) lies {_bounds(exact)} of the solver at every "
        "slipping edge, which confirms the solver, and the headline b lies "
        f"{_bounds(_largest(no_tension, 'b_elements', 'b_error_elements'))} wherever "
        "`slip_zone` gives no validity warning; with tension, where no warning is given, b "
        f"stays {_bounds(_largest(with_tension, 'b_elements', 'b_error_elements'))} while the "
        "paper's (22) misses by "
    )
    if paper is not None:
        sentence += (
            f"{_bounds(abs(float(paper['b_paper_elements'])) / float(paper['b_error_elements']))}"
            f" (up to {100 * _largest(with_tension, 'b_paper_fraction'):.0f} % of the slip-zone "
            "width); "
        )
    which = "all" if uncovered_warned == len(uncovered) else str(uncovered_warned)
    sentence += (
        f"b's error exceeds its stated accuracy plus the solver's bound at {len(uncovered)} of "
        f"the {len(slipping)} slipping edges, {which} of them with a validity warning (there b "
        f"errs by up to {_largest(warned, 'b_elements'):.1f} elements)."
    )
    alone = [row for row in slipping if row["other_edge"] == "none"]
    lines += ["", sentence, ""]
    if alone:
        alone_quiet = [row for row in alone if row["validity_warning"] == "0"]
        lines += [
            f"Where the other edge does not slip ({len(alone)} edges), b uses a branch that is "
            "not derived; its largest error is "
            f"{_bounds(_largest(alone_quiet, 'b_elements', 'b_error_elements'))} without a "
            f"validity warning and {_largest(alone, 'b_elements'):.1f} elements with one.",
            "",
        ]
    return lines


def render_report(
    run: DerivationRun,
    paper_equations: Mapping[str, str] | None = None,
    *,
    languages: Mapping[str, Sequence[str]] | None = None,
    error_map: str | None = None,
) -> str:
    """Markdown text of ``generated/report/derivation.md`` for a :class:`DerivationRun`.

    Reads ``run.checks`` (EquationCheck records) and ``run.formulas`` (Formula records);
    ``paper_equations`` maps equation numbers to the paper's printed LaTeX (default: the run's
    own ``paper_equations`` record), used where a check recorded no ``printed`` form;
    ``languages`` maps each function to the languages it is emitted in (a column of the table
    of generated functions); ``error_map`` is the text of the committed error map's CSV (its
    summary follows the results beyond the paper; left out when None).
    """
    checks: list[EquationCheck] = list(run.checks)
    formulas: list[Formula] = list(run.formulas)
    printed = dict(paper_equations if paper_equations is not None else run.paper_equations)

    by_label: dict[str, list[EquationCheck]] = defaultdict(list)
    for check in checks:
        by_label[check.equation].append(check)
    missing = [number for number in NUMBERED_EQUATIONS if number not in by_label]
    others = sorted(
        (label for label in by_label if label not in NUMBERED_EQUATIONS), key=equation_key
    )

    lines = [
        "<!-- Generated by `make report` from the records of derivations/*.py. Do not edit: "
        "change a derivation and run `make report`. -->",
        "",
        "# asymslip derivation report",
        "",
        f"The paper: {PAPER}.",
        "",
        "For every numbered equation of the paper, in order: the equation as the paper prints "
        "it, as the derivations here produce it (SymPy's LaTeX printer), how it was obtained or "
        "verified, and its status. Equations that no derivation covers yet are listed as "
        "**missing**. Then the errata of the paper, with the evidence, and the results that go "
        "beyond the paper. The report is written from the same records as the generated code "
        "in `generated/asymslip_gen/` (the functions named under **Code**), never by hand.",
        "",
        "Statuses: *starting point* (a model statement the derivations start from), *derived "
        "and verified* (derived by SymPy and proved equal to the printed form), *verified "
        "numerically* (checked at 30+ digits where SymPy cannot decide), *erratum found* (the "
        "printed form is wrong; the derived one is right), *beyond the paper*.",
        "",
        "## Summary",
        "",
        *_summary(by_label, missing),
        "",
        f"## Equations (1)-({NUMBERED_EQUATIONS[-1]})",
        "",
    ]
    for number in NUMBERED_EQUATIONS:
        lines.append(f'<a id="{anchor(number)}"></a>')
        lines.append("")
        records = by_label.get(number, [])
        code = _implementing(formulas, number)
        if not records:
            lines += [
                f"### ({number}) missing",
                "",
                "**Status:** missing: no derivation covers "
                "this equation yet" + (f" · **Code:** {', '.join(code)}" if code else ""),
            ]
            if number in printed:
                lines += ["", "As printed in the paper:", *display_math(printed[number])]
            else:
                lines.append("")
            continue
        lines += [f"### ({number}) {markdown_text(records[0].title)}", ""]
        for index, check in enumerate(records):
            if index:
                lines += [f"Also recorded: {markdown_text(check.title)}", ""]
            # The paper's form is shown once per equation; a check may override it.
            shown = check.printed or (printed.get(number) if index == 0 else None)
            lines += _check_block(check, shown, code if index == 0 else [])

    # Unnumbered statements appear once: errata and results beyond the paper in their own
    # sections, anything else here.
    anchored = set(NUMBERED_EQUATIONS)
    plain = [
        label
        for label in others
        if any(check.status not in (Status.ERRATUM, Status.BEYOND) for check in by_label[label])
    ]
    if plain:
        lines += ["## Other statements of the paper", ""]
        for label in plain:
            anchored.add(label)
            lines += [f'<a id="{anchor(label)}"></a>', ""]
            lines += [f"### {markdown_text(label)}: {markdown_text(by_label[label][0].title)}", ""]
            for check in by_label[label]:
                if check.status not in (Status.ERRATUM, Status.BEYOND):
                    lines += _check_block(check, check.printed, _implementing(formulas, label))

    lines += _labelled_section(
        "Errata of the paper",
        (check for check in checks if check.status is Status.ERRATUM),
        printed,
        formulas,
        "No erratum recorded by the derivations yet.",
        anchored,
    )
    lines += _labelled_section(
        "Results beyond the paper",
        (check for check in checks if check.status is Status.BEYOND),
        None,
        formulas,
        "No result beyond the paper recorded by the derivations yet.",
        anchored,
    )

    if error_map is not None:
        lines += error_map_section(error_map)

    lines += ["## Generated functions", ""]
    if languages is not None:
        lines += [
            "Every function is emitted as NumPy (`generated/asymslip_gen/`) and, unless the "
            "language lacks a function it needs, as C (`generated/c/`), Fortran "
            "(`generated/fortran/`) and MATLAB/Octave (`generated/matlab/`), from the same "
            "records.",
            "",
        ]
    header = "| Function | Module | Equations | Derivation |"
    rule = "| --- | --- | --- | --- |"
    if languages is not None:
        header, rule = header + " Languages |", rule + " --- |"
    lines += [header, rule]
    for formula in sorted(formulas, key=lambda f: (f.module, f.name)):
        equations = ", ".join(f"({label})" for label in formula.equations)
        row = (
            f"| `{formula.name}` | `asymslip_gen.{formula.module}` | {equations} | "
            f"{_source_link(formula.source)} |"
        )
        if languages is not None:
            row += f" {', '.join(languages.get(formula.name, ()))} |"
        lines.append(row)
    lines.append("")
    text = "\n".join(lines)
    # One blank line between blocks, a single trailing newline: stable bytes for the diff.
    return re.sub(r"\n{3,}", "\n\n", text).rstrip("\n") + "\n"
