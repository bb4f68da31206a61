# ringchain generated code v1 sha256=5284e5be06d4063191bbe6cb45deff45f56ef7b630bb7c3fb3c31c7194290608
# derivation: series._series_extension
# source key: 0881d513a06819d2e367 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: delta_c, F, K_b
# expression sha256: 4d4a973f03e6c55e733864f19a7dda5500fd46b66ed7aa38e692d054b1cdccb3 (of its srepr)
def _lambdifygenerated(delta_c, F, K_b):
    return F/K_b + delta_c
