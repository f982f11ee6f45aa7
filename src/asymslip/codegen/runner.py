"""Run the derivation scripts, then write, verify or freshness-check everything generated.

One run of the derivations feeds every output: the NumPy package (with ``formulas.json``),
the C, Fortran and MATLAB/Octave trees (:mod:`asymslip.codegen.languages`) and the derivation
report, each formula CSE'd once (:mod:`asymslip.codegen.cse`).

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
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

from asymslip.files.atomic import atomic_write

from .cse import Reduced, reduce_formula
from .derivation import Derivation
from .derivation_run import DerivationRun
from .emit import format_sources, render_module, render_package_init
from .formula import Formula
from .languages import LANGUAGES
from .loader import load_derivations_package
from .program_emit import MODULE as PROGRAMS_MODULE
from .program_emit import SCALAR_MODULE as SCALAR_PROGRAMS_MODULE
from .program_emit import render_programs_module
from .records import FILE as RECORDS_FILE
from .records import render_records
from .report import render_report
from .scalar import MODULE as SCALAR_MODULE
from .scalar import render_scalar_module

PACKAGE = "asymslip_gen"


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
        run.programs.extend(derivation.programs)
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


#: Where each part of the output goes under the generated root, and which files in that
#: folder the code generator owns (stale ones are removed; anything else is left alone).
PYTHON_FOLDER = PACKAGE
REPORT_FOLDER = "report"
REPORT_FILE = "derivation.md"
#: The committed error map (written by `make error-map`, not by the code generator), which the
#: report summarises.
ERROR_MAP_FILE = "error_map.csv"
PYTHON_LANGUAGE = "Python"


@dataclass(frozen=True)
class Tree:
    """The files of one folder under ``generated/`` and the extensions the generator owns."""

    files: dict[str, str]
    extensions: tuple[str, ...]
    #: Files the generator owns whatever their extension (the report).
    owned: tuple[str, ...] = ()

    def owns(self, name: str) -> bool:
        return name in self.owned or any(name.endswith(ext) for ext in self.extensions)


@dataclass(frozen=True)
class Generated:
    """Everything ``make generate`` writes, folder -> :class:`Tree`, from one derivation run."""

    trees: dict[str, Tree]
    #: Function name -> the languages that have it (Python always; others unless left out).
    languages: dict[str, tuple[str, ...]]


def _module_order(run: DerivationRun) -> list[Formula]:
    """The formulas grouped by module (modules by name, functions in the scripts' order)."""
    seen: dict[str, str] = {}
    for formula in run.formulas:
        if formula.name in seen:
            raise ValueError(
                f"{formula.name} emitted twice ({seen[formula.name]}, {formula.module})"
            )
        seen[formula.name] = formula.module
        if formula.module not in run.module_docs:
            raise ValueError(
                f"generated module {formula.module!r} has no description (describe_module)"
            )
    return sorted(run.formulas, key=lambda formula: formula.module)


def render_package(run: DerivationRun, reduced: Sequence[Reduced] | None = None) -> dict[str, str]:
    """File name -> formatted source of the NumPy package ``asymslip_gen``."""
    if reduced is None:
        reduced = [reduce_formula(formula) for formula in _module_order(run)]
    modules: dict[str, list[Reduced]] = defaultdict(list)
    for item in reduced:
        modules[item.formula.module].append(item)
    sources = {
        f"{module}.py": render_module(module, run.module_docs[module], items)
        for module, items in sorted(modules.items())
    }
    sources["__init__.py"] = render_package_init(
        {module: [item.formula for item in items] for module, items in modules.items()}
    )
    sources[f"{SCALAR_MODULE}.py"] = render_scalar_module(reduced, run.module_docs)
    if run.programs:
        by_name = {item.formula.name: item for item in reduced}
        for module, scalar in ((PROGRAMS_MODULE, False), (SCALAR_PROGRAMS_MODULE, True)):
            sources[f"{module}.py"] = render_programs_module(run.programs, by_name, scalar)
    return format_sources(sources)


def render_all(run: DerivationRun, error_map: str | None = None) -> Generated:
    """Every generated file, in every language, from one run's records (each CSE'd once).

    ``error_map``: the committed error map's CSV text, summarised in the report (or None).
    """
    reduced = [reduce_formula(formula) for formula in _module_order(run)]
    names = [item.formula.name for item in reduced]
    languages: dict[str, list[str]] = {name: [PYTHON_LANGUAGE] for name in names}
    trees: dict[str, Tree] = {}
    python_files = render_package(run, reduced)
    for language in LANGUAGES:
        rendered = language.render(reduced, run.module_docs)
        for name in rendered.functions:
            languages[name].append(language.name)
        trees[language.folder] = Tree(rendered.files, language.extensions)
    available = {name: tuple(found) for name, found in languages.items()}
    python_files[RECORDS_FILE] = render_records([item.formula for item in reduced], dict(available))
    trees[PYTHON_FOLDER] = Tree(python_files, (".py", ".json"))
    report = render_report(run, languages=available, error_map=error_map)
    trees[REPORT_FOLDER] = Tree({REPORT_FILE: report}, (), owned=(REPORT_FILE,))
    return Generated(dict(sorted(trees.items())), available)


def _write_if_changed(path: Path, text: str) -> None:
    if not path.exists() or path.read_text(encoding="utf-8") != text:
        with atomic_write(path, "generated", mode="w") as handle:
            handle.write(text)


def write_tree(tree: Tree, target: Path) -> None:
    """Write one folder, removing files it owns that nothing generates any more."""
    target.mkdir(parents=True, exist_ok=True)
    for stale in sorted(target.iterdir()):
        if stale.is_file() and tree.owns(stale.name) and stale.name not in tree.files:
            stale.unlink()
    for name, text in tree.files.items():
        _write_if_changed(target / name, text)


def write_generated(generated: Generated, root: Path, folders: Sequence[str] | None = None) -> int:
    """Write the trees (all, or only ``folders``) under ``root``; return the number of files."""
    count = 0
    for folder, tree in generated.trees.items():
        if folders is None or folder in folders:
            write_tree(tree, root / folder)
            count += len(tree.files)
    return count


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


def _lines(path: Path) -> list[str]:
    return path.read_text(encoding="utf-8").splitlines(True) if path.exists() else []


def diff_tree(tree: Tree, fresh: Path, committed: Path, label: str) -> list[str]:
    """Unified diff of the files ``tree`` owns, freshly generated vs committed."""

    def owned(folder: Path) -> set[str]:
        if not folder.is_dir():
            return set()
        return {p.name for p in folder.iterdir() if p.is_file() and tree.owns(p.name)}

    lines: list[str] = []
    for name in sorted(owned(fresh) | owned(committed)):
        old_path, new_path = committed / name, fresh / name
        old = _lines(old_path)
        new = _lines(new_path)
        lines.extend(
            difflib.unified_diff(
                old, new, f"committed/{label}/{name}", f"regenerated/{label}/{name}"
            )
        )
    return lines


def check_fresh(
    derivations: Path,
    root: Path,
    seeds: tuple[str, ...] = ("0", "4242"),
) -> int:
    """Regenerate every tree under each PYTHONHASHSEED (in parallel) and diff against ``root``.

    Each seed runs the derivations once, in its own process, and renders every language and
    the report from that one run.
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
                "--root",
                str(out),
                "--quiet",
                "--error-map",
                str(root / REPORT_FOLDER / ERROR_MAP_FILE),
            ]
            jobs.append((seed, out, subprocess.Popen(command, env=env)))
        failed = False
        for seed, out, process in jobs:
            if process.wait() != 0:
                print(f"regeneration with PYTHONHASHSEED={seed} failed", file=sys.stderr)
                failed = True
                continue
            diff: list[str] = []
            for folder, tree in _owned_trees().items():
                diff += diff_tree(tree, out / folder, root / folder, folder)
            if diff:
                sys.stdout.writelines(diff)
                print(
                    f"\n{root} is stale (PYTHONHASHSEED={seed}): run `make generate`",
                    file=sys.stderr,
                )
                failed = True
        if not failed:
            folders = ", ".join(f"{folder}/" for folder in _owned_trees())
            print(f"{root}/{{{folders}}}: fresh under PYTHONHASHSEED in {list(seeds)}")
        return 1 if failed else 0


def _owned_trees() -> dict[str, Tree]:
    """Which files of which folders the freshness check compares (contents not needed)."""
    trees = {language.folder: Tree({}, language.extensions) for language in LANGUAGES}
    trees[PYTHON_FOLDER] = Tree({}, (".py", ".json"))
    trees[REPORT_FOLDER] = Tree({}, (), owned=(REPORT_FILE,))
    return dict(sorted(trees.items()))
