"""Docstrings written as plain text, rendered as such: bars and stars are not markup.

The package's docstrings write mathematics as people type it: ``|a1 - b|`` for an absolute
value, ``(*params)`` or ``a*b`` for products.  reStructuredText would read ``|...|`` as a
substitution and a lone ``*`` as the start of emphasis, and fail (under ``-W``).  This hook
(run after numpydoc) escapes them outside inline literals, math roles and literal blocks; a
``*emphasis*`` or ``**strong**`` pair is kept.  It also joins a line whose inline literal
continues on the next one (an RST definition term cannot span lines).  No docstring is edited;
nothing else changes.
"""

from __future__ import annotations

import re
from typing import Any

from sphinx.application import Sphinx

#: Inline literals and roles (``x``, :math:`...`, :func:`...`): left as they are.
_PROTECTED = re.compile(r"``.+?``|:[\w:.-]+:`[^`]*`|`[^`]+`_?")
#: *emphasis* or **strong**: a pair that reStructuredText reads as intended.
_EMPHASIS = re.compile(r"(?<![\w*\\])(\*\*?)(?=\S)[^*]*?(?<=\S)\1(?![\w*])")


#: A star that reStructuredText could take for the start of emphasis: at the start of the text
#: or after a space or an opening character, and followed by a non-space.  (A bullet "* " and
#: a product "a*b" or "a**2" are not, and are left alone.)
_STRAY_STAR = re.compile(r"(?:(?<=^)|(?<=[\s\-:/'\"<(\[{]))\*+(?=\S)")


def _escape_stars(text: str) -> str:
    return _STRAY_STAR.sub(lambda match: "\\*" * len(match.group(0)), text)


def _escape_text(text: str) -> str:
    pieces: list[str] = []
    last = 0
    for match in _EMPHASIS.finditer(text):
        pieces.append(_escape_stars(text[last : match.start()]))
        pieces.append(match.group(0))
        last = match.end()
    pieces.append(_escape_stars(text[last:]))
    return "".join(pieces).replace("|", "\\|")


def escape_line(line: str) -> str:
    """One line of running text with its bars and stray stars escaped."""
    out: list[str] = []
    last = 0
    for match in _PROTECTED.finditer(line):
        out.append(_escape_text(line[last : match.start()]))
        out.append(match.group(0))
        last = match.end()
    out.append(_escape_text(line[last:]))
    return "".join(out)


def _indent(line: str) -> int:
    return len(line) - len(line.lstrip())


def plain_text_lines(lines: list[str]) -> list[str]:
    """The docstring's lines with running text escaped; literal blocks and doctests kept."""
    joined: list[str] = []
    for line in lines:
        if joined and joined[-1].count("``") % 2 == 1 and not joined[-1].lstrip().startswith(">>>"):
            joined[-1] = f"{joined[-1].rstrip()} {line.strip()}"
        else:
            joined.append(line)
    result: list[str] = []
    literal_from: int | None = None  # indentation of the paragraph that opened a literal block
    for index, line in enumerate(joined):
        stripped = line.strip()
        if literal_from is not None:
            if stripped and _indent(line) <= literal_from:
                literal_from = None
            else:
                result.append(line)
                continue
        if stripped.startswith((">>>", "...")) or stripped.startswith(".. "):
            result.append(line)
            continue
        if index and result and result[-1].strip().startswith(">>>") and stripped:
            result.append(line)  # doctest output
            continue
        result.append(escape_line(line))
        if stripped.endswith("::"):
            literal_from = _indent(line)
    return result


_ITEM = re.compile(r"^(\s*)(\d+|[A-Za-z]|#)[.)]\s+")


def aligned_list_items(lines: list[str]) -> list[str]:
    """Continuation lines of a numbered item aligned with the item's text.

    A generated docstring numbers its steps ``1.`` to ``29.`` and indents every continuation
    line as for a one-digit number; from ``10.`` on, reStructuredText reads that line as the end
    of the list.  A line indented more than the item's number but less than its text is moved to
    the text's column, which is what the writer meant.
    """
    result: list[str] = []
    item: tuple[int, int] | None = None  # (the number's column, the text's column)
    for line in lines:
        match = _ITEM.match(line)
        if match:
            item = (len(match.group(1)), match.end())
        elif not line.strip():
            pass
        elif item is not None and item[0] < _indent(line) < item[1]:
            line = " " * item[1] + line.lstrip()
        elif item is not None and _indent(line) <= item[0]:
            item = None
        result.append(line)
    return result


def _process(app: Sphinx, what: str, name: str, obj: Any, options: Any, lines: list[str]) -> None:
    if not name.startswith(("asymslip.", "asymslip_gen.")) and name not in {
        "asymslip",
        "asymslip_gen",
    }:
        return
    lines[:] = plain_text_lines(aligned_list_items(lines))


def setup(app: Sphinx) -> dict[str, Any]:
    app.connect("autodoc-process-docstring", _process, priority=600)
    return {"parallel_read_safe": True}
