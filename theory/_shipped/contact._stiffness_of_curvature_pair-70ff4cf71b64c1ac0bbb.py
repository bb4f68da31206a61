# ringchain generated code v1 sha256=9e3446e8eb1c665f18766d5dad39163c58d49bdc0862420b9dfcaee83526b20f
# derivation: contact._stiffness_of_curvature_pair
# source key: a22a0557fcec1bc1abe9 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: A, E_1, nu_1, E_2, nu_2
# expression sha256: a7375f821857b142ce11533e579399e906fa653d1456e2febaaabc752046ecec (of its srepr)
def _lambdifygenerated(A, E_1, nu_1, E_2, nu_2):
    return -2/3*numpy.sqrt(2)*E_1*E_2/(numpy.sqrt(A)*(E_1*nu_2**2 - E_1 + E_2*nu_1**2 - E_2))
