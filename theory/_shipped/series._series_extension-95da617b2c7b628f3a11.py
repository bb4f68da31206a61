# ringchain generated code v1 sha256=e44a2b53652600872584c1d39113e6f63eb935f1f14c08685ecea970551b1d42
# derivation: series._series_extension
# source key: f3be020559998432f519 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: delta_c, F, K_b
# expression sha256: 4d4a973f03e6c55e733864f19a7dda5500fd46b66ed7aa38e692d054b1cdccb3 (of its srepr)
def _lambdifygenerated(delta_c, F, K_b):
    return F/K_b + delta_c
