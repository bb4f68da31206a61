"""The engine: sites and links with contact laws (:mod:`.network`, :mod:`.laws`), one integrator layer
(:mod:`.integrate`) and its compiled kernels (:mod:`.kernels`), result records (:mod:`.results`),
measurement files (:mod:`.traces`), pulses read from traces (:mod:`.signals`), where jobs run
(:mod:`.executors`) and figures (:mod:`.plots`).  It knows no layout and no job."""
