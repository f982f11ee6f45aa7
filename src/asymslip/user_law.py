"""``asymslip derive``: a contact law P(a) typed as a formula, derived into a law module.

The user gives P(a) as text, e.g. ``"pi*E_star*a**2/(4*R)"``, with the names of its
parameters.  The formula is parsed by SymPy under a whitelist (no ``eval`` of arbitrary
names), differentiated, passed through the paper's calibration (19) -- the symbolic L_I that
``derivations/section2_calibrations.py`` derives from Mossakovskii's superposition -- and
written through the same emitter as the generated package (banner, NumPy docstrings, CSE,
ruff format).  The module needs NumPy only; :class:`asymslip.laws.module_law.ModuleLaw` wraps
it as a contact law.

SymPy is imported only when a law is derived (the ``derive`` extra), never at import time.
"""

from __future__ import annotations

import keyword
import re
import textwrap
from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import Any

from .errors import InputError
from .expressions import IDENTIFIER as _IDENTIFIER
from .expressions import check_params, parse_formula
from .expressions import sympy_module as _sympy

#: The half-width symbol of every law.
HALF_WIDTH = "a"
#: The functions every law module defines, in this order, each taking (a, *params).
LAW_FUNCTIONS = ("load", "load_slope", "normal_edge_multiplier", "normal_edge_multiplier_slope")
#: Version of the ``__asymslip_law__`` description written into law modules.
LAW_FORMAT = 1


def _derivations_folder() -> Path:
    """The repository's ``derivations/`` (the derive step runs from a source checkout)."""
    folder = Path(__file__).resolve().parents[2] / "derivations"
    if not (folder / "section2_calibrations.py").is_file():
        raise InputError("derive", "needs the asymslip source checkout (derivations/ next to "
                         "src/) to derive the calibration (19)", str(folder))  # fmt: skip
    return folder


def parse_law(text: str, params: Sequence[str]) -> tuple[Any, Any, list[Any]]:
    """(P(a) as a SymPy expression, the symbol a, the parameter symbols) from screened text."""
    from .codegen.loader import import_derivation

    a = import_derivation(_derivations_folder(), "_glossary").a  # the symbol (19) is in
    expr, symbols = parse_formula(text, a, params, option="P_of_a")
    return expr, a, symbols


def derive_law(text: str, params: Sequence[str]) -> dict[str, Any]:
    """Derive P, dP/da, L_I from (19) and dL_I/dP for the law ``P(a) = text``.

    Returns the SymPy expressions keyed by :data:`LAW_FUNCTIONS`, plus ``"a"`` and
    ``"params"`` (the symbols).
    """
    load, a, symbols = parse_law(text, params)
    sympy = _sympy()
    from .codegen.loader import import_derivation

    dP_da = import_derivation(_derivations_folder(), "_glossary").dP_da
    calibrations = import_derivation(_derivations_folder(), "section2_calibrations")
    normal_multiplier = calibrations.normal_multiplier
    slope = sympy.diff(load, a)
    if sympy.simplify(slope) == 0:
        raise InputError("P_of_a", "does not depend on a (dP/da is identically zero); a "
                         "contact law P(a) must increase with the half-width a", text)  # fmt: skip
    multiplier = normal_multiplier().subs(dP_da, slope)
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


def _check_increasing(derived: Mapping[str, Any], values: Mapping[str, float],
                      half_widths: Sequence[float], text: str) -> None:  # fmt: skip
    sympy = _sympy()
    names = [symbol.name for symbol in derived["params"]]
    missing = [name for name in names if name not in values]
    if missing:
        raise InputError("check", f"needs a value for every parameter to check dP/da > 0; "
                         f"missing {', '.join(missing)}")  # fmt: skip
    unknown = sorted(set(values) - set(names))
    if unknown:
        raise InputError("check", f"{', '.join(unknown)} is not a parameter of the law")
    substitution = {symbol: sympy.Float(values[symbol.name], 30) for symbol in derived["params"]}
    for half_width in half_widths:
        at = {**substitution, derived["a"]: sympy.Float(half_width, 30)}
        slope = sympy.N(derived["load_slope"].subs(at), 20)
        if not (slope.is_real and slope.is_finite and slope > 0):
            shown = f"{float(slope):.6g}" if slope.is_real and slope.is_finite else str(slope)
            raise InputError("P_of_a", f"dP/da = {shown} is not > 0 at a = {half_width:g} with "
                             + ", ".join(f"{k} = {v:g}" for k, v in values.items())
                             + ": the law must increase with a", text)  # fmt: skip


def render_law_module(text: str, params: Sequence[str], name: str,
                      derived: Mapping[str, Any]) -> str:  # fmt: skip
    """The formatted source of the law module for ``P(a) = text``."""
    from .codegen import Argument
    from .codegen.emit import format_source, render_module
    from .codegen.formula import Formula

    sympy = _sympy()
    shown = sympy.sstr(derived["load"])
    args = (
        Argument(derived["a"], "Contact half-width a > 0 [length]."),
        *(Argument(symbol, f"Parameter {symbol.name} of the law P(a) = {shown}.")
          for symbol in derived["params"]),
    )  # fmt: skip
    source = f"asymslip derive --name {name}"
    specs = {
        "load": ("Normal load P(a) of the contact of half-width a.", (),
                 f"The user's contact law P(a) = {shown}, as given.", "P [force/length]."),
        "load_slope": ("Slope dP/da of the contact law.", ("19",),
                       "Derivative of P(a); must be > 0 for an incomplete contact.",
                       "dP/da [force/length^2]."),
        "normal_edge_multiplier": (
            "Normal edge multiplier L_I of the contact pressure p = L_I sqrt(a - x).", ("19",),
            "The calibration (19), L_I = (1/pi) sqrt(2/a) dP/da, derived from Mossakovskii's "
            "superposition in derivations/section2_calibrations.py, applied to this law.",
            "L_I [force/length^(5/2)]."),
        "normal_edge_multiplier_slope": (
            "Slope dL_I/dP of the normal edge multiplier with load.", ("19", "26"),
            "(dL_I/da)/(dP/da); enters the validity measure (26).", "dL_I/dP."),
    }  # fmt: skip
    formulas = []
    for function in LAW_FUNCTIONS:
        summary, equations, doc, returns = specs[function]
        try:
            formulas.append(Formula(
                name=function, args=args, expr=derived[function], equations=equations,
                summary=summary, doc=doc, module=name, source=source, returns=returns,
            ))  # fmt: skip
        except ValueError as error:
            raise InputError("P_of_a", f"cannot be emitted as NumPy code: {error}", text) from None
    doc = f"Contact law {name}: P(a) = {shown}, parameters {', '.join(params) or '(none)'}.\n\n"
    doc += textwrap.fill(
        "Written by `asymslip derive`; each function takes the half-width a, then the "
        "parameters in that order.  Use it with ``ModuleLaw.from_file`` or "
        "``asymslip ... --law module --module FILE --param NAME=VALUE``.",
        width=92,
    )
    try:
        body = render_module(name, doc, formulas)
    except Exception as error:  # the NumPy printer refuses functions it cannot print
        raise InputError("P_of_a", f"cannot be emitted as NumPy code: {error}", text) from None
    description = (
        "__asymslip_law__ = {\n"
        f'    "format": {LAW_FORMAT},\n'
        f'    "name": {name!r},\n'
        f'    "P_of_a": {shown!r},\n'
        f'    "params": {list(params)!r},\n'
        f'    "functions": {list(LAW_FUNCTIONS)!r},\n'
        "}\n"
    )
    # The law itself has no equation number in the paper (Section 2 introduces a(P) in words).
    body = re.sub(r"Implements\s+Eqs\.\s+of\s+the\s+paper;", "The contact law a(P) of Section 2;",
                  body)  # fmt: skip
    # The engine's banner names `make generate`; a user law is made by `asymslip derive`.
    banner_end = body.index('"""')
    body = (
        f"# Generated by `asymslip derive` from P(a) = {shown} (parameters: "
        f"{' '.join(params) or 'none'}).\n"
        "# Do not edit: change the formula and run `asymslip derive` again.\n" + body[banner_end:]
    )
    marker = "\n]\n"
    cut = body.index(marker, body.index("__all__")) + len(marker)
    body = body[:cut] + "\n" + description + body[cut:]
    return format_source(body)


def derive_law_module(
    P_of_a: str,
    params: Sequence[str],
    name: str,
    out: str | Path,
    *,
    check: Mapping[str, float] | None = None,
    check_half_widths: Sequence[float] = (),
) -> Path:
    """Derive the law ``P(a) = P_of_a`` and write it as a NumPy module.

    Parameters
    ----------
    P_of_a
        The normal load as a formula in the half-width ``a`` and the parameters, e.g.
        ``"pi*E_star*a**2/(4*R)"`` (Hertz, (29)).  Allowed: numbers, ``a``, the parameters,
        :data:`asymslip.expressions.ALLOWED_FUNCTIONS`, ``pi``, ``E``, ``+ - * / ** ^`` and
        parentheses.
    params
        Parameter names, in the order the generated functions take them after ``a``.
    name
        Name of the law (a Python identifier), shown in results and messages.
    out
        The module file to write (``.py``).
    check, check_half_widths
        Optional parameter values and half-widths at which dP/da > 0 is checked now.

    Returns
    -------
    Path
        ``out``.

    Raises
    ------
    InputError
        Unknown names (listed, with the allowed ones), anything but arithmetic in the
        formula, a law that does not depend on a, dP/da <= 0 at a checked point.
    """
    if not _IDENTIFIER.match(name) or keyword.iskeyword(name):
        raise InputError("name", "must be a Python identifier (letters, digits, _)", name)
    out = Path(out)
    if out.suffix != ".py":
        raise InputError("out", "must be a .py file", str(out))
    derived = derive_law(P_of_a, params)
    if check_half_widths:
        _check_increasing(derived, dict(check or {}), check_half_widths, P_of_a)
    source = render_law_module(P_of_a, check_params(params, HALF_WIDTH), name, derived)
    try:
        out.write_text(source)
    except OSError as error:
        raise InputError("out", f"cannot write {out}: {error}") from None
    return out
