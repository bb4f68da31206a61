# ringchain generated code v1 sha256=7d08b905aa69b84aa76ff9b99288c9896c91cb502efc39228e2bebec5dd22a29
# derivation: contact._long_semi_axis
# source key: ceca10620e89af986038 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: P, A, m_1, E, nu
# expression sha256: edf1cb73c517a3221638ee0790038c96b703b56a2db4a54d34e40680d75bd8f8 (of its srepr)
def _lambdifygenerated(P, A, m_1, E, nu):
    return P**(1/3)*(nu + 1)**(1/3)*scipy.special.elliprd(0, m_1, 1)**(1/3)/(numpy.pi**(1/3)*A**(1/3)*E**(1/3)*(-1/(nu - 1))**(1/3))
