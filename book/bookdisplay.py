"""Display helpers shared by the book's pages (run from book/, so ``import bookdisplay`` works).

They only format what the package returns: an equation is ``sympy.latex`` of the package's
expression, with derivatives of the fields written as subscripts (u_xx for d^2u/dx^2) and
long sums broken over lines; a table is Markdown built from numbers the page computed.
"""

from __future__ import annotations

import sympy as sp
from IPython.display import Markdown, Math, display

__all__ = ["compact", "grouped", "show", "table"]


def compact(expr):
    """``expr`` with u(x, t), xi(x, t), f(tau) and their derivatives written as u, u_x, u_xx, ..."""
    if not isinstance(expr, sp.Basic):
        return expr
    replacements = {}
    for derivative in expr.atoms(sp.Derivative):
        function = derivative.expr
        if isinstance(function, sp.core.function.AppliedUndef):
            name = sp.latex(function.func)
            subscript = "".join(sp.latex(variable) * count for variable, count in derivative.variable_count)
            replacements[derivative] = sp.Symbol(f"{name}_{{{subscript}}}")
    expr = expr.xreplace(replacements)
    functions = {f: sp.Symbol(sp.latex(f.func)) for f in expr.atoms(sp.core.function.AppliedUndef)}
    return expr.xreplace(functions)


def grouped(expr):
    """``compact(expr)`` with its terms grouped by their field factors, each coefficient factored.

    E.g. n^2 u_xx^3/24 - n u_xx^3/8 + ... becomes n (n - 3)/24 u_xx^3 + ...; the value is unchanged.
    """
    expr = sp.expand(compact(expr))
    fields = [s for s in expr.free_symbols if "_{" in s.name or s.name in ("u", "\\xi", "f")]
    groups: dict = {}
    for term in sp.Add.make_args(expr):
        coefficient, part = term.as_independent(*fields, as_Add=False)
        groups[part] = groups.get(part, 0) + coefficient
    return sp.Add(*[sp.factor(c) * part for part, c in groups.items()])


def show(lhs: str, expr, *, per_line: int | None = None) -> None:
    """Display ``lhs = expr``; a sum with more than ``per_line`` terms is broken over several lines."""
    expr = compact(expr)
    terms = sp.Add.make_args(expr) if isinstance(expr, sp.Add) else (expr,)
    if per_line is None or len(terms) <= per_line:
        display(Math(f"{lhs} = {sp.latex(expr)}"))
        return
    lines = []
    for start in range(0, len(terms), per_line):
        chunk = sp.latex(sp.Add(*terms[start : start + per_line], evaluate=False))
        if start and not chunk.startswith("-"):
            chunk = "+ " + chunk
        lines.append(("&= " if start == 0 else "&\\quad ") + chunk)
    display(Math(f"\\begin{{aligned}}{lhs} " + " \\\\\n".join(lines) + "\\end{aligned}"))


def table(header, rows, caption: str | None = None) -> None:
    """A Markdown table (and an optional caption line above it)."""
    lines = [] if caption is None else [caption, ""]
    lines += ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    lines += ["| " + " | ".join(row) + " |" for row in rows]
    display(Markdown("\n".join(lines)))
