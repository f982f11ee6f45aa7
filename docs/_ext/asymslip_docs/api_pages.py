"""The Python API reference, one page per module, written from the packages at build time.

Every module of ``asymslip`` and ``asymslip_gen`` gets a page (``docs/reference/api/``, not
committed) with its docstring and every public name it defines: the names in ``__all__``, or,
without ``__all__``, the classes and functions whose ``__module__`` is the module.  A name a
package re-exports is documented once, where it is defined, and the package's page links to it,
so that a cross-reference never has two targets.  A module added to either package appears with
no change to the docs; ``tests/docs/test_site.py`` checks that every public name is in the
built inventory.
"""

from __future__ import annotations

import ast
import importlib
import inspect
import pkgutil
from dataclasses import dataclass
from pathlib import Path
from types import ModuleType
from typing import Any

from sphinx.application import Sphinx
from sphinx.domains.python import PythonDomain
from sphinx.environment import BuildEnvironment
from sphinx.errors import PycodeError
from sphinx.pycode import ModuleAnalyzer

from .docstrings import escape_line

#: The packages documented, with the title of their part of the reference.
PACKAGES = {
    "asymslip": "The API (hand-written, in src/asymslip)",
    "asymslip_gen": "The generated kernels (emitted by make generate into generated/asymslip_gen)",
}
#: Modules that must not be imported to be documented (running them has effects).
SKIPPED = {"asymslip.__main__", "asymslip.codegen.__main__"}
FOLDER = Path("reference") / "api"
#: Every module documented, and the names written as re-export entries (filled by write_pages):
#: the short-name resolver skips the latter, so that a name has one target.
SUBMODULES: set[str] = set()
ALIASES: set[str] = set()
#: The type aliases declared on the pages (``module.Name``), for the annotation resolver.
DOCUMENTED_ALIASES: set[str] = set()


@dataclass(frozen=True)
class ModulePage:
    """What one module's page shows."""

    name: str
    summary: str
    defined: tuple[tuple[str, str], ...]  # (name, autodoc directive)
    reexported: tuple[tuple[str, str, str], ...]  # (name, directive, canonical dotted path)


def module_names(package: str) -> list[str]:
    """Every module of ``package``, the package first, in name order."""
    root = importlib.import_module(package)
    found = [package]
    for info in pkgutil.walk_packages(root.__path__, f"{package}."):
        if info.name not in SKIPPED and not info.name.split(".")[-1].startswith("_"):
            found.append(info.name)
    return sorted(found)


def _directive(value: Any) -> str | None:
    if inspect.isclass(value):
        return "exception" if issubclass(value, BaseException) else "class"
    if inspect.isfunction(value) or inspect.isbuiltin(value):
        return "function"
    if callable(value) and inspect.isfunction(getattr(value, "__wrapped__", None)):
        return "function"  # a decorated function (functools.lru_cache and the like)
    return None


def is_type_alias(value: Any) -> bool:
    """``Parsed = tuple[...]``, ``Engine = Literal[...]``, ``X = A | B``: a typing construct."""
    kind = type(value)
    return kind.__module__ in {"typing", "types"} and kind.__name__ in {
        "GenericAlias",
        "UnionType",
        "_GenericAlias",
        "_LiteralGenericAlias",
        "_UnionGenericAlias",
        "_SpecialGenericAlias",
        "_CallableGenericAlias",
    }


def _attribute_doc(module: str, name: str) -> list[str]:
    """The ``#:`` comment of a module-level name, as written."""
    try:
        analyzer = ModuleAnalyzer.for_module(module)
        analyzer.analyze()
    except PycodeError:
        return []
    return list(analyzer.attr_docs.get(("", name), []))


def _canonical(value: Any, name: str) -> str | None:
    module = getattr(value, "__module__", None)
    qualname = getattr(value, "__qualname__", name)
    return f"{module}.{qualname}" if module else None


def documented_data(module: ModuleType) -> list[str]:
    """Module-level values the module's own source documents with a ``#:`` comment or names
    as a constant (an UPPER_CASE name assigned at the top level)."""
    try:
        analyzer = ModuleAnalyzer.for_module(module.__name__)
        analyzer.analyze()
    except PycodeError:
        return []
    names = [
        name for (scope, name) in analyzer.attr_docs if scope == "" and not name.startswith("_")
    ]
    tree = ast.parse(analyzer.code)
    for node in tree.body:
        targets = node.targets if isinstance(node, ast.Assign) else [getattr(node, "target", None)]
        for target in targets:
            if (
                isinstance(target, ast.Name)
                and target.id.isupper()
                and not target.id.startswith("_")
                and target.id not in names
            ):
                names.append(target.id)
    return names


def public_names(module: ModuleType) -> list[str]:
    """The module's public names: ``__all__``, or else the classes and functions defined in it
    and the module-level values it documents with ``#:`` comments."""
    exported = getattr(module, "__all__", None)
    if exported is not None:
        return [str(name) for name in exported]
    names = [
        name
        for name, value in vars(module).items()
        if not name.startswith("_")
        and _directive(value) is not None
        and getattr(value, "__module__", None) == module.__name__
    ]
    return names + [name for name in documented_data(module) if name not in names]


def describe(name: str) -> ModulePage:
    """The page of module ``name``: its public names split into defined and re-exported."""
    module = importlib.import_module(name)
    defined: list[tuple[str, str]] = []
    reexported: list[tuple[str, str, str]] = []
    for member in public_names(module):
        value = getattr(module, member)
        directive = _directive(value)
        canonical = _canonical(value, member)
        home = getattr(value, "__module__", None)
        if directive is not None and home != name and canonical is not None:
            reexported.append((member, directive, canonical))
        elif directive is None and is_type_alias(value):
            defined.append((member, "alias"))
        else:
            defined.append((member, directive or "data"))
    doc = inspect.getdoc(module) or ""
    summary = doc.strip().splitlines()[0] if doc.strip() else ""
    return ModulePage(name, summary, tuple(defined), tuple(reexported))


def render(page: ModulePage) -> str:
    """reStructuredText of one module's page."""
    title = f"``{page.name}``"
    lines = [f".. _api-{page.name}:", "", title, "=" * len(title), ""]
    lines += [f".. automodule:: {page.name}", "   :no-members:", ""]
    if page.reexported:
        # A short entry under the name users import (found in the index, and by that name in
        # docstrings) that points to the one full description, where the object is defined.
        lines += [".. rubric:: Re-exported here", ""]
        for member, directive, canonical in page.reexported:
            home = canonical.rsplit(".", 1)[0]
            if f"{page.name}.{member}" in SUBMODULES:
                # The name is also a submodule's: one entry per name, so a link only.
                lines += [f"- ``{member}``: see :py:obj:`{canonical}`", ""]
                continue
            lines += [
                f".. py:{directive}:: {member}",
                f"   :module: {page.name}",
                "",
                f"   Defined in :py:mod:`{home}`: see :py:obj:`{canonical}`.",
                "",
            ]
    if page.defined:
        lines += [".. rubric:: Defined here", ""]
        for member, directive in page.defined:
            if directive == "alias":
                # autodoc cannot format every typing construct (a tuple[...] of five members
                # fails): a type alias is declared by hand with its #: comment and its value.
                value = getattr(importlib.import_module(page.name), member)
                lines += [f".. py:data:: {member}", f"   :module: {page.name}", ""]
                doc = _attribute_doc(page.name, member)
                lines += [f"   {escape_line(line)}" for line in doc if line]
                lines += ["", "   A type alias of::", "", f"      {value!r}", ""]
                continue
            lines.append(f".. auto{directive}:: {page.name}.{member}")
            if directive in ("class", "exception"):
                lines += ["   :members:", "   :undoc-members:"]
            lines.append("")
    return "\n".join(lines)


def render_index(pages: dict[str, list[ModulePage]]) -> str:
    lines = [
        "Python API",
        "==========",
        "",
        "Every module of the two packages, one page each, written from the modules themselves at",
        "build time.  Functions are array-first: they broadcast over NumPy arrays, and scalars in",
        "give scalars out.  Equation numbers in the docstrings are the paper's.",
        "",
    ]
    for package, title in PACKAGES.items():
        lines += [title, "-" * len(title), ""]
        lines += [".. list-table::", "   :header-rows: 1", "   :widths: 35 65", ""]
        lines += ["   * - module", "     - what it holds"]
        for page in pages[package]:
            summary = page.summary.replace("|", "\\|") or " "
            lines += [f"   * - :ref:`{page.name} <api-{page.name}>`", f"     - {summary}"]
        lines += ["", ".. toctree::", "   :hidden:", ""]
        lines += [f"   {page.name}" for page in pages[package]]
        lines.append("")
    return "\n".join(lines)


def write_if_changed(path: Path, text: str) -> None:
    """Rewrite only what changed, so that an unchanged page is not read again."""
    if not path.is_file() or path.read_text(encoding="utf-8") != text:
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text, encoding="utf-8")


def write_pages(srcdir: Path) -> None:
    folder = srcdir / FOLDER
    SUBMODULES.update(name for package in PACKAGES for name in module_names(package))
    pages = {package: [describe(name) for name in module_names(package)] for package in PACKAGES}
    ALIASES.update(
        f"{page.name}.{member}"
        for package_pages in pages.values()
        for page in package_pages
        for member, _, _ in page.reexported
    )
    DOCUMENTED_ALIASES.update(
        f"{page.name}.{member}"
        for package_pages in pages.values()
        for page in package_pages
        for member, directive in page.defined
        if directive == "alias"
    )
    wanted = {"index.rst"}
    for package_pages in pages.values():
        for page in package_pages:
            wanted.add(f"{page.name}.rst")
            write_if_changed(folder / f"{page.name}.rst", render(page))
    write_if_changed(folder / "index.rst", render_index(pages))
    for stale in folder.glob("*.rst"):
        if stale.name not in wanted:
            stale.unlink()


def _builder_inited(app: Sphinx) -> None:
    write_pages(Path(app.srcdir))


def _mark_aliases(app: Sphinx, env: BuildEnvironment) -> None:
    """The re-export entries are aliases of the one description where the object is defined.

    Sphinx prefers the one non-aliased object among several candidates, so ``ContactLaw``
    resolves to ``asymslip.laws.base.ContactLaw`` although ``asymslip.ContactLaw`` and
    ``asymslip.laws.ContactLaw`` are entries too (an exact ``asymslip.ContactLaw`` still finds
    its own entry, which links to the description).
    """
    domain = env.get_domain("py")
    assert isinstance(domain, PythonDomain)
    for name in ALIASES:
        entry = domain.objects.get(name)
        if entry is not None and not entry.aliased:
            domain.objects[name] = entry._replace(aliased=True)


def setup(app: Sphinx) -> dict[str, Any]:
    app.connect("builder-inited", _builder_inited)
    app.connect("env-updated", _mark_aliases)
    return {"parallel_read_safe": True}
