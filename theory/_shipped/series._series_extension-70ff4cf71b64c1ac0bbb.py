# ringchain generated code v1 sha256=83fae0a0f128047ff5ff0dcc5896058c37ea2105115441bfabe69ee1c2a59932
# derivation: series._series_extension
# source key: a22a0557fcec1bc1abe9 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: delta_c, F, K_b
# expression sha256: 4d4a973f03e6c55e733864f19a7dda5500fd46b66ed7aa38e692d054b1cdccb3 (of its srepr)
def _lambdifygenerated(delta_c, F, K_b):
    return F/K_b + delta_c
