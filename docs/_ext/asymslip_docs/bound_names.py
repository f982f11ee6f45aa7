"""A type name in a signature means what the documented module binds it to.

Sphinx turns every name of an annotation (``-> bytes``, ``law: ContactLaw``) into a
cross-reference that it resolves *fuzzily*: with no object of that exact name it links to any
documented object whose name ends with it, and warns when there are several.  So ``bytes`` met
the attributes ``WrittenTable.bytes``, ``StudyRun.bytes`` and ``BatchSummary.bytes``, and
``EdgeState`` met two different classes of that name (the core's and the solver's).  Python
itself reads an annotation in the namespace of the module that wrote it; this transform does the
same before Sphinx resolves anything:

* a name the module binds to a class or function (its own, an import, a builtin) is rewritten
  to that object's full name, so it resolves exactly or not at all (``bytes`` becomes
  ``builtins.bytes``, which has no target offline and is ignored as foreign, like ``numpy``);
* a type variable (``Task = TypeVar("Task")``) has no page: it is shown as plain text;
* a type alias is linked to its description where the module documents it (a ``#:`` comment),
  and is otherwise shown as what it stands for (``FloatArray`` as ``numpy.ndarray[...,
  numpy.dtype[numpy.float64]]``), each name in it a reference of its own;
* a name the module does not bind is left as written, for the resolvers that follow
  (:mod:`short_names`), so an unknown name still fails ``-n -W``.

Only annotation references are touched (Sphinx marks them with a ``refspecific`` attribute and a
``class`` or ``obj`` role); a reference written in a docstring (``:attr:`bytes```) is left alone.
"""

from __future__ import annotations

import builtins
import importlib
import inspect
from types import ModuleType
from typing import Any, TypeVar

from docutils import nodes
from sphinx.addnodes import pending_xref
from sphinx.application import Sphinx
from sphinx.domains.python._annotations import _parse_annotation
from sphinx.environment import BuildEnvironment
from sphinx.util.typing import stringify_annotation

from .api_pages import DOCUMENTED_ALIASES, is_type_alias

#: The roles Sphinx gives the names of an annotation.
ANNOTATION_ROLES = {"class", "obj"}
PACKAGES = ("asymslip", "asymslip_gen")


def _module(name: str | None) -> ModuleType | None:
    if not name or name.split(".")[0] not in PACKAGES:
        return None
    try:
        return importlib.import_module(name)
    except ImportError:
        return None


def _bound(module: ModuleType, target: str) -> Any:
    """What ``target`` (``name`` or ``name.attr...``) is in the module's namespace, or None."""
    head, *rest = target.split(".")
    namespace = vars(module)
    if head in namespace:
        value = namespace[head]
    elif hasattr(builtins, head):
        value = getattr(builtins, head)
    else:
        return None
    for part in rest:
        value = getattr(value, part, None)
        if value is None:
            return None
    return value


def _located(target: str) -> tuple[ModuleType, str] | None:
    """A full name of the packages split into its longest importable module and the rest."""
    parts = target.split(".")
    for cut in range(len(parts) - 1, 0, -1):
        module = _module(".".join(parts[:cut]))
        if module is not None:
            return module, ".".join(parts[cut:])
    return None


def full_name(value: Any) -> str | None:
    """``module.qualname`` of a class, function or module; None for anything else."""
    if inspect.ismodule(value):
        return str(value.__name__)
    if inspect.isclass(value) or inspect.isfunction(value) or inspect.isbuiltin(value):
        module = getattr(value, "__module__", None)
        qualname = getattr(value, "__qualname__", None)
        if module and qualname and "<locals>" not in qualname:
            return f"{module}.{qualname}"
    return None


def rebind(node: pending_xref, env: BuildEnvironment, documented: set[str]) -> None:
    """Rewrite one annotation reference to the object its module binds the name to."""
    target = str(node["reftarget"])
    if target.startswith((".", "~")):
        return  # relative: Sphinx's own rules apply
    if target.split(".")[0] in PACKAGES:
        located = _located(target)
        if located is None:
            return
        module, target = located
    else:
        found = _module(node.get("py:module"))
        if found is None:
            return
        module = found
    value = _bound(module, target)
    if isinstance(value, TypeVar):
        node.replace_self(nodes.Text(node.astext()))
        return
    if is_type_alias(value):
        alias = f"{module.__name__}.{target}"
        if alias in documented:
            node["reftarget"] = alias
            return
        # An alias the module does not document (``FloatArray = NDArray[np.float64]`` in many
        # modules): shown as what it stands for, each name of it a reference of its own.
        text = stringify_annotation(value, "fully-qualified-except-typing")
        expansion = _parse_annotation(text, env)
        for part in expansion:
            if isinstance(part, pending_xref):
                part["py:module"] = module.__name__
        node.replace_self(expansion)
        return
    name = full_name(value)
    if name is not None and name != node["reftarget"]:
        node["reftarget"] = name


def _doctree_read(app: Sphinx, doctree: nodes.document) -> None:
    documented = set(DOCUMENTED_ALIASES)
    for node in list(doctree.findall(pending_xref)):
        if (
            node.get("refdomain") == "py"
            and node.get("reftype") in ANNOTATION_ROLES
            and node.hasattr("refspecific")
        ):
            rebind(node, app.env, documented)


def setup(app: Sphinx) -> dict[str, Any]:
    app.connect("doctree-read", _doctree_read)
    return {"parallel_read_safe": True}
