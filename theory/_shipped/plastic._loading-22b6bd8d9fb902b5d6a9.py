# ringchain generated code v1 sha256=610ab80668f430e83b2e078a0ef5755c6879df454d81be73b3d3590ba9176242
# derivation: plastic._loading
# source key: 0881d513a06819d2e367 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: delta, K_c, delta_y
# expression sha256: 829c8391ea97190d4556acc8f4b7d238188d1ff2b13e5ed6139d195aee3d7325 (of its srepr)
def _lambdifygenerated(delta, K_c, delta_y):
    x0 = K_c*numpy.sqrt(delta_y)
    return ((1/2)*x0*(3*delta - delta_y), (3/2)*x0,)
