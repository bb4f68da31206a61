# ringchain generated code v1 sha256=00b505a3a74d9590be0b13c582581a248c96b0e4f4c3822ef91ba19663ca91fe
# derivation: sheet._square_gradient
# source key: ceca10620e89af986038 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: q_x, q_y, m, k_x, k_y, T_x, T_y, a_x, a_y
# expression sha256: 5f5d3aaec8f88aacf7bb5043918e9278414aa2b0f5959a3678a927fc8b09fd3b (of its srepr)
def _lambdifygenerated(q_x, q_y, m, k_x, k_y, T_x, T_y, a_x, a_y):
    x0 = (1/2)*a_x*q_x
    x1 = 4/m
    x2 = x1*numpy.sin(x0)*numpy.cos(x0)
    x3 = (1/2)*a_y*q_y
    x4 = x1*numpy.sin(x3)*numpy.cos(x3)
    return (a_x*k_x*x2, T_x*x2, 0, T_y*x4, a_y*k_y*x4, 0)
