# ringchain generated code v1 sha256=99626f4e702234040245723cbc76678f0413271b45a0b473f6f0c9e3e66be856
# derivation: plastic._loading
# source key: ceca10620e89af986038 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: delta, K_c, delta_y
# expression sha256: 829c8391ea97190d4556acc8f4b7d238188d1ff2b13e5ed6139d195aee3d7325 (of its srepr)
def _lambdifygenerated(delta, K_c, delta_y):
    x0 = K_c*numpy.sqrt(delta_y)
    return ((1/2)*x0*(3*delta - delta_y), (3/2)*x0,)
