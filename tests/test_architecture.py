"""The house has one-way traffic: derivations -> records -> code generator -> generated code ->
API -> command line.  Read from the source's own import statements (``ast``), not assumed."""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

SOURCE = Path(__file__).resolve().parents[1] / "src" / "asymslip"

#: Low to high: a module may import only from its own layer's package or a lower layer.
LAYERS = (
    {"errors", "edge", "lazy"},
    {"expressions", "files", "rules", "laws"},
    {"cycle", "codegen"},
    {"core"},
    {"slip_zones", "edge_flags", "solver"},
    {"tractions", "sweep", "calibration"},
    {"stress"},
    {"nucleation"},
    {"batch"},
    {"figures", "match", "fe"},
    {"cli"},
    {"__main__"},
)


def _module_name(path: Path) -> str:
    parts = path.relative_to(SOURCE.parent).with_suffix("").parts
    return ".".join(parts[:-1] if parts[-1] == "__init__" else parts)


def _imports(path: Path) -> set[str]:
    """Every asymslip module ``path`` imports, at any depth of the file (lazy imports too)."""
    name = _module_name(path)
    package = name if path.name == "__init__.py" else name.rsplit(".", 1)[0]
    found: set[str] = set()
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.Import):
            found.update(alias.name for alias in node.names if alias.name.startswith("asymslip."))
        elif isinstance(node, ast.ImportFrom):
            if node.level:
                base = package.split(".")
                base = base[: len(base) - node.level + 1]
                target = ".".join([*base, node.module] if node.module else base)
            else:
                target = node.module or ""
            if target == "asymslip" or target.startswith("asymslip."):
                # ``from package import submodule`` depends on the submodule; a name defined
                # in the package (its __init__) is a dependency on the package itself.
                for alias in node.names:
                    submodule = f"{target}.{alias.name}"
                    found.add(submodule if _is_module(submodule) else target)
    return {module for module in found if _is_module(module)}


def _is_module(name: str) -> bool:
    relative = Path(*name.split(".")[1:])
    return (SOURCE / relative).with_suffix(".py").is_file() or (SOURCE / relative).is_dir()


GRAPH = {_module_name(path): _imports(path) - {_module_name(path)} for path in SOURCE.rglob("*.py")}


def _top(module: str) -> str:
    parts = module.split(".")
    return parts[1] if len(parts) > 1 else ""


def _layer(module: str) -> int:
    top = _top(module)
    for index, layer in enumerate(LAYERS):
        if top in layer:
            return index
    raise AssertionError(f"{module} is in no layer of LAYERS: place it")


def test_every_module_has_a_layer():
    for module in GRAPH:
        if module != "asymslip":
            _layer(module)


def test_no_module_imports_from_a_higher_layer():
    upward = [
        (module, imported)
        for module, imports in GRAPH.items()
        if module != "asymslip"
        for imported in imports
        if imported != "asymslip" and _layer(imported) > _layer(module)
    ]
    assert upward == []


def test_modules_import_each_other_without_a_circle():
    state: dict[str, int] = {}
    circles: list[list[str]] = []

    def visit(module: str, trail: list[str]) -> None:
        state[module] = 1
        for imported in sorted(GRAPH.get(module, ())):
            if state.get(imported) == 1:
                circles.append([*trail[trail.index(imported) :], imported])
            elif imported not in state:
                visit(imported, [*trail, imported])
        state[module] = 2

    for module in sorted(GRAPH):
        if module not in state:
            visit(module, [module])
    assert circles == []


def test_the_code_generator_never_imports_the_api():
    allowed = {
        "asymslip",
        "asymslip.errors",
        "asymslip.expressions",
        "asymslip.files",
        "asymslip.files.atomic",
        "asymslip.lazy",
    }
    leaks = {
        (module, imported)
        for module, imports in GRAPH.items()
        if _top(module) == "codegen"
        for imported in imports
        if _top(imported) != "codegen" and imported not in allowed
    }
    assert leaks == set()


def test_only_the_command_line_reaches_the_code_generator():
    users = {
        module
        for module, imports in GRAPH.items()
        if any(_top(imported) == "codegen" for imported in imports) and _top(module) != "codegen"
    }
    assert {_top(module) for module in users} <= {"cli"}


@pytest.mark.parametrize("folder", ["solver"])
def test_the_solver_computes_without_the_asymptotes(folder):
    if not (SOURCE / folder).is_dir():
        pytest.skip(f"no {folder} package yet")
    asymptotes = {
        "asymslip.slip_zones",
        "asymslip.tractions",
        "asymslip.core",
        "asymslip.core.evaluation",
        "asymslip.core.edge_state",
        "asymslip.core.estimates",
        "asymslip.core.operations",
    }
    comparing = {f"asymslip.{folder}.compare", f"asymslip.{folder}.error_map"}
    computing = {
        module: imports & asymptotes
        for module, imports in GRAPH.items()
        if _top(module) == folder and module not in comparing
    }
    assert {module: used for module, used in computing.items() if used} == {}


def test_no_source_file_edits_sys_path():
    edits = [
        path.name
        for path in SOURCE.rglob("*.py")
        if "sys.path.insert" in path.read_text() or "sys.path.append" in path.read_text()
    ]
    assert edits == []
