"""Resolve a short or package-relative name in an asymslip docstring to its one description.

Docstrings name things as their readers do: ``:func:`calibrate``` in the calibration package,
``:class:`Formula``` in the code generator, ``:class:`asymslip.LoadCycle``` for what the package
exports.  Sphinx looks such a name up only in the current module and class; where that fails,
this handler looks for the objects of the asymslip packages whose full name ends with the
written one (``.calibrate``) and are of a kind the role accepts, and links to it when there is
exactly one.  Anything ambiguous or absent is left unresolved, so ``-n -W`` still fails on it.
"""

from __future__ import annotations

import importlib
from typing import Any

from docutils import nodes
from sphinx.addnodes import pending_xref
from sphinx.application import Sphinx
from sphinx.domains.python import PythonDomain
from sphinx.environment import BuildEnvironment
from sphinx.util.nodes import make_refnode

from .api_pages import ALIASES

PACKAGES = ("asymslip.", "asymslip_gen.")
#: The object kinds each role may point to.
KINDS = {
    "func": {"function", "method", "classmethod", "staticmethod"},
    "meth": {"method", "classmethod", "staticmethod", "property"},
    "class": {"class", "exception"},
    "exc": {"exception", "class"},
    "data": {"data", "attribute"},
    "attr": {"attribute", "property", "data"},
    "const": {"data", "attribute"},
    "mod": {"module"},
}


def _candidates(domain: PythonDomain, target: str, role: str) -> set[tuple[str, str]]:
    kinds = KINDS.get(role)
    written = target.removeprefix("asymslip.") if target.startswith("asymslip.") else target
    found: set[tuple[str, str]] = set()
    for name, entry in domain.objects.items():
        if not name.startswith(PACKAGES) or entry.aliased or name in ALIASES:
            continue
        if kinds is not None and entry.objtype not in kinds:
            continue
        if name == target or name.endswith(f".{written}"):
            found.add((name, entry.docname))
    return found


def _value(name: str) -> Any:
    """The object a full name of the packages stands for, or None."""
    parts = name.split(".")
    for cut in range(len(parts) - 1, 0, -1):
        try:
            value: Any = importlib.import_module(".".join(parts[:cut]))
        except ImportError:
            continue
        for attribute in parts[cut:]:
            value = getattr(value, attribute, None)
        return value
    return None


def _inherited(domain: PythonDomain, node: pending_xref, target: str) -> set[tuple[str, str]]:
    """A member written as ``name`` inside a class, or ``Class.name``, that the class inherits:
    the description on the first class of its method resolution order that has one."""
    if "." in target:
        owner_name, member = target.rsplit(".", 1)
        owners = {name for name, _ in _candidates(domain, owner_name, "class")}
    else:
        member = target
        context = ".".join(part for part in (node.get("py:module"), node.get("py:class")) if part)
        owners = {context} if context else set()
    found: set[tuple[str, str]] = set()
    for owner in owners:
        cls = _value(owner)
        if not isinstance(cls, type):
            continue
        for base in cls.__mro__:
            name = f"{base.__module__}.{base.__qualname__}.{member}"
            entry = domain.objects.get(name)
            if entry is not None and member in vars(base):
                found.add((name, entry.docname))
                break
    return found


def _as_bound(node: pending_xref, target: str, found: set[tuple[str, str]]) -> set[tuple[str, str]]:
    """Of several candidates, the one that is the object the docstring's module binds the name to
    (``CYCLE_COLUMNS`` in ``sweep.evaluate`` is the one it imports from ``sweep.columns``, not
    ``batch.cases``'s own), as Python would read the name there."""
    module = node.get("py:module")
    if not module or "." in target:
        return found
    try:
        namespace = vars(importlib.import_module(module))
    except ImportError:
        return found
    if target not in namespace:
        return found
    value = namespace[target]
    return {(name, docname) for name, docname in found if _value(name) is value}


def resolve(
    app: Sphinx, env: BuildEnvironment, node: pending_xref, contnode: nodes.Element
) -> nodes.Element | None:
    if node.get("refdomain") != "py":
        return None
    target = node["reftarget"].lstrip("~.")
    if not target:
        return None
    domain = env.get_domain("py")
    assert isinstance(domain, PythonDomain)
    # What the class in context (or the named class) inherits comes first; then the one object
    # of the packages whose name ends with the written one.
    found = _inherited(domain, node, target)
    if not found:
        found = _candidates(domain, target, node.get("reftype", "obj"))
    if len(found) > 1:
        found = _as_bound(node, target, found)
    if len(found) != 1:
        return None
    ((name, docname),) = found
    entry = domain.objects[name]
    return make_refnode(app.builder, node["refdoc"], docname, entry.node_id, contnode, name)


def setup(app: Sphinx) -> dict[str, Any]:
    app.connect("missing-reference", resolve, priority=400)
    return {"parallel_read_safe": True}
