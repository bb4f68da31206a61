# ringchain generated code v1 sha256=81ab042cb7a92ec10bc6fa10ec3dff07987b931c052239a20696319313880132
# derivation: sheet._triangular_matrix
# source key: ceca10620e89af986038 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: q_x, q_y, m, k_1, k_2, k_3, T_1, T_2, T_3, a
# expression sha256: 4824758aaed15441e6fa853dbae8b36c27316804c336abc170dc9250900f65c6 (of its srepr)
def _lambdifygenerated(q_x, q_y, m, k_1, k_2, k_3, T_1, T_2, T_3, a):
    x0 = m**(-1.0)
    x1 = a*q_x
    x2 = 4*x0*numpy.sin((1/2)*x1)**2
    x3 = a*k_2
    x4 = (1/4)*x1
    x5 = numpy.sqrt(3)
    x6 = (1/4)*a*q_y*x5
    x7 = a**(-1.0)
    x8 = x0*x7
    x9 = x8*numpy.sin(x4 + x6)**2
    x10 = a*k_3
    x11 = x8*numpy.sin(x4 - x6)**2
    return (k_1*x2 + x11*(3*T_3 + x10) + x9*(3*T_2 + x3), T_1*x2*x7 + x11*(T_3 + 3*x10) + x9*(T_2 + 3*x3), -x11*x5*(-T_3 + a*k_3) + x5*x9*(-T_2 + a*k_2))
