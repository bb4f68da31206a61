# ringchain generated code v1 sha256=1d698a2bc6f6db102d21eed7a5f566ea877ee81e52d8cf0187e3f9a19409a942
# derivation: plastic._largest
# source key: ceca10620e89af986038 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: delta_m, K_c, delta_y
# expression sha256: 80a2a998b0b7caada7cf76a1e0f390cd36db311a63cf75f8b102f8b578c0aede (of its srepr)
def _lambdifygenerated(delta_m, K_c, delta_y):
    x0 = numpy.sqrt(delta_m)
    x1 = numpy.sqrt(delta_y)
    x2 = (1/2)*x1/x0
    return ((x0 - x1)**2*(x2 + 1), x2*(3*delta_m - delta_y), (1/20)*K_c*x1*(15*delta_m**2 - 10*delta_m*delta_y + 3*delta_y**2),)
