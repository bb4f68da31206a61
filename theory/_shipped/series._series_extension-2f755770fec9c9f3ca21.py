# ringchain generated code v1 sha256=3acdbbb2cfa6f0cf57840cb8c5982cc335be3eca0f6573d71c54ad5a4bed9969
# derivation: series._series_extension
# source key: 0d3b9b67499038ff2889 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: delta_c, F, K_b
# expression sha256: 4d4a973f03e6c55e733864f19a7dda5500fd46b66ed7aa38e692d054b1cdccb3 (of its srepr)
def _lambdifygenerated(delta_c, F, K_b):
    return F/K_b + delta_c
