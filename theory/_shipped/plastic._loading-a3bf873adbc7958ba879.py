# ringchain generated code v1 sha256=183d606c9faad3589a6e7ad85a2cf0a2fc2af587eea2f1a8d89d6d7d50cb2b77
# derivation: plastic._loading
# source key: 67895ff0807168ca9dd5 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: delta, K_c, delta_y
# expression sha256: 829c8391ea97190d4556acc8f4b7d238188d1ff2b13e5ed6139d195aee3d7325 (of its srepr)
def _lambdifygenerated(delta, K_c, delta_y):
    x0 = K_c*numpy.sqrt(delta_y)
    return ((1/2)*x0*(3*delta - delta_y), (3/2)*x0,)
