"""The floors of ../shared/ARCHITECTURE.md, read from the code: no import cycle, no private reach, imports only
downwards, thin command line, the public names where they were.

Every import counts, at the top of a module or inside a function.  A module may import an underscore name
only from a private module (``_validate``, ``_codegen``, ``_options``).
"""

import ast
import importlib
import subprocess
import sys
from pathlib import Path

import pytest
import tomllib

ROOT = Path(__file__).resolve().parents[1]
PACKAGES = {"theory": "ringchain.theory", "numerics": "ringchain.numerics"}

#: The floors of numerics, bottom to top: a module imports only from its own floor and those below.
FLOORS = ("engine", "contact", "layouts", "jobs", "cli")


def modules() -> dict:
    """{dotted name: (syntax tree, is a package __init__)} of every module of the two packages, subpackages too."""
    out = {}
    for folder, package in PACKAGES.items():
        for path in sorted((ROOT / folder).rglob("*.py")):
            parts = list(path.relative_to(ROOT / folder).with_suffix("").parts)
            is_package = parts[-1] == "__init__"
            name = ".".join([package, *(parts[:-1] if is_package else parts)])
            out[name] = (ast.parse(path.read_text()), is_package)
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


def floor(name: str) -> int | None:
    """The floor of a numerics module (index into FLOORS); None for the package's face and for theory."""
    parts = name.split(".")
    if parts[:2] != ["ringchain", "numerics"] or len(parts) < 4:
        return None
    return FLOORS.index(parts[2])


def test_every_numerics_module_lives_on_a_floor():
    stray = [name for name in MODULES if name.startswith("ringchain.numerics.") and name.count(".") == 2
             and name.rsplit(".", 1)[-1] not in FLOORS]  # fmt: skip
    assert stray == []
    assert len(list((ROOT / "numerics").glob("*.py"))) <= 6
    assert sorted(p.name for p in (ROOT / "numerics").iterdir() if p.is_dir() and p.name != "__pycache__") == sorted(
        FLOORS
    )


def test_a_floor_imports_only_from_itself_and_the_floors_below():
    upward = []
    for name, deps in graph().items():
        here = floor(name)
        if name.startswith("ringchain.theory"):
            upward += [f"{name} -> {dep}" for dep in deps if dep.startswith("ringchain.numerics")]
        elif here is not None:
            upward += [f"{name} -> {dep}" for dep in deps if (floor(dep) or 0) > here]
    assert upward == []


def test_the_wheel_lists_every_subpackage():
    config = tomllib.loads((ROOT / "pyproject.toml").read_text())["tool"]["setuptools"]
    packages = {name for name, (_, is_package) in MODULES.items() if is_package}
    assert packages == set(config["packages"])


def test_the_public_names_of_the_last_release_import_from_the_same_package():
    listed = [line.split() for line in (ROOT / "tests" / "public_names.txt").read_text().splitlines()
              if line and not line.startswith("#")]  # fmt: skip
    missing = []
    for package, name in listed:
        module = importlib.import_module(package)
        if name not in module.__all__ or not hasattr(module, name):
            missing.append(f"{package}.{name}")
    assert len(listed) > 150 and missing == []
    from ringchain.numerics.engine import laws, signals
    from ringchain.numerics.laws import PowerLaw
    from ringchain.numerics.signals import leading_pulse

    assert PowerLaw is laws.PowerLaw and leading_pulse is signals.leading_pulse


def test_the_command_line_is_thin_and_no_module_is_huge():
    lines = {path.relative_to(ROOT).as_posix(): len(path.read_text().splitlines())
             for folder in PACKAGES for path in (ROOT / folder).rglob("*.py")}  # fmt: skip
    assert lines["numerics/cli/commands.py"] < 350
    assert {name: n for name, n in lines.items() if n > 900} == {}


@pytest.mark.parametrize("module", ["network", "laws", "integrate", "kernels", "results", "traces", "signals"])
def test_the_engine_knows_no_layout_and_no_job(module):
    deps = graph()[f"ringchain.numerics.engine.{module}"]
    assert {dep for dep in deps if dep.startswith("ringchain.numerics") and floor(dep) != 0} == set()


def test_the_numerics_face_hands_on_each_name_from_the_module_that_defines_it():
    # The face imports a name's module on first use (numerics/__init__.py, PEP 562): each name it lists is the
    # defining module's own object, every name of __all__ is listed once, and dir() shows them before any use.
    import ringchain.numerics as face

    listed = [name for names in face._WHERE.values() for name in names]
    assert sorted(listed) == sorted(set(face.__all__) - {"laws", "signals"}) and len(listed) == len(set(listed))
    for module, names in face._WHERE.items():
        source = importlib.import_module(module, face.__name__)
        assert all(getattr(face, name) is getattr(source, name) for name in names), module
    assert set(face.__all__) <= set(dir(face))
    with pytest.raises(AttributeError, match="no attribute 'not_a_name'"):
        face.not_a_name  # noqa: B018


def test_importing_the_numerics_loads_neither_sympy_nor_scipy_nor_matplotlib():
    # A fresh interpreter (this session has imported everything): the numeric API starts without the symbolic
    # engine, the plotting library, SciPy or Numba; each is imported by what needs it.
    code = "import sys, ringchain.numerics; print(*sorted(sys.modules))"
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    loaded = set(done.stdout.split())
    assert {"ringchain.numerics", "numpy"} <= loaded
    assert {name.split(".")[0] for name in loaded} & {"sympy", "matplotlib", "scipy", "numba"} == set()
