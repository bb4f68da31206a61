# ringchain generated code v1 sha256=b2fd90f8051696233eddaeb84d1b5e17808ab82080cc824f734143458d2b1cf8
# derivation: contact._long_semi_axis
# source key: 67895ff0807168ca9dd5 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: P, A, m_1, E, nu
# expression sha256: edf1cb73c517a3221638ee0790038c96b703b56a2db4a54d34e40680d75bd8f8 (of its srepr)
def _lambdifygenerated(P, A, m_1, E, nu):
    return P**(1/3)*(nu + 1)**(1/3)*scipy.special.elliprd(0, m_1, 1)**(1/3)/(numpy.pi**(1/3)*A**(1/3)*E**(1/3)*(-1/(nu - 1))**(1/3))
