# ringchain generated code v1 sha256=d38ed8a709d6b6ce8bbcff6396b813e6f95917c8af6e734f0bf3a1c8d6afa23c
# derivation: series._series_extension
# source key: caeff341571871d5b69b (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: delta_c, F, K_b
# expression sha256: 4d4a973f03e6c55e733864f19a7dda5500fd46b66ed7aa38e692d054b1cdccb3 (of its srepr)
def _lambdifygenerated(delta_c, F, K_b):
    return F/K_b + delta_c
