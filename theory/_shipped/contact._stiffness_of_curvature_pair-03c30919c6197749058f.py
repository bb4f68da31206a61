# ringchain generated code v1 sha256=bcd69c1433570fa176a7a13b28237972fdadf65cb8fdedd310df207f60cf6d65
# derivation: contact._stiffness_of_curvature_pair
# source key: ceca10620e89af986038 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: A, E_1, nu_1, E_2, nu_2
# expression sha256: a7375f821857b142ce11533e579399e906fa653d1456e2febaaabc752046ecec (of its srepr)
def _lambdifygenerated(A, E_1, nu_1, E_2, nu_2):
    return -2/3*numpy.sqrt(2)*E_1*E_2/(numpy.sqrt(A)*(E_1*nu_2**2 - E_1 + E_2*nu_1**2 - E_2))
