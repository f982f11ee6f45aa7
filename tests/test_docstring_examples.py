"""The examples in the public docstrings run and print what they claim."""

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


@pytest.mark.parametrize("name", ["asymslip", *RUNTIME_MODULES])
def test_docstring_examples_run(name):
    module = importlib.import_module(name)
    result = doctest.testmod(module, optionflags=doctest.NORMALIZE_WHITESPACE)
    assert result.failed == 0
