"""Solvers that misbehave on purpose, for the tests of failures in a batch (they pickle by
reference, so the workers of a cluster import them from here)."""

from __future__ import annotations

import os
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from asymslip import HertzLaw, LoadCycle
from asymslip.laws.base import LawState
from asymslip.solver import SolverResult, solve


def _is_case(loading: Any, P2: float) -> bool:
    return isinstance(loading, LoadCycle) and float(loading.P2) == P2


@dataclass(frozen=True)
class ExitOnce:
    """The solver, except that the case with this P2 ends its worker process (``os._exit``)
    the first time it is solved anywhere (a marker file remembers it): a worker that dies in
    the middle of a batch."""

    marker: str
    P2: float

    def __call__(self, law: Any, loading: Any, mu: float, **options: Any) -> SolverResult:
        if _is_case(loading, self.P2) and not os.path.exists(self.marker):
            Path(self.marker).write_text(str(os.getpid()))
            os._exit(1)
        return solve(law, loading, mu, **options)


@dataclass(frozen=True)
class RaiseAt:
    """The solver, except that the case with this P2 raises an error no case should (a bug, a
    full disk): the batch stops and must leave nothing behind."""

    P2: float

    def __call__(self, law: Any, loading: Any, mu: float, **options: Any) -> SolverResult:
        if _is_case(loading, self.P2):
            raise RuntimeError("a failure that is not the case's fault")
        return solve(law, loading, mu, **options)


@dataclass(frozen=True)
class ExitOnceHertz(HertzLaw):
    """Hertz's law, except that the chunk holding a cycle with this P1 ends its worker process
    the first time it is evaluated anywhere (a marker file remembers it)."""

    marker: str = ""
    P1: float = 0.0

    def cycle_state(self, P1: Any, dP: Any) -> LawState:
        if np.any(np.asarray(P1) == self.P1) and not os.path.exists(self.marker):
            Path(self.marker).write_text(str(os.getpid()))
            os._exit(1)
        return super().cycle_state(P1, dP)


@dataclass(frozen=True)
class ExitAlways:
    """The solver, except that the case with this P2 ends its worker process every time: a
    case that crashes the interpreter."""

    P2: float

    def __call__(self, law: Any, loading: Any, mu: float, **options: Any) -> SolverResult:
        if _is_case(loading, self.P2):
            os._exit(1)
        return solve(law, loading, mu, **options)
