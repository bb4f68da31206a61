# ringchain generated code v1 sha256=10b03f249359edaa0861b8157f8ee44ac4e3b32a617c15ca3911ab60512e8680
# derivation: plastic._largest
# source key: 263ab3517922b3fc21eb (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: delta_m, K_c, delta_y
# expression sha256: 80a2a998b0b7caada7cf76a1e0f390cd36db311a63cf75f8b102f8b578c0aede (of its srepr)
def _lambdifygenerated(delta_m, K_c, delta_y):
    x0 = numpy.sqrt(delta_m)
    x1 = numpy.sqrt(delta_y)
    x2 = (1/2)*x1/x0
    return ((x0 - x1)**2*(x2 + 1), x2*(3*delta_m - delta_y), (1/20)*K_c*x1*(15*delta_m**2 - 10*delta_m*delta_y + 3*delta_y**2),)
