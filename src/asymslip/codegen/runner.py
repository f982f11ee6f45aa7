"""Run the derivation scripts, then write, verify or freshness-check the generated package.

The scripts in ``derivations/`` are imported as one package (:mod:`asymslip.codegen.loader`),
never through ``sys.path``: a script imports its neighbours relatively
(``from ._glossary import a``; see ``derivations/README.md``).
"""

from __future__ import annotations

import difflib
import importlib
import os
import re
import subprocess
import sys
import tempfile
import time
from collections import defaultdict
from dataclasses import dataclass, field
from pathlib import Path

from .derivation import Derivation
from .emit import format_source, render_module, render_package_init
from .formula import EquationCheck, Formula
from .loader import load_derivations_package

PACKAGE = "asymslip_gen"


@dataclass
class DerivationRun:
    """Everything the derivation scripts produced, in a fixed order."""

    formulas: list[Formula] = field(default_factory=list)
    checks: list[EquationCheck] = field(default_factory=list)
    module_docs: dict[str, str] = field(default_factory=dict)
    seconds: dict[str, float] = field(default_factory=dict)
    #: The paper's printed equations (number -> LaTeX), display only: the derivations
    #: package's ``PAPER_EQUATIONS``, shown by the report where a check recorded none.
    paper_equations: dict[str, str] = field(default_factory=dict)


def derivation_scripts(directory: Path) -> list[Path]:
    """The scripts to run: every ``*.py`` not starting with ``_``, sorted by name."""
    return sorted(p for p in directory.glob("*.py") if not p.name.startswith("_"))


def run_derivations(directory: Path, *, progress: bool = True) -> DerivationRun:
    """Import each derivation script and call its ``derive()``; report progress on stderr."""
    directory = directory.resolve()
    package = load_derivations_package(directory)
    run = DerivationRun(paper_equations=dict(getattr(package, "PAPER_EQUATIONS", {})))
    scripts = derivation_scripts(directory)
    for index, script in enumerate(scripts, start=1):
        start = time.perf_counter()
        module = importlib.import_module(f"{package.__name__}.{script.stem}")
        derive = getattr(module, "derive", None)
        if derive is None:
            raise RuntimeError(f"{script} has no derive() function")
        derivation = derive()
        if not isinstance(derivation, Derivation):
            raise TypeError(f"{script}: derive() must return a Derivation")
        run.formulas.extend(derivation.formulas)
        run.checks.extend(derivation.checks)
        for module_name, doc in derivation.module_docs.items():
            if run.module_docs.get(module_name, doc) != doc:
                raise ValueError(f"module {module_name!r} described twice differently")
            run.module_docs[module_name] = doc
        run.seconds[script.name] = time.perf_counter() - start
        if progress:
            print(
                f"[{index}/{len(scripts)}] {script.name}: {len(derivation.formulas)} formulas, "
                f"{len(derivation.checks)} equations, {run.seconds[script.name]:.1f} s",
                file=sys.stderr,
                flush=True,
            )
    return run


def render_package(run: DerivationRun) -> dict[str, str]:
    """File name -> formatted source for the whole generated package."""
    modules: dict[str, list[Formula]] = defaultdict(list)
    seen: dict[str, str] = {}
    for formula in run.formulas:
        if formula.name in seen:
            raise ValueError(
                f"{formula.name} emitted twice ({seen[formula.name]}, {formula.module})"
            )
        seen[formula.name] = formula.module
        modules[formula.module].append(formula)
    files: dict[str, str] = {}
    for module, formulas in sorted(modules.items()):
        if module not in run.module_docs:
            raise ValueError(f"generated module {module!r} has no description (describe_module)")
        files[f"{module}.py"] = format_source(
            render_module(module, run.module_docs[module], formulas)
        )
    files["__init__.py"] = format_source(render_package_init(modules))
    return files


def write_package(files: dict[str, str], target: Path) -> None:
    """Write the package, removing generated modules that no derivation emits any more."""
    target.mkdir(parents=True, exist_ok=True)
    for stale in target.glob("*.py"):
        if stale.name not in files:
            stale.unlink()
    for name, text in files.items():
        path = target / name
        if not path.exists() or path.read_text() != text:
            path.write_text(text)


def write_report(text: str, path: Path) -> None:
    """Write the derivation report, leaving the file untouched when nothing changed."""
    path.parent.mkdir(parents=True, exist_ok=True)
    if not path.exists() or path.read_text() != text:
        path.write_text(text)


def _equation_key(number: str) -> tuple[int, str]:
    match = re.match(r"(\d+)", number)
    return (int(match.group(1)) if match else 10_000, number)


def print_verification(run: DerivationRun) -> None:
    """One line per paper equation: number, status, time, title."""
    for check in sorted(run.checks, key=lambda c: _equation_key(c.equation)):
        print(
            f"({check.equation:>4}) {check.status.value:<22} {check.seconds:7.2f} s  "
            f"{check.title}  [{check.source}]"
        )
        for detail in (check.how, *check.details):
            print(f"{'':7}- {detail}")
    counts: dict[str, int] = defaultdict(int)
    for check in run.checks:
        counts[check.status.value] += 1
    summary = ", ".join(f"{n} {status}" for status, n in sorted(counts.items()))
    print(f"{len(run.checks)} equations: {summary}")


def diff_trees(expected: dict[str, str], committed: Path) -> list[str]:
    """Unified diff between freshly generated files and the committed package."""
    lines: list[str] = []
    names = sorted(set(expected) | {p.name for p in committed.glob("*.py")})
    for name in names:
        path = committed / name
        old = path.read_text().splitlines(keepends=True) if path.exists() else []
        new = expected.get(name, "").splitlines(keepends=True)
        lines.extend(difflib.unified_diff(old, new, f"committed/{name}", f"regenerated/{name}"))
    return lines


def check_fresh(
    derivations: Path,
    committed: Path,
    seeds: tuple[str, ...] = ("0", "4242"),
    *,
    report: Path | None = None,
) -> int:
    """Regenerate under each PYTHONHASHSEED in parallel and diff against the committed tree.

    With ``report``, the derivation report is regenerated in the same runs and diffed too.
    """
    with tempfile.TemporaryDirectory() as scratch:
        jobs = []
        for seed in seeds:
            out = Path(scratch) / f"seed{seed}"
            env = {**os.environ, "PYTHONHASHSEED": seed}
            command = [
                sys.executable,
                "-m",
                "asymslip.codegen",
                "generate",
                "--derivations",
                str(derivations),
                "--out",
                str(out / "asymslip_gen"),
                "--quiet",
            ]
            if report is not None:
                command += ["--report", str(out / report.name)]
            jobs.append((seed, out, subprocess.Popen(command, env=env)))
        failed = False
        for seed, out, process in jobs:
            if process.wait() != 0:
                print(f"regeneration with PYTHONHASHSEED={seed} failed", file=sys.stderr)
                failed = True
                continue
            files = {p.name: p.read_text() for p in (out / "asymslip_gen").glob("*.py")}
            diff = diff_trees(files, committed)
            if report is not None:
                old = report.read_text().splitlines(keepends=True) if report.exists() else []
                new = (out / report.name).read_text().splitlines(keepends=True)
                diff += difflib.unified_diff(
                    old, new, f"committed/{report.name}", f"regenerated/{report.name}"
                )
            if diff:
                sys.stdout.writelines(diff)
                print(
                    f"\n{committed} or its report is stale (PYTHONHASHSEED={seed}): "
                    "run `make generate`",
                    file=sys.stderr,
                )
                failed = True
        if not failed:
            print(f"{committed}: fresh under PYTHONHASHSEED in {list(seeds)}")
        return 1 if failed else 0


def check_figure_data(folder: Path) -> int:
    """The committed figure data (fig5.csv) equals what `make figures` writes now.

    The PNG is not compared: its bytes depend on the matplotlib version.
    """
    from asymslip.figures import fig5_csv_text, fig5_curves

    committed = folder / "fig5.csv"
    fresh = fig5_csv_text(fig5_curves())
    old = committed.read_text().splitlines(keepends=True) if committed.exists() else []
    diff = list(
        difflib.unified_diff(
            old,
            fresh.splitlines(keepends=True),
            f"committed/{committed.name}",
            "regenerated/fig5.csv",
        )
    )
    if diff:
        sys.stdout.writelines(diff)
        print(f"\n{committed} is stale: run `make figures`", file=sys.stderr)
        return 1
    print(f"{committed}: fresh")
    return 0
