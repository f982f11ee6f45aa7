"""The command-line reference, read from the argument parser itself.

``{asymslip-command-line}`` calls :func:`asymslip.cli.build_parser` and writes one section per
command (and per sub-command, such as ``figure fig5``): its description, its usage line as
argparse prints it, and every option of every argument group with its metavar, help and
default.  Help texts are shown as written (plain text, not parsed as markup).  A new command or
option appears with no change to the docs.
"""

from __future__ import annotations

import argparse
from collections.abc import Iterator
from typing import Any

from docutils import nodes
from sphinx.application import Sphinx
from sphinx.util.docutils import SphinxDirective


def _subcommands(
    parser: argparse.ArgumentParser,
) -> Iterator[tuple[str, str, argparse.ArgumentParser]]:
    """(name, one-line help, parser) of each sub-command, in the order they were added."""
    for action in parser._actions:
        if isinstance(action, argparse._SubParsersAction):
            helps = {choice.dest: choice.help or "" for choice in action._choices_actions}
            for name, sub in action.choices.items():
                yield name, helps.get(name, ""), sub


def _paragraphs(text: str) -> list[nodes.Node]:
    return [nodes.paragraph(part, part) for part in text.split("\n\n") if part.strip()]


def _option_rows(parser: argparse.ArgumentParser) -> list[tuple[str, list[tuple[str, str]]]]:
    """Per argument group with options: (title, [(invocation, help)])."""
    formatter = parser._get_formatter()
    groups = []
    for group in parser._action_groups:
        rows = []
        for action in group._group_actions:
            if action.help == argparse.SUPPRESS or isinstance(action, argparse._SubParsersAction):
                continue
            if action.option_strings:
                if action.nargs == 0:
                    invocation = ", ".join(action.option_strings)
                else:
                    metavar = formatter._format_args(action, action.dest.upper())
                    invocation = ", ".join(
                        f"{option} {metavar}" for option in action.option_strings
                    )
            else:
                invocation = formatter._format_args(action, action.dest)
            text = formatter._expand_help(action) if action.help else ""
            default = action.default
            if (
                action.option_strings
                and action.nargs != 0
                and default not in (None, argparse.SUPPRESS)
                and "default" not in text
            ):
                text = f"{text} (default: {default})".strip()
            rows.append((invocation, text))
        if rows:
            groups.append((group.title or "arguments", rows))
    return groups


class CommandLine(SphinxDirective):
    """``asymslip-command-line``: every command of ``asymslip`` from ``build_parser()``."""

    has_content = False

    def run(self) -> list[nodes.Node]:
        from asymslip.cli import build_parser

        parser = build_parser()
        # The parser is built from code all over the package: the page is read again on every
        # build (see _always_outdated), so a new command or option is never missing.
        users = getattr(self.env, "asymslip_command_line_docs", set())
        users.add(self.env.docname)
        self.env.asymslip_command_line_docs = users  # type: ignore[attr-defined]
        result: list[nodes.Node] = _paragraphs(parser.description or "")
        result.append(nodes.literal_block(parser.format_usage(), parser.format_usage()))
        commands = nodes.bullet_list()
        for name, summary, _ in _subcommands(parser):
            item = nodes.paragraph()
            ref = nodes.reference("", "", internal=True, refid=f"cli-{name}")
            ref += nodes.literal(f"asymslip {name}", f"asymslip {name}")
            item += ref
            if summary:
                item += nodes.Text(f": {summary}")
            commands += nodes.list_item("", item)
        result.append(commands)
        for name, summary, sub in _subcommands(parser):
            result.append(self._section(f"asymslip {name}", f"cli-{name}", summary, sub))
        return result

    def _section(
        self, title: str, anchor: str, summary: str, parser: argparse.ArgumentParser
    ) -> nodes.section:
        section = nodes.section(ids=[anchor], names=[anchor])
        section += nodes.title(title, title)
        self.state.document.note_explicit_target(section)
        description = parser.description or summary
        section.extend(_paragraphs(description))
        usage = parser.format_usage().strip()
        section += nodes.literal_block(usage, usage)
        for group, rows in _option_rows(parser):
            section += nodes.rubric(group, group)
            options = nodes.definition_list(classes=["cli-options"])
            for invocation, text in rows:
                term = nodes.term()
                term += nodes.literal(invocation, invocation)
                definition = nodes.definition()
                definition += nodes.paragraph(text, text)
                options += nodes.definition_list_item("", term, definition)
            section += options
        if parser.epilog:
            section.extend(_paragraphs(parser.epilog))
        for name, sub_summary, sub in _subcommands(parser):
            section += self._section(f"{title} {name}", f"{anchor}-{name}", sub_summary, sub)
        return section


def _always_outdated(
    app: Sphinx, env: Any, added: set[str], changed: set[str], removed: set[str]
) -> list[str]:
    return sorted(getattr(env, "asymslip_command_line_docs", set()) - removed)


def setup(app: Sphinx) -> dict[str, Any]:
    app.add_directive("asymslip-command-line", CommandLine)
    app.connect("env-get-outdated", _always_outdated)
    return {"parallel_read_safe": True}
