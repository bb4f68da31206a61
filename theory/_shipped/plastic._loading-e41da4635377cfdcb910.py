# ringchain generated code v1 sha256=2cc7c096932ffe81d7a5ece4a2c8d90d3618761029d5b2f82ce65f4684e6ddf3
# derivation: plastic._loading
# source key: aaa6be78b00d30412b2b (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: delta, K_c, delta_y
# expression sha256: 829c8391ea97190d4556acc8f4b7d238188d1ff2b13e5ed6139d195aee3d7325 (of its srepr)
def _lambdifygenerated(delta, K_c, delta_y):
    x0 = K_c*numpy.sqrt(delta_y)
    return ((1/2)*x0*(3*delta - delta_y), (3/2)*x0,)
