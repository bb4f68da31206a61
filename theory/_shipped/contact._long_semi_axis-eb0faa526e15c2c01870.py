# ringchain generated code v1 sha256=e977607acda19000cbe088a5629103d1f438285fff320b4b06a799b84c368811
# derivation: contact._long_semi_axis
# source key: c0b268e8f55b26f011d3 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: P, A, m_1, E, nu
# expression sha256: edf1cb73c517a3221638ee0790038c96b703b56a2db4a54d34e40680d75bd8f8 (of its srepr)
def _lambdifygenerated(P, A, m_1, E, nu):
    return P**(1/3)*(nu + 1)**(1/3)*scipy.special.elliprd(0, m_1, 1)**(1/3)/(numpy.pi**(1/3)*A**(1/3)*E**(1/3)*(-1/(nu - 1))**(1/3))
