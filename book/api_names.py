"""Write the package's public names into api.md: ``python book/api_names.py`` (``--check``: only compare).

The two package sections of the API page list every name of ``ringchain.theory.__all__`` and
``ringchain.numerics.__all__``, in that order, in their summary table and in autodoc's member
list; tests/book/test_book.py checks that the page is current.
"""

from __future__ import annotations

import importlib
import re
import sys
from pathlib import Path

PAGE = Path(__file__).with_name("api.md")
PACKAGES = ("ringchain.theory", "ringchain.numerics")


def public_names(package: str) -> list[str]:
    """The names of ``package.__all__`` that its section documents: not submodules (each has its own section),
    nor a name an earlier package of :data:`PACKAGES` exports too (documented there, once)."""
    module = importlib.import_module(package)
    earlier = {name for other in PACKAGES[: PACKAGES.index(package)] for name in importlib.import_module(other).__all__}
    return [name for name in module.__all__
            if type(getattr(module, name)).__name__ != "module" and name not in earlier]  # fmt: skip


def current_page(text: str) -> str:
    """``text`` (api.md) with both package sections' name lists rewritten from ``__all__``."""
    for package in PACKAGES:
        names = public_names(package)
        section = re.compile(
            rf"(\.\. currentmodule:: {re.escape(package)}\n\n\.\. autosummary::\n   :nosignatures:\n\n)"
            rf"(?:   \S+\n)*(\n\.\. automodule:: {re.escape(package)}\n   :members: )[^\n]*\n"
        )
        if not section.search(text):
            raise SystemExit(f"{PAGE}: the section of {package} is not in the expected form")
        # A dict or tuple constant has no docstring of its own: autosummary would show the builtin's ("dict(**kwargs)
        # -> ...", broken reStructuredText); it is listed under automodule, which reads its #: comment.
        module = importlib.import_module(package)
        table = "".join(f"   {name}\n" for name in names if not isinstance(getattr(module, name), (dict, tuple, list)))
        text = section.sub(lambda m, t=table, n=names: m.group(1) + t + m.group(2) + ", ".join(n) + "\n", text)
    return text


def main(argv=None) -> int:
    check = "--check" in (sys.argv[1:] if argv is None else argv)
    text = PAGE.read_text()
    new = current_page(text)
    if check:
        return 0 if new == text else 1
    PAGE.write_text(new)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
