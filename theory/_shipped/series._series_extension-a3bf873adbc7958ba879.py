# ringchain generated code v1 sha256=e32c030e9a9878fb34bd4fb31c2da2886f04c95fa87f75196d4d5835039aa8a9
# derivation: series._series_extension
# source key: 67895ff0807168ca9dd5 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: delta_c, F, K_b
# expression sha256: 4d4a973f03e6c55e733864f19a7dda5500fd46b66ed7aa38e692d054b1cdccb3 (of its srepr)
def _lambdifygenerated(delta_c, F, K_b):
    return F/K_b + delta_c
