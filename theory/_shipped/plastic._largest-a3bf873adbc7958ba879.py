# ringchain generated code v1 sha256=38a61291fb4c14f85b78092452737d3fe2ba2af8615982befdce4b3c2fbe098d
# derivation: plastic._largest
# source key: 67895ff0807168ca9dd5 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: delta_m, K_c, delta_y
# expression sha256: 80a2a998b0b7caada7cf76a1e0f390cd36db311a63cf75f8b102f8b578c0aede (of its srepr)
def _lambdifygenerated(delta_m, K_c, delta_y):
    x0 = numpy.sqrt(delta_m)
    x1 = numpy.sqrt(delta_y)
    x2 = (1/2)*x1/x0
    return ((x0 - x1)**2*(x2 + 1), x2*(3*delta_m - delta_y), (1/20)*K_c*x1*(15*delta_m**2 - 10*delta_m*delta_y + 3*delta_y**2),)
