# ringchain generated code v1 sha256=ac7217a636faeed10af40e81034f012505a34978d642061ac1f7503166d9dc1a
# derivation: series._series_extension
# source key: c0b268e8f55b26f011d3 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: delta_c, F, K_b
# expression sha256: 4d4a973f03e6c55e733864f19a7dda5500fd46b66ed7aa38e692d054b1cdccb3 (of its srepr)
def _lambdifygenerated(delta_c, F, K_b):
    return F/K_b + delta_c
