"""Session-wide hooks: the skipped tests summed up, one line per cause.

pytest's own ``-rs`` lists a skip once per test location, which for the compiled-language tests
(one per generated function) is four lines for one cause; ``pyproject.toml`` asks pytest for
failures and errors only (``-rfExX``) and this hook writes the skips, one line per reason.
"""

from __future__ import annotations

from collections import Counter

import pytest

from tests.emit.toolchains import MISSING


def _reason(report: pytest.TestReport) -> str:
    reason = report.longrepr[2] if isinstance(report.longrepr, tuple) else str(report.longrepr)
    return reason.removeprefix("Skipped: ")


def pytest_terminal_summary(terminalreporter: pytest.TerminalReporter) -> None:
    """One line for the tests an absent toolchain skipped, saying how to run them; one line
    per other skip reason with its count."""
    reasons = Counter(_reason(report) for report in terminalreporter.stats.get("skipped", []))
    tools = Counter()
    for reason, count in reasons.items():
        if reason.startswith(MISSING):
            tools[reason.removeprefix(MISSING).split()[0]] += count
    if tools:
        terminalreporter.write_line(
            f"SKIPPED {sum(tools.values())} compiled-language tests: {', '.join(sorted(tools))} "
            "not installed; `make test-languages` installs the toolchains (Debian, as root) "
            "and runs them",
            yellow=True,
        )
    for reason, count in sorted(reasons.items()):
        if not reason.startswith(MISSING):
            terminalreporter.write_line(f"SKIPPED {count}: {reason}", yellow=True)
