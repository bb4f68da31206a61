"""Jobs: the paper's tables and figures (:mod:`.paper`), a drop read at two sensors (:mod:`.experiment`), grids
(:mod:`.sweep`), ensembles of disordered chains (:mod:`.ensemble`), fits to measurements (:mod:`.fit`,
:mod:`.fit_dynamic`), the effective mass (:mod:`.effective_mass`), the pulse at a junction (:mod:`.junction`) and
where the energy of a yielding chain goes (:mod:`.dissipation`)."""
