# ringchain generated code v1 sha256=b7ab1272fb05bb44b2d466a4fcb4fa8c65b4ba36e644524bd85ebf73e17a70b6
# derivation: series._series_extension
# source key: aaa6be78b00d30412b2b (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: delta_c, F, K_b
# expression sha256: 4d4a973f03e6c55e733864f19a7dda5500fd46b66ed7aa38e692d054b1cdccb3 (of its srepr)
def _lambdifygenerated(delta_c, F, K_b):
    return F/K_b + delta_c
