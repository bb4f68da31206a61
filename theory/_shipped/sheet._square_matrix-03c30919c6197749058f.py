# ringchain generated code v1 sha256=870cf4b36cd1aede2dc8317d74575f464cd5a0b66bf6619ec051f607e1a6850e
# derivation: sheet._square_matrix
# source key: ceca10620e89af986038 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: q_x, q_y, m, k_x, k_y, T_x, T_y, a_x, a_y
# expression sha256: 52c958d74e707d66ea53a7a69dd01629bfd092b4dfa492f549cc473a609b2054 (of its srepr)
def _lambdifygenerated(q_x, q_y, m, k_x, k_y, T_x, T_y, a_x, a_y):
    x0 = 4/m
    x1 = x0*numpy.sin((1/2)*a_x*q_x)**2
    x2 = x0*numpy.sin((1/2)*a_y*q_y)**2
    return (T_y*x2/a_y + k_x*x1, T_x*x1/a_x + k_y*x2, 0)
