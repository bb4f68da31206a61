"""Layouts: networks built from rings.  The paper's chains and their graded, alternating, joined and
disordered kinds (:mod:`.chain`, :mod:`.chain_kinds`, :mod:`.chain_file`, :mod:`.disorder`), contacts that
yield (:mod:`.yielding`), the ring-resolved chain (:mod:`.ring_beam`, :mod:`.ring_chain`) and sheets
(:mod:`.sheet`, :mod:`.sheet_runs`)."""
