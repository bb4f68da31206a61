# ringchain generated code v1 sha256=de7b835bc7319bfb80b7841842d5290e1a1586d4b3bba759619f160d2858ce4a
# derivation: contact._stiffness_of_curvature
# source key: f3be020559998432f519 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: A, E, nu
# expression sha256: abcf98825a2c2068bdbe744e62c52cc8bba54d77cb5ef6324781464f50b31407 (of its srepr)
def _lambdifygenerated(A, E, nu):
    return ((1/3)*numpy.sqrt(2)*E/((1 - nu)*(nu + 1)), 1/numpy.sqrt(A),)
