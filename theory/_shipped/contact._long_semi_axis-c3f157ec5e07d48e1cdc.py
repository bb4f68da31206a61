# ringchain generated code v1 sha256=31eb493b7b01b9093d57d11958e3798bb33b4e96cf4f442757f960dd22c76be7
# derivation: contact._long_semi_axis
# source key: caeff341571871d5b69b (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: P, A, m_1, E, nu
# expression sha256: edf1cb73c517a3221638ee0790038c96b703b56a2db4a54d34e40680d75bd8f8 (of its srepr)
def _lambdifygenerated(P, A, m_1, E, nu):
    return P**(1/3)*(nu + 1)**(1/3)*scipy.special.elliprd(0, m_1, 1)**(1/3)/(numpy.pi**(1/3)*A**(1/3)*E**(1/3)*(-1/(nu - 1))**(1/3))
