# ringchain generated code v1 sha256=f2ffdbae269962ef750eb5de1b4261da5beb38248e9769317bd3a5e5d1d882ef
# derivation: series._series_extension
# source key: 10a35615fa68ecdff34f (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: delta_c, F, K_b
# expression sha256: 4d4a973f03e6c55e733864f19a7dda5500fd46b66ed7aa38e692d054b1cdccb3 (of its srepr)
def _lambdifygenerated(delta_c, F, K_b):
    return F/K_b + delta_c
