# ringchain generated code v1 sha256=9d1245fa900aa2c002774bc4356e3e95fa1ca65432b7e05efe641e11715c66b5
# derivation: sheet._triangular_gradient
# source key: ceca10620e89af986038 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: q_x, q_y, m, k_1, k_2, k_3, T_1, T_2, T_3, a
# expression sha256: 69928ecd637dffb3b10710c12ecdc3429708a3910405aa0a998850fd52fc99cb (of its srepr)
def _lambdifygenerated(q_x, q_y, m, k_1, k_2, k_3, T_1, T_2, T_3, a):
    x0 = m**(-1.0)
    x1 = a*q_x
    x2 = (1/2)*x1
    x3 = 4*x0*numpy.sin(x2)*numpy.cos(x2)
    x4 = a*k_2
    x5 = (1/2)*x0
    x6 = (1/4)*x1
    x7 = numpy.sqrt(3)
    x8 = (1/4)*a*q_y*x7
    x9 = x6 + x8
    x10 = numpy.sin(x9)*numpy.cos(x9)
    x11 = x10*x5
    x12 = x11*(3*T_2 + x4)
    x13 = a*k_3
    x14 = x6 - x8
    x15 = numpy.sin(x14)*numpy.cos(x14)
    x16 = x15*x5
    x17 = x16*(3*T_3 + x13)
    x18 = x11*(T_2 + 3*x4)
    x19 = x16*(T_3 + 3*x13)
    x20 = -T_2 + a*k_2
    x21 = -T_3 + a*k_3
    x22 = (3/2)*x0
    return (a*k_1*x3 + x12 + x17, T_1*x3 + x18 + x19, x11*x20*x7 - x16*x21*x7, x12*x7 - x17*x7, x18*x7 - x19*x7, x10*x20*x22 + x15*x21*x22)
