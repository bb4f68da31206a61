# ringchain generated code v1 sha256=3075317a32a9ae45ba555a4c69db4fe9864b562860085b2a5bba5121ba8da492
# derivation: contact._long_semi_axis
# source key: a22a0557fcec1bc1abe9 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: P, A, m_1, E, nu
# expression sha256: edf1cb73c517a3221638ee0790038c96b703b56a2db4a54d34e40680d75bd8f8 (of its srepr)
def _lambdifygenerated(P, A, m_1, E, nu):
    return P**(1/3)*(nu + 1)**(1/3)*scipy.special.elliprd(0, m_1, 1)**(1/3)/(numpy.pi**(1/3)*A**(1/3)*E**(1/3)*(-1/(nu - 1))**(1/3))
