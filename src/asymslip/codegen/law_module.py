"""``asymslip derive``: a contact law P(a) typed as a formula, derived into a law module.

The user gives P(a) as text, e.g. ``"pi*E_star*a**2/(4*R)"``, with the names of its
parameters.  The formula is read by the safe parser (:mod:`asymslip.expressions`: a whitelist,
never ``eval``), differentiated, passed through the paper's calibration (19) -- the formula
record ``normal_edge_multiplier`` that ``make generate`` shipped in
``asymslip_gen/formulas.json``, derived in ``derivations/section2_calibrations.py`` from
Mossakovskii's superposition -- and written through the same emitter as the generated package
(banner, NumPy docstrings, CSE, ruff format).  The module needs NumPy only;
:class:`asymslip.laws.module_law.ModuleLaw` wraps it as a contact law.

Before anything is written, what SymPy can establish about the law is established
(:mod:`asymslip.codegen.law_range`): a law that provably decreases, or is nowhere positive
where it increases, is refused with the reason; otherwise the half-widths and loads where it
is a valid incomplete-contact law are recorded in the module (``half_width_minimum`` ...
``load_maximum`` and ``__asymslip_law__["range"]``) so that the law can refuse loads outside.

SymPy is imported only when a law is derived (the ``derive`` extra), never at import time, and
its absence is one line naming the extra.
"""

from __future__ import annotations

import functools
import importlib.machinery
import keyword
import math
import pprint
import sys
import textwrap
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from ..errors import InputError
from ..expressions import IDENTIFIER, check_params, parse_formula, sympy_module
from ..files.atomic import atomic_write

#: The half-width symbol of every law.
HALF_WIDTH = "a"
#: The functions every law module defines, in this order, each taking (a, *params).
LAW_FUNCTIONS = ("load", "load_slope", "normal_edge_multiplier", "normal_edge_multiplier_slope")
#: The functions giving the range where the law is valid, each taking (*params).
RANGE_FUNCTIONS = ("half_width_minimum", "half_width_maximum", "load_minimum", "load_maximum")
#: Version of the ``__asymslip_law__`` description written into law modules (2: adds the range).
LAW_FORMAT = 2
#: The formula record of the calibration (19), and the names of its arguments.
CALIBRATION = "normal_edge_multiplier"
#: What the parameters are taken to be (stated in ``asymslip derive --help``).
PARAMETER_RULE = "positive real numbers"


@functools.cache
def calibration() -> tuple[Any, Any, Any]:
    """(19) from the packaged formula records: (L_I in terms of a and dP/da, a, dP/da)."""
    sympy_module()
    from .records import RecordError, packaged_formulas

    try:
        record = packaged_formulas()[CALIBRATION]
    except (OSError, KeyError, RecordError) as error:
        raise InputError(
            "derive",
            "cannot read the calibration (19) from asymslip_gen's "
            f"formulas.json ({error}): reinstall asymslip",
        ) from None
    symbols = {arg.name: arg.symbol for arg in record.args}
    return record.expr, symbols[HALF_WIDTH], symbols["dP_da"]


def parse_law(text: str, params: Sequence[str]) -> tuple[Any, Any, list[Any]]:
    """(P(a), the symbol a, the parameter symbols) from screened text.

    ``a`` is the positive half-width symbol (19) is written in; every parameter is taken to be
    positive (:data:`PARAMETER_RULE`).
    """
    sympy = sympy_module()
    _, a, _ = calibration()
    expr, symbols = parse_formula(text, a, params, option="P_of_a")
    positive = [sympy.Symbol(symbol.name, positive=True) for symbol in symbols]
    return expr.xreplace(dict(zip(symbols, positive, strict=True))), a, positive


def derive_law(text: str, params: Sequence[str]) -> dict[str, Any]:
    """Derive P, dP/da, L_I from (19) and dL_I/dP for the law ``P(a) = text``.

    Returns the SymPy expressions keyed by :data:`LAW_FUNCTIONS`, plus ``"a"`` and
    ``"params"`` (the symbols).
    """
    load, a, symbols = parse_law(text, params)
    sympy = sympy_module()
    multiplier_of_slope, _, dP_da = calibration()
    slope = sympy.diff(load, a)
    if sympy.simplify(slope) == 0:
        raise InputError(
            "P_of_a",
            "does not depend on a (dP/da is identically zero); a "
            "contact law P(a) must increase with the half-width a",
            text,
        )
    multiplier = multiplier_of_slope.subs(dP_da, slope)
    # d/da of |x| is sign(x), whose derivative is a Dirac delta: zero wherever it is defined.
    multiplier_slope = (sympy.diff(multiplier, a) / slope).replace(sympy.DiracDelta, lambda *_: 0)
    return {
        "load": load,
        "load_slope": slope,
        "normal_edge_multiplier": multiplier,
        "normal_edge_multiplier_slope": multiplier_slope,
        "a": a,
        "params": symbols,
    }


def _check_values(
    names: Sequence[str], values: Mapping[str, float], half_widths: Sequence[float]
) -> None:
    """The values of --check and --check-a, refused before anything is derived."""
    missing = [name for name in names if name not in values]
    if missing:
        raise InputError(
            "check",
            f"needs a value for every parameter to check dP/da > 0; missing {', '.join(missing)}",
        )
    unknown = sorted(set(values) - set(names))
    if unknown:
        raise InputError("check", f"{', '.join(unknown)} is not a parameter of the law")
    # Non-finite values first, and without showing them: SymPy would turn them into oo or nan
    # and the message would blame the law.
    for name, value in values.items():
        if not math.isfinite(value):
            raise InputError("check", f"{name} must be finite (not inf or nan)")
        if not value > 0:
            raise InputError(
                "check", f"{name} must be > 0 (parameters are {PARAMETER_RULE})", value
            )
    for half_width in half_widths:
        if not math.isfinite(half_width):
            raise InputError("check_a", "half-widths must be finite (not inf or nan)")
        if not half_width > 0:
            raise InputError("check_a", "half-widths must be > 0", half_width)


def _check_increasing(
    derived: Mapping[str, Any], values: Mapping[str, float], half_widths: Sequence[float], text: str
) -> None:
    sympy = sympy_module()
    substitution = {symbol: sympy.Float(values[symbol.name], 30) for symbol in derived["params"]}
    for half_width in half_widths:
        at = {**substitution, derived["a"]: sympy.Float(half_width, 30)}
        slope = sympy.N(derived["load_slope"].subs(at), 20)
        if not (slope.is_real and slope.is_finite and slope > 0):
            shown = f"{float(slope):.6g}" if slope.is_real and slope.is_finite else str(slope)
            raise InputError(
                "P_of_a",
                f"dP/da = {shown} is not > 0 at a = {half_width:g} with "
                + ", ".join(f"{k} = {v:g}" for k, v in values.items())
                + ": the law must increase with a",
                text,
            )


_SPECS = {
    "load": (
        "Normal load P(a) of the contact of half-width a.",
        (),
        "The user's contact law P(a) = {shown}, as given.",
        "P [force/length].",
    ),
    "load_slope": (
        "Slope dP/da of the contact law.",
        ("19",),
        "Derivative of P(a); must be > 0 for an incomplete contact.",
        "dP/da [force/length^2].",
    ),
    "normal_edge_multiplier": (
        "Normal edge multiplier L_I of the contact pressure p = L_I sqrt(a - x).",
        ("19",),
        "The calibration (19), L_I = (1/pi) sqrt(2/a) dP/da, derived from Mossakovskii's "
        "superposition in derivations/section2_calibrations.py (read from asymslip_gen's "
        "formula records), applied to this law.",
        "L_I [force/length^(5/2)].",
    ),
    "normal_edge_multiplier_slope": (
        "Slope dL_I/dP of the normal edge multiplier with load.",
        ("19", "26"),
        "(dL_I/da)/(dP/da); enters the validity measure (26).",
        "dL_I/dP.",
    ),
    "half_width_minimum": (
        "Smallest half-width of the range where the law is a valid incomplete-contact law.",
        (),
        "{range}",
        "Half-width [length] (0 when the law holds from a = 0).",
    ),
    "half_width_maximum": (
        "Largest half-width of the range where the law is a valid incomplete-contact law.",
        (),
        "{range}",
        "Half-width [length] (inf when unbounded).",
    ),
    "load_minimum": (
        "Smallest load the law reaches on its valid range.",
        (),
        "{range}",
        "P [force/length]; loads below it have no half-width.",
    ),
    "load_maximum": (
        "Supremum of the loads the law reaches on its valid range.",
        (),
        "{range}",
        "P [force/length] (inf when unbounded); loads at or above it have no half-width.",
    ),
}


def render_law_module(
    text: str, params: Sequence[str], name: str, derived: Mapping[str, Any], law_range: Any
) -> str:
    """The formatted source of the law module for ``P(a) = text``."""
    sympy = sympy_module()
    from .emit import banner, format_source, render_module
    from .formula import Argument, Formula

    shown = sympy.sstr(derived["load"])
    parameters = [
        Argument(symbol, f"Parameter {symbol.name} > 0 of the law P(a) = {shown}.")
        for symbol in derived["params"]
    ]
    law_args = (Argument(derived["a"], "Contact half-width a > 0 [length]."), *parameters)
    source = f"asymslip derive --name {name}"
    expressions = {**derived, **law_range.expressions()}
    formulas = []
    for function in (*LAW_FUNCTIONS, *RANGE_FUNCTIONS):
        summary, equations, doc, returns = _SPECS[function]
        try:
            formulas.append(
                Formula(
                    name=function,
                    args=law_args if function in LAW_FUNCTIONS else tuple(parameters),
                    expr=expressions[function],
                    equations=equations,
                    summary=summary,
                    doc=doc.format(shown=shown, range=law_range.describe()),
                    module=name,
                    source=source,
                    returns=returns,
                )
            )
        except ValueError as error:
            raise InputError("P_of_a", f"cannot be emitted as NumPy code: {error}", text) from None
    doc = f"Contact law {name}: P(a) = {shown}, parameters {', '.join(params) or '(none)'}.\n\n"
    doc += textwrap.fill(
        f"Written by `asymslip derive`; each law function takes the half-width a, then the "
        f"parameters in that order ({PARAMETER_RULE}); the range functions take the "
        "parameters only.  " + law_range.describe() + "  Use it with ``ModuleLaw.from_file`` "
        "or ``asymslip ... --law module --module FILE --param NAME=VALUE``.",
        width=92,
    )
    described = {
        "format": LAW_FORMAT,
        "name": name,
        "P_of_a": shown,
        "params": list(params),
        "parameters_are": PARAMETER_RULE,
        "functions": list(LAW_FUNCTIONS),
        "range_functions": list(RANGE_FUNCTIONS),
        "range": law_range.record(),
    }
    # pprint splits long strings into adjacent literals: the module stays within 100 columns.
    description = f"__asymslip_law__ = {pprint.pformat(described, width=80, sort_dicts=False)}\n"
    header = banner(
        [f"P(a) = {shown} (parameters: {' '.join(params) or 'none'})"],
        "asymslip derive",
        edit="the formula",
    )
    try:
        body = render_module(name, doc, formulas, header=header, preamble=description)
    except Exception as error:  # the NumPy printer refuses functions it cannot print
        raise InputError("P_of_a", f"cannot be emitted as NumPy code: {error}", text) from None
    return format_source(body)


#: asymslip's own top-level packages (an editable install finds them by its own finder).
OWN_PACKAGES = ("asymslip", "asymslip_gen")


def _same_folder(first: str | Path, second: Path) -> bool:
    try:
        return Path(first).resolve() == second.resolve()
    except OSError:
        return False


def _in_folder(origin: str | None, folder: Path) -> bool:
    """Whether a module's file (``origin``) lies in ``folder`` (a package: its folder does)."""
    if not origin:
        return False
    parent = Path(origin).parent
    return _same_folder(parent, folder) or (
        Path(origin).name == "__init__.py" and _same_folder(parent.parent, folder)
    )


def shadowed_module(name: str, folder: Path) -> str | None:
    """What importing ``name`` gives elsewhere, if anything: the module a file ``name.py`` in
    ``folder`` would shadow for Python run there (``numpy.py`` hides NumPy).  None if nothing.

    The standard library, built-in modules, asymslip's own packages, and every module the
    running interpreter can import from a folder other than ``folder`` (its path entries,
    including installed and editable packages); a module found only in ``folder`` itself --
    an earlier version of the same law module -- shadows nothing.
    """
    if name in sys.stdlib_module_names or name in sys.builtin_module_names:
        return "a module of Python's standard library"
    if name in OWN_PACKAGES:
        return "asymslip's own package"
    elsewhere = [entry for entry in sys.path if not _same_folder(entry or ".", folder)]
    spec = importlib.machinery.PathFinder.find_spec(name, elsewhere)
    if spec is None:
        for finder in sys.meta_path:  # editable installs and other import hooks
            if finder in (
                importlib.machinery.PathFinder,
                importlib.machinery.BuiltinImporter,
                importlib.machinery.FrozenImporter,
            ):
                continue
            try:
                found = finder.find_spec(name, None)
            except Exception:  # noqa: BLE001 - a third-party hook: it only fails to find
                continue
            if found is not None and not _in_folder(found.origin, folder):
                spec = found
                break
    if spec is None:
        return None
    origin = spec.origin if spec.origin not in (None, "built-in", "frozen") else name
    return f"an installed module ({origin})"


def refuse_shadowing(out: Path) -> None:
    """Refuse a law module file whose name is that of an importable module (see
    :func:`shadowed_module`): Python run in its folder would import the law instead."""
    shadowed = shadowed_module(out.stem, out.parent if str(out.parent) else Path("."))
    if shadowed is not None:
        raise InputError(
            "out",
            f"{out.name} would shadow {shadowed}: Python run in {out.parent or '.'} would import "
            f"this law module for every `import {out.stem}`; choose another file name",
        )


@dataclass(frozen=True)
class WrittenLaw:
    """A law module written by :func:`write_law_module`, and what was established about it."""

    path: Path
    #: One sentence: where the law is valid (or why that could not be established).
    range_summary: str


def write_law_module(
    P_of_a: str,
    params: Sequence[str],
    name: str,
    out: str | Path,
    *,
    check: Mapping[str, float] | None = None,
    check_half_widths: Sequence[float] = (),
) -> WrittenLaw:
    """Derive the law ``P(a) = P_of_a`` and write it as a NumPy module.

    Parameters
    ----------
    P_of_a
        The normal load as a formula in the half-width ``a`` and the parameters, e.g.
        ``"pi*E_star*a**2/(4*R)"`` (Hertz, (29)).  Allowed: numbers, ``a``, the parameters,
        :data:`asymslip.expressions.ALLOWED_FUNCTIONS`, ``pi``, ``E``, ``+ - * / ** ^`` and
        parentheses.  The parameters are taken to be positive (write a negative coefficient
        with its minus sign: ``E_star*a**2 - k*a**3``).
    params
        Parameter names, in the order the generated functions take them after ``a``.
    name
        Name of the law (a Python identifier), shown in results and messages.
    out
        The module file to write (``.py``), written whole or not at all.
    check, check_half_widths
        Optional parameter values and half-widths at which dP/da > 0 is checked now.

    Returns
    -------
    WrittenLaw
        ``out`` and one sentence on the range where the law is valid.

    Raises
    ------
    InputError
        Unknown names (listed, with the allowed ones), anything but arithmetic in the formula,
        a law that does not depend on a, a law that provably decreases or is nowhere positive
        where it increases, dP/da <= 0 at a checked point, an unwritable ``out``, or an ``out``
        whose name would shadow an importable module (``numpy.py``: :func:`refuse_shadowing`).
    """
    from .law_range import analyse_law

    if not IDENTIFIER.match(name) or keyword.iskeyword(name):
        raise InputError("name", "must be a Python identifier (letters, digits, _)", name)
    out = Path(out)
    if out.suffix != ".py":
        raise InputError("out", "must be a .py file", str(out))
    refuse_shadowing(out)
    if check_half_widths:  # before the derivation: a typo in a value costs no SymPy time
        _check_values(check_params(params, HALF_WIDTH), dict(check or {}), check_half_widths)
    derived = derive_law(P_of_a, params)
    law_range = analyse_law(derived["load"], derived["load_slope"], derived["a"], P_of_a)
    if check_half_widths:
        _check_increasing(derived, dict(check or {}), check_half_widths, P_of_a)
    source = render_law_module(P_of_a, check_params(params, HALF_WIDTH), name, derived, law_range)
    with atomic_write(out, "out", mode="w") as handle:
        handle.write(source)
    return WrittenLaw(out, law_range.summary)
