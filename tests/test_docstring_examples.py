"""Every runtime module shows its use in docstring examples that run and print what they claim.

``doctest`` alone passes a module with no examples (it attempts nothing and fails nothing), so
the test also requires at least one example that runs (a ``+SKIP``ped one does not count) in
every module, except those listed in ``EXEMPT`` with the reason they have none.
"""

from __future__ import annotations

import doctest
import importlib
import pkgutil

import pytest

import asymslip

RUNTIME_MODULES = sorted(
    info.name
    for info in pkgutil.walk_packages(asymslip.__path__, "asymslip.")
    if not info.name.startswith("asymslip.codegen") and info.name != "asymslip.__main__"
)
MODULES = ["asymslip", *RUNTIME_MODULES]

EXEMPT = {
    "asymslip.edge_flags": "the old name of asymslip.core.flags, whose examples run",
    # The command line is documented by its --help and the README, and run by the tests of
    # each command (tests/test_cli*.py); its modules are argparse wiring over the API.
    **{
        name: "command-line wiring (argparse) over the API; documented by --help"
        for name in MODULES
        if name == "asymslip.cli" or name.startswith("asymslip.cli.")
    },
    "asymslip.laws": "re-exports the law classes, whose modules carry the examples",
    "asymslip.files": "re-exports what its modules define; their docstrings carry the examples",
    "asymslip.files.arrow": "imports the optional pyarrow on demand: nothing to compute",
    "asymslip.files.progress": "draws on a terminal, with rates that depend on the clock",
    "asymslip.sweep.evaluate": "one chunk of sweep_file, whose example (asymslip.sweep) runs it",
    "asymslip.calibration": "re-exports what its modules define; their docstrings carry examples",
    **{
        f"asymslip.solver.{name}": "a numerical step inside solve(), not called by users; the "
        "package's example (asymslip.solver) runs it end to end"
        for name in ("boundaries", "grid", "normal", "qp", "tangential", "toeplitz", "steady")
    },
    "asymslip.solver.settings": "records passed from the solver's run to its results; the "
    "package's example (asymslip.solver) builds them",
}


def problem_with_examples(module, exempt: bool) -> str | None:
    """What is wrong with the module's docstring examples, or None."""
    # Only whitespace is normalised; an example that elides output says so (+ELLIPSIS).
    result = doctest.testmod(module, optionflags=doctest.NORMALIZE_WHITESPACE)
    if result.failed:
        return f"{result.failed} of {result.attempted} examples fail (printed above)"
    if exempt and result.attempted:
        return f"{module.__name__} has examples now: remove it from EXEMPT"
    if not exempt and not result.attempted:
        return (
            f"{module.__name__} has no docstring example that runs: add one, or list the "
            "module in EXEMPT with the reason it has none"
        )
    return None


@pytest.mark.parametrize("name", MODULES)
def test_docstring_examples_run(name):
    module = importlib.import_module(name)
    assert problem_with_examples(module, exempt=name in EXEMPT) is None


def test_every_exemption_names_a_runtime_module_and_a_reason():
    assert set(EXEMPT) <= set(MODULES)
    assert all(len(reason) > 20 for reason in EXEMPT.values())


def test_a_module_without_examples_that_run_fails(tmp_path, monkeypatch):
    # doctest alone passes it: no example, or only a skipped one, is nothing attempted.
    (tmp_path / "bare_module.py").write_text(
        '"""No example."""\n\n\ndef f():\n    """>>> f()  # doctest: +SKIP\n    1\n    """\n'
    )
    monkeypatch.syspath_prepend(str(tmp_path))
    module = importlib.import_module("bare_module")
    assert doctest.testmod(module).attempted == 0
    assert "has no docstring example that runs" in problem_with_examples(module, exempt=False)
