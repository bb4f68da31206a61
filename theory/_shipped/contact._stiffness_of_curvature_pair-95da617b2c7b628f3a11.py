# ringchain generated code v1 sha256=6d291b3b1a0d3aebff858937d51497e905668ec672d519518ceccea883ec6ee9
# derivation: contact._stiffness_of_curvature_pair
# source key: f3be020559998432f519 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: A, E_1, nu_1, E_2, nu_2
# expression sha256: a7375f821857b142ce11533e579399e906fa653d1456e2febaaabc752046ecec (of its srepr)
def _lambdifygenerated(A, E_1, nu_1, E_2, nu_2):
    return -2/3*numpy.sqrt(2)*E_1*E_2/(numpy.sqrt(A)*(E_1*nu_2**2 - E_1 + E_2*nu_1**2 - E_2))
