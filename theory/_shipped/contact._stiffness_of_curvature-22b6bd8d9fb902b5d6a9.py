# ringchain generated code v1 sha256=72c9663249257b2bd17882083507d95e06fabeffa8fe482c7efa3ea92bd4e204
# derivation: contact._stiffness_of_curvature
# source key: 0881d513a06819d2e367 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: A, E, nu
# expression sha256: abcf98825a2c2068bdbe744e62c52cc8bba54d77cb5ef6324781464f50b31407 (of its srepr)
def _lambdifygenerated(A, E, nu):
    return ((1/3)*numpy.sqrt(2)*E/((1 - nu)*(nu + 1)), 1/numpy.sqrt(A),)
