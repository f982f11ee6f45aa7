"""What the site reads from the generated tree: the formula records and the derivation report.

``generated/asymslip_gen/formulas.json`` lists each generated function with the paper's
equations it implements and the derivation script that registered it;
``generated/report/derivation.md`` (written by ``make report`` from the same records) holds, for
each paper equation, its title, its printed LaTeX, its status and the script that covers it.
Both are regenerated and freshness-checked by ``make check-generated``, so links built from them
cannot drift from the code.  The report's layout is parsed strictly: a change of layout is an
error here, not a silently empty page.
"""

from __future__ import annotations

import functools
import json
import re
from dataclasses import dataclass
from pathlib import Path

ROOT = Path(__file__).resolve().parents[3]
FORMULAS = ROOT / "generated" / "asymslip_gen" / "formulas.json"
REPORT = ROOT / "generated" / "report" / "derivation.md"
DERIVATIONS = ROOT / "derivations"
GENERATED = ROOT / "generated"


class SourceLayoutError(RuntimeError):
    """The generated report or the records are not laid out as this reader expects."""


@dataclass(frozen=True)
class FormulaRecord:
    """One generated function, as ``formulas.json`` records it."""

    name: str
    module: str
    source: str
    equations: tuple[str, ...]
    summary: str
    args: tuple[str, ...]
    languages: tuple[str, ...]

    @property
    def python(self) -> str:
        """Dotted path of the NumPy function."""
        return f"asymslip_gen.{self.module}.{self.name}"


@dataclass(frozen=True)
class ReportEquation:
    """One numbered equation of the paper as the derivation report presents it."""

    number: str
    title: str
    status: str
    derivation: str
    printed: str | None
    derived: str | None


@functools.cache
def formula_records() -> tuple[FormulaRecord, ...]:
    """Every record of ``formulas.json``, in its order."""
    document = json.loads(FORMULAS.read_text(encoding="utf-8"))
    return tuple(
        FormulaRecord(
            name=record["name"],
            module=record["module"],
            source=record["source"],
            equations=tuple(record["equations"]),
            summary=record["summary"],
            args=tuple(arg["name"] for arg in record["args"]),
            languages=tuple(record.get("languages", ())),
        )
        for record in document["formulas"]
    )


def formulas_of(number: str) -> list[FormulaRecord]:
    """The generated functions whose records name equation ``number``."""
    return [record for record in formula_records() if number in record.equations]


_SECTION = re.compile(r'^<a id="eq-(?P<id>[^"]+)"></a>\n\n### (?P<heading>.+)$', re.M)
_STATUS = re.compile(r"^\*\*Status:\*\* (?P<status>[^·\n]+?)(?: ·|$)", re.M)
_DERIVATION = re.compile(r"\*\*Derivation:\*\* \[`(?P<path>derivations/[\w./]+\.py)`\]")
_ALSO = re.compile(r"^Also recorded: (.+)$", re.M)
_DISPLAY = re.compile(
    r"^(?P<label>As printed in the paper|As derived here):\n\n\$\$\n(?P<tex>.*?)\n\$\$", re.M | re.S
)


def _unescape(text: str) -> str:
    return (
        text.replace("\\_", "_")
        .replace("\\[", "[")
        .replace("\\]", "]")
        .replace("&lt;", "<")
        .replace("&gt;", ">")
        .replace("&amp;", "&")
    )


@functools.cache
def report_equations() -> dict[str, tuple[ReportEquation, ...]]:
    """Each of the paper's equations (1)-(51): every entry the report has for it, by number.

    The report may have several entries for one number (the printed form, an identity used on
    the way, an erratum of it); they share the printed form and differ in title and status.
    """
    text = REPORT.read_text(encoding="utf-8")
    start = text.find("\n## Equations (1)-(51)\n")
    end = text.find("\n## ", start + 1)
    if start < 0 or end < 0:
        raise SourceLayoutError(f"{REPORT}: no '## Equations (1)-(51)' section")
    body = text[start:end]
    matches = list(_SECTION.finditer(body))
    found: dict[str, list[ReportEquation]] = {}
    for index, match in enumerate(matches):
        stop = matches[index + 1].start() if index + 1 < len(matches) else None
        chunk = body[match.end() : stop]
        heading = match["heading"]
        number = match["id"]
        prefix = f"({number}) "
        if not heading.startswith(prefix):
            raise SourceLayoutError(f"{REPORT}: heading {heading!r} does not start with {prefix!r}")
        # One section per number: the first recorded entry under the heading, then each
        # further one after an "Also recorded: TITLE" line.
        parts = _ALSO.split(chunk)
        titles = [heading.removeprefix(prefix), *parts[1::2]]
        for title, part in zip(titles, parts[0::2], strict=True):
            status = _STATUS.search(part)
            derivation = _DERIVATION.search(part)
            if status is None or derivation is None:
                raise SourceLayoutError(f"{REPORT}: ({number}) has no status or derivation line")
            displays = {m["label"]: m["tex"].strip() for m in _DISPLAY.finditer(part)}
            found.setdefault(number, []).append(
                ReportEquation(
                    number=number,
                    title=_unescape(title.strip()),
                    status=status["status"].strip(),
                    derivation=derivation["path"],
                    printed=displays.get("As printed in the paper"),
                    derived=displays.get("As derived here"),
                )
            )
    missing = [str(n) for n in range(1, 52) if str(n) not in found]
    if missing:
        raise SourceLayoutError(f"{REPORT}: equations {', '.join(missing)} not found")
    return {number: tuple(entries) for number, entries in found.items()}


def printed_form(number: str) -> str:
    """The LaTeX of equation ``number`` as the paper prints it."""
    for entry in report_equations()[number]:
        if entry.printed:
            return entry.printed
    raise SourceLayoutError(f"{REPORT}: ({number}) has no printed form")


def derivation_scripts() -> list[Path]:
    """The derivation scripts (not the package's private helpers), in name order."""
    return sorted(path for path in DERIVATIONS.glob("*.py") if not path.name.startswith("__"))


def displayable(latex: str) -> str:
    """The printed LaTeX with any unbalanced ``\\right`` written as a plain delimiter.

    Printed errors are kept as printed -- (25)'s bars are unbalanced -- but MathJax refuses a
    ``\\right`` without its ``\\left``; shown as a plain bar, the formula typesets and still
    looks as the paper prints it (the errata page says what is wrong with it).
    """
    excess = latex.count("\\right") - latex.count("\\left")
    while excess > 0:
        index = latex.rindex("\\right")
        latex = latex[:index] + "\\big" + latex[index + len("\\right") :]
        excess -= 1
    return latex


_DISPLAY_MATH = re.compile(r"^\$\$\n(.*?)\n\$\$$", re.M | re.S)
_LINK = re.compile(r"\[([^\]]+)\]\((?!https?:)[^)]*\)")


def report_section(heading: str) -> str:
    """The Markdown body of the report's ``## HEADING...`` section (without its heading line),
    its links into the repository written as plain text (the site has no such pages)."""
    text = REPORT.read_text(encoding="utf-8")
    start = text.find(f"\n## {heading}")
    if start < 0:
        raise SourceLayoutError(f"{REPORT}: no section '## {heading}'")
    body_start = text.index("\n", start + 1) + 1
    end = text.find("\n## ", body_start)
    body = text[body_start : end if end >= 0 else None]
    body = _DISPLAY_MATH.sub(lambda match: f"$$\n{displayable(match.group(1))}\n$$", body)
    return _LINK.sub(lambda match: match.group(1), body).strip() + "\n"
