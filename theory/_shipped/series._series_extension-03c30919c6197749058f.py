# ringchain generated code v1 sha256=2b5d70579d81e284e72b3e08e2e0bc20c0960ce8549359e9612131b58e6d69e3
# derivation: series._series_extension
# source key: ceca10620e89af986038 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: delta_c, F, K_b
# expression sha256: 4d4a973f03e6c55e733864f19a7dda5500fd46b66ed7aa38e692d054b1cdccb3 (of its srepr)
def _lambdifygenerated(delta_c, F, K_b):
    return F/K_b + delta_c
