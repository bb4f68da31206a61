"""Author-year labels for the book's bibliography (a local Sphinx extension, see _config.yml).

The text cites author-year (``bibtex_reference_style: author_year``); with this pybtex style the list of
references is labelled the same way, e.g. [Johnson 1985], [Young and Budynas 2002], [Xiong et al. 2025].
"""

from __future__ import annotations

import pybtex.plugin
from pybtex.richtext import Text
from pybtex.style.formatting.unsrt import Style as UnsrtStyle
from pybtex.style.labels import BaseLabelStyle
from pybtex.style.sorting.author_year_title import SortingStyle


def _surname(person) -> str:
    return Text(*person.rich_last_names).render_as("text") or str(person)


class AuthorYearLabels(BaseLabelStyle):
    """ "Surname Year", "Surname and Surname Year" or "Surname et al. Year"."""

    def format_labels(self, sorted_entries):
        for entry in sorted_entries:
            people = entry.persons.get("author") or entry.persons.get("editor") or []
            names = [_surname(p) for p in people]
            if not names:
                who = entry.fields.get("institution") or entry.fields.get("organization") or entry.key
            elif len(names) == 1:
                who = names[0]
            elif len(names) == 2:
                who = f"{names[0]} and {names[1]}"
            else:
                who = f"{names[0]} et al."
            yield f"{who} {entry.fields.get('year', 'n.d.')}".replace("{", "").replace("}", "")


class AuthorYearStyle(UnsrtStyle):
    default_label_style = AuthorYearLabels
    default_sorting_style = SortingStyle


def setup(app):
    pybtex.plugin.register_plugin("pybtex.style.formatting", "authoryear", AuthorYearStyle)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
