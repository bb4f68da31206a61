# ringchain generated code v1 sha256=eab9d714ddd951da886ce2a2ad694fb0eb07d13171bfcd4fdd45b9ec26ee66c9
# derivation: series._series_extension
# source key: 07201ab9dccdbac32795 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: delta_c, F, K_b
# expression sha256: 4d4a973f03e6c55e733864f19a7dda5500fd46b66ed7aa38e692d054b1cdccb3 (of its srepr)
def _lambdifygenerated(delta_c, F, K_b):
    return F/K_b + delta_c
