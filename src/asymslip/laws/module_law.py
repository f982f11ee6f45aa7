"""A contact law from a module written by ``asymslip derive`` (or by hand in the same form).

The module defines ``load(a, *params)``, ``load_slope(a, *params)``,
``normal_edge_multiplier(a, *params)`` and optionally ``normal_edge_multiplier_slope(a,
*params)`` (dL_I/dP), and describes itself in ``__asymslip_law__ = {"name": ..., "params":
[...]}``.  a(P) is found by inverting the increasing P(a) (:mod:`asymslip.laws.roots`).
"""

from __future__ import annotations

import hashlib
import importlib.util
from collections.abc import Callable, Mapping
from dataclasses import replace
from pathlib import Path
from types import ModuleType
from typing import Any

import numpy as np
from numpy.typing import ArrayLike

from ..errors import InputError
from .base import BoolArray, ContactLaw, FloatArray, LawState
from .module_check import REQUIRED_FUNCTIONS, check_law_source
from .parameters import law_parameter
from .roots import invert_increasing_where_possible


def import_law_module(path: str | Path) -> ModuleType:
    """Import a law module by file path, refusing files that are not one.

    The file is read and checked first (:func:`~asymslip.laws.module_check.check_law_source`):
    a file whose import would run code of its own, or that is no law module, is refused
    before anything of it runs.
    """
    path = Path(path)
    if path.is_dir():
        raise InputError("module", "is a folder, not a law module file (FILE.py)", str(path))
    if not path.is_file():
        raise InputError("module", "no such file", str(path))
    try:
        source = path.read_bytes()  # decoded as the importer would (a BOM, a coding line)
    except OSError as error:
        raise InputError("module", f"cannot be read ({error.strerror})", str(path)) from None
    if path.suffix != ".py":
        raise InputError("module", "is not a Python module (expected a .py file)", str(path))
    check_law_source(source, str(path))
    digest = hashlib.sha1(str(path.resolve()).encode()).hexdigest()[:12]
    spec = importlib.util.spec_from_file_location(f"asymslip_user_law_{digest}", path)
    if spec is None or spec.loader is None:
        raise InputError("module", "is not a Python module (expected a .py file)", str(path))
    module = importlib.util.module_from_spec(spec)
    try:
        spec.loader.exec_module(module)
    except Exception as error:  # any failure of the user's file is a bad --module
        raise InputError(
            "module", f"could not be imported ({type(error).__name__}: {error})", str(path)
        ) from None
    description = getattr(module, "__asymslip_law__", None)
    if not isinstance(description, Mapping) or not isinstance(description.get("params"), list):
        raise InputError(
            "module",
            "is not an asymslip law module (it has no __asymslip_law__ "
            "description; write one with `asymslip derive`)",
            str(path),
        )
    missing = [name for name in REQUIRED_FUNCTIONS if not callable(getattr(module, name, None))]
    if missing:
        raise InputError(
            "module", f"is not an asymslip law module: it lacks {', '.join(missing)}", str(path)
        )
    return module


class ModuleLaw(ContactLaw):
    """The contact law defined by a law module, with its parameters bound to values.

    Examples
    --------
    A module written by hand in the form ``asymslip derive`` writes: the cylinder of (29).

    >>> import pathlib, tempfile
    >>> source = '''
    ... import numpy
    ... __asymslip_law__ = {"name": "cylinder", "params": ["R", "E_star"]}
    ... def load(a, R, E_star):
    ...     return numpy.pi * E_star * a**2 / (4 * R)
    ... def load_slope(a, R, E_star):
    ...     return numpy.pi * E_star * a / (2 * R)
    ... def normal_edge_multiplier(a, R, E_star):
    ...     return E_star / R * numpy.sqrt(a / 2)
    ... '''
    >>> with tempfile.TemporaryDirectory() as folder:
    ...     path = pathlib.Path(folder) / "cylinder.py"
    ...     _ = path.write_text(source)
    ...     law = ModuleLaw.from_file(path, R=1.0, E_star=1.0)
    >>> round(float(law.half_width(100.0)), 12)  # sqrt(400/pi)
    11.283791670955
    """

    def __init__(self, module: ModuleType, source: str = "module", **param_values: float) -> None:
        description = module.__asymslip_law__
        self.module = module
        self.source = source
        self.name = str(description.get("name", Path(source).stem))
        self.param_names: tuple[str, ...] = tuple(description["params"])
        listed = ", ".join(self.param_names) or "none"
        missing = [name for name in self.param_names if name not in param_values]
        if missing:
            raise InputError(
                "param",
                f"{', '.join(missing)} required by the law {self.name} in "
                f"{source} (its parameters: {listed}); give NAME=VALUE",
            )
        unknown = sorted(set(param_values) - set(self.param_names))
        if unknown:
            raise InputError(
                "param",
                f"{', '.join(unknown)} is not a parameter of the law "
                f"{self.name} in {source} (its parameters: {listed})",
            )
        self.params = {name: law_parameter(name, param_values[name]) for name in self.param_names}
        if description.get("parameters_are") == "positive real numbers":
            for name, value in self.params.items():
                if not value > 0:
                    raise InputError(
                        "param",
                        f"{name} must be > 0: the law {self.name} was "
                        "derived (and its range established) for positive "
                        "parameters",
                        value,
                    )
        self._values = tuple(self.params.values())
        self.valid_half_widths, self.valid_loads = self._range()
        #: False when ``asymslip derive`` could not establish where P(a) increases (P =
        #: sin(a)); the first rising branch is then found numerically (:meth:`_first_branch`).
        self.range_established = bool(description.get("range", {}).get("established", True))
        if not self.range_established:
            self.valid_half_widths, self.valid_loads = self._first_branch()
        self.range_note = self._describe_range()

    @classmethod
    def from_file(cls, path: str | Path, **param_values: float) -> ModuleLaw:
        """Import the law module at ``path`` and bind its parameters."""
        return cls(import_law_module(path), str(path), **param_values)

    def __repr__(self) -> str:
        values = ", ".join(f"{k}={v!r}" for k, v in self.params.items())
        return f"ModuleLaw({self.name} from {self.source}: {values})"

    def _range(self) -> tuple[tuple[float, float], tuple[float, float]]:
        """The half-widths and loads where the module says the law is valid (positive and
        increasing), from its range functions; all of (0, inf) for a module without them."""
        names = ("half_width_minimum", "half_width_maximum", "load_minimum", "load_maximum")
        functions = [getattr(self.module, name, None) for name in names]
        called: list[Callable[..., Any]] = [f for f in functions if callable(f)]
        if len(called) < len(names):
            return (0.0, np.inf), (0.0, np.inf)
        with np.errstate(all="ignore"):
            a_min, a_max, P_min, P_max = (float(function(*self._values)) for function in called)
        return (a_min, a_max), (P_min, P_max)

    #: The scan of :meth:`_first_branch`: half-widths from 1e-12 to 1e12, log-spaced.
    BRANCH_SCAN = np.geomspace(1e-12, 1e12, 20_001)

    def _first_branch(self) -> tuple[tuple[float, float], tuple[float, float]]:
        """Where P(a) first rises, for a law whose range SymPy could not establish.

        A contact grows as the load rises, so its half-width is on the first branch of P(a)
        that rises: P = sin(a) at P = 0.98 has the root 7.65 as well as asin(0.98) = 1.37,
        with dP/da > 0 at both, and only 1.37 is a contact; P = a**a first falls (to 0.69 at
        a = 1/e) and rises beyond, so only loads above 0.69 have a half-width.  dP/da is
        sampled on 20001 log-spaced half-widths (ratio 1.0028) from 1e-12 to 1e12; the first
        sample where it is > 0 starts the branch and the first one after it where it is <= 0
        (NaN samples do not count) ends it, each refined by bisection, and the law carries the
        loads between P at the two ends only.  No rising sample: no load at all.  A sampling
        check: a dip (or rise) narrower than 0.28 % of a can pass it.
        """
        (a_min, a_max), (P_min, P_max) = self.valid_half_widths, self.valid_loads
        scan = self.BRANCH_SCAN
        with np.errstate(all="ignore"):
            slope = self.load_slope(scan)
        usable = scan > a_min
        rising = np.flatnonzero((slope > 0) & usable)
        if rising.size == 0:  # P(a) increases nowhere on the scan: no load has a half-width
            return (a_min, a_min), (P_min, P_min)
        first = int(rising[0])
        if first > 0 and usable[first - 1]:  # the branch starts after a fall: find where
            a_start = self._turn(float(scan[first - 1]), float(scan[first]), rises=True)
            with np.errstate(all="ignore"):
                P_start = float(self.load(a_start))
            a_min, P_min = max(a_min, a_start), max(P_min, P_start)
        falling = np.flatnonzero((slope <= 0) & usable & (np.arange(scan.size) > first))
        if falling.size == 0:
            return (a_min, a_max), (P_min, P_max)
        end = int(falling[0])
        low = self._turn(float(scan[end - 1]), float(scan[end]), rises=False)
        with np.errstate(all="ignore"):
            P_end = float(self.load(low))
        return (a_min, min(a_max, low)), (P_min, min(P_max, P_end))

    def _turn(self, low: float, high: float, *, rises: bool) -> float:
        """The half-width in [low, high] where dP/da changes sign, by bisection to the double
        next to it (60 halvings of < 0.3 %); on the rising side of the turn."""
        with np.errstate(all="ignore"):
            for _ in range(60):
                middle = 0.5 * (low + high)
                if middle in (low, high):
                    break
                if (self.load_slope(middle) > 0) == rises:
                    high = middle
                else:
                    low = middle
        return high if rises else low

    def _describe_range(self) -> str:
        """:attr:`range_note`: the loads the law carries, where that is not every load."""
        low, high = self.valid_loads
        if low <= 0 and high == np.inf:
            return ""
        if high == np.inf:  # never print inf as though it were a number
            return f"; it carries loads above {low:.6g} only"
        return f"; it carries loads from {low:.6g} to {high:.6g} only"

    def half_width_where_possible(self, P: ArrayLike) -> tuple[FloatArray, BoolArray]:
        """a(P) by inverting P(a) inside the law's valid range; loads outside it have none."""
        P = np.asarray(P, dtype=np.float64)
        (a_min, a_max), (P_min, P_max) = self.valid_half_widths, self.valid_loads
        inside = (P > P_min) & (P < P_max)
        if not (a_max > a_min and a_max > 0 and np.any(inside)):  # no load has a half-width
            return np.full(P.shape, np.nan)[()], np.zeros(P.shape, dtype=bool)[()]
        lower = np.full(P.shape, 1.0 if a_min <= 0 else a_min)
        if np.isfinite(a_max):  # a root lies inside the valid half-widths
            lower = np.where(a_min > 0, a_min, np.minimum(1.0, 0.5 * a_max))
            upper = np.full(P.shape, a_max)
        else:
            upper = np.maximum(lower, 1.0)
        a, found = invert_increasing_where_possible(
            self.load, np.where(inside, P, np.nan), self.load_slope, lower=lower, upper=upper
        )
        return a, np.asarray(found) & inside

    def cycle_state(self, P1: ArrayLike, dP: ArrayLike) -> LawState:
        """As for every law, with state 2 marked where P2 lies outside the law's valid loads.

        a2 comes from Newton's method started at a1, which does not know the range: near a
        bounded law's supremum (k tanh(a) at P = k) it settles where P(a) rounds to the bound.
        """
        state = super().cycle_state(P1, dP)
        low, high = self.valid_loads
        if low <= 0 and high == np.inf:
            return state
        inside = (state.P2 > low) & (state.P2 < high)
        if np.all(inside):
            return state
        return replace(state, found2=np.asarray(state.found2) & inside)

    def _call(self, function: Callable[..., FloatArray], a: ArrayLike) -> FloatArray:
        values: FloatArray = np.asarray(
            function(np.asarray(a, dtype=np.float64), *self._values), dtype=np.float64
        )
        return values

    def load(self, a: ArrayLike) -> FloatArray:
        return self._call(self.module.load, a)

    def load_slope(self, a: ArrayLike) -> FloatArray:
        return self._call(self.module.load_slope, a)

    def normal_multiplier_at(self, a: ArrayLike, load_slope: ArrayLike) -> FloatArray:
        """L_I of (19), from the module's derived form."""
        return self._call(self.module.normal_edge_multiplier, a)

    def normal_multiplier_slope_at(self, a: ArrayLike, load_slope: ArrayLike) -> FloatArray:
        """dL_I/dP from the module when it has it, else central differences."""
        function = getattr(self.module, "normal_edge_multiplier_slope", None)
        if function is None:
            differences: FloatArray = super().normal_multiplier_slope_at(a, load_slope)
            return differences
        return self._call(function, a)
