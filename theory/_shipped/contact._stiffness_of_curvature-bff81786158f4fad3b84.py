# ringchain generated code v1 sha256=0acf02e5e95a76612b8a3c324d0713c98e23965a35c0c553b767a4a22d6c3fa1
# derivation: contact._stiffness_of_curvature
# source key: 07201ab9dccdbac32795 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: A, E, nu
# expression sha256: abcf98825a2c2068bdbe744e62c52cc8bba54d77cb5ef6324781464f50b31407 (of its srepr)
def _lambdifygenerated(A, E, nu):
    return ((1/3)*numpy.sqrt(2)*E/((1 - nu)*(nu + 1)), 1/numpy.sqrt(A),)
