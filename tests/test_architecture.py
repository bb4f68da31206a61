"""The floors of ../shared/ARCHITECTURE.md, read from the code: no import cycle, no private reach, thin command line.

Every import counts, at the top of a module or inside a function.  A module may import an underscore name
only from a private module (``_validate``, ``_codegen``, ``_cli_options``).
"""

import ast
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
PACKAGES = {"theory": "ringchain.theory", "numerics": "ringchain.numerics"}


def modules() -> dict:
    """{dotted name: (syntax tree, is a package __init__)} of every module of the two packages."""
    out = {}
    for folder, package in PACKAGES.items():
        for path in sorted((ROOT / folder).glob("*.py")):
            name = package if path.name == "__init__.py" else f"{package}.{path.stem}"
            out[name] = (ast.parse(path.read_text()), path.name == "__init__.py")
    return out


def imports(name, tree, is_package):
    """(module imported, name imported) of every ``from ... import`` in ``tree``."""
    for node in ast.walk(tree):
        if isinstance(node, ast.ImportFrom):
            if node.level:
                base = name.split(".") if is_package else name.split(".")[:-1]
                base = base[: len(base) - (node.level - 1)]
                target = ".".join(base + ([node.module] if node.module else []))
            else:
                target = node.module or ""
            for alias in node.names:
                yield target, alias.name


MODULES = modules()


def graph() -> dict:
    edges = {name: set() for name in MODULES}
    for name, (tree, is_package) in MODULES.items():
        if name in PACKAGES.values():
            continue  # a package's face hands names on
        for target, imported in imports(name, tree, is_package):
            full = f"{target}.{imported}"
            dependency = full if full in MODULES else target
            if dependency in MODULES and dependency != name and dependency not in PACKAGES.values():
                edges[name].add(dependency)
    return edges


def test_no_import_cycle():
    edges = graph()
    state, cycles = {}, []

    def visit(node, path):
        state[node] = "open"
        for nxt in sorted(edges[node]):
            if state.get(nxt) == "open":
                cycles.append(" -> ".join([*path[path.index(nxt) :], nxt]))
            elif nxt not in state:
                visit(nxt, [*path, nxt])
        state[node] = "done"

    for node in sorted(edges):
        if node not in state:
            visit(node, [node])
    assert cycles == []


def test_no_private_name_is_imported_across_modules():
    reached = []
    for name, (tree, is_package) in MODULES.items():
        for target, imported in imports(name, tree, is_package):
            private_module = target.rsplit(".", 1)[-1].startswith("_")
            if (imported.startswith("_") and not imported.startswith("__") and target in MODULES
                    and f"{target}.{imported}" not in MODULES and target != name and not private_module):  # fmt: skip
                reached.append(f"{name} imports {target}.{imported}")
    assert reached == []


def test_the_command_line_is_thin_and_no_numerics_module_is_huge():
    lines = {path.name: len(path.read_text().splitlines()) for path in (ROOT / "numerics").glob("*.py")}
    assert lines["cli.py"] < 350
    assert {name: n for name, n in lines.items() if n > 900} == {}


def test_theory_is_a_module_per_derivation_none_huge():
    lines = {path.name: len(path.read_text().splitlines()) for path in (ROOT / "theory").glob("*.py")}
    assert {name: n for name, n in lines.items() if n > 900} == {}


@pytest.mark.parametrize("floor", ["network", "laws", "integrate", "results", "traces"])
def test_the_engine_knows_no_layout_and_no_job(floor):
    above = {"chain", "chain_file", "ring_chain", "ring_beam", "paper", "experiment", "sweep", "fit", "fit_dynamic",
             "junction", "effective_mass", "cli", "fit_cli", "_cli_options", "sheet", "sheet_runs",
             "sheet_cli"}  # fmt: skip
    assert {dep.rsplit(".", 1)[-1] for dep in graph()[f"ringchain.numerics.{floor}"]} & above == set()
