# ringchain generated code v1 sha256=aae45a31c0da3fa4810d6a81f1a209f563272c907f634d069d00e97115e217bb
# derivation: contact._stiffness_of_curvature
# source key: caeff341571871d5b69b (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: A, E, nu
# expression sha256: abcf98825a2c2068bdbe744e62c52cc8bba54d77cb5ef6324781464f50b31407 (of its srepr)
def _lambdifygenerated(A, E, nu):
    return ((1/3)*numpy.sqrt(2)*E/((1 - nu)*(nu + 1)), 1/numpy.sqrt(A),)
