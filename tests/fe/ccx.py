"""CalculiX (``ccx``) for the FE model's tests: skipped where it is missing, required in CI.

Like the compiled-language tests (tests/emit/toolchains.py): ``make toolchains`` (CI's
``.ci/install-toolchains``) installs Debian's ``calculix-ccx``; where
``ASYMSLIP_REQUIRE_TOOLCHAINS=1`` (CI, ``make test-languages``) a missing ccx is a failure,
elsewhere a skip that the root conftest sums up in one line.
"""

from __future__ import annotations

import os

import pytest

from asymslip.fe import find_ccx
from tests.emit.toolchains import REQUIRED

#: The start of the skip reason (one summary line for all of them).
MISSING = "CalculiX missing:"


def require_ccx() -> str:
    found = find_ccx()
    if found:
        return found
    if os.environ.get(REQUIRED) == "1":
        pytest.fail(f"ccx is not installed and {REQUIRED}=1: run `make toolchains` first")
    pytest.skip(f"{MISSING} ccx (`make toolchains` installs Debian's calculix-ccx)")
