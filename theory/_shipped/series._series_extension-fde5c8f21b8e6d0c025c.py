# ringchain generated code v1 sha256=8fb0e6325dfff5f929426a5c16892293154b581d3a9a7eebcc2fecb94cb2c415
# derivation: series._series_extension
# source key: 263ab3517922b3fc21eb (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: delta_c, F, K_b
# expression sha256: 4d4a973f03e6c55e733864f19a7dda5500fd46b66ed7aa38e692d054b1cdccb3 (of its srepr)
def _lambdifygenerated(delta_c, F, K_b):
    return F/K_b + delta_c
