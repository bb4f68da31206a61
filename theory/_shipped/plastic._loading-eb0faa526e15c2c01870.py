# ringchain generated code v1 sha256=c2a1b5e9f45a71a7883260b54738acab4805cef9477018b1b0069a0fcc3cc7d4
# derivation: plastic._loading
# source key: c0b268e8f55b26f011d3 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: delta, K_c, delta_y
# expression sha256: 829c8391ea97190d4556acc8f4b7d238188d1ff2b13e5ed6139d195aee3d7325 (of its srepr)
def _lambdifygenerated(delta, K_c, delta_y):
    x0 = K_c*numpy.sqrt(delta_y)
    return ((1/2)*x0*(3*delta - delta_y), (3/2)*x0,)
