# ringchain generated code v1 sha256=e832c77bce47c92cc2dbfdb8ce7fc2f78ff948813c9f61e23df0c46cb7dfaa5d
# derivation: contact._stiffness_of_curvature
# source key: 317867d47b5755454417 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: A, E, nu
# expression sha256: abcf98825a2c2068bdbe744e62c52cc8bba54d77cb5ef6324781464f50b31407 (of its srepr)
def _lambdifygenerated(A, E, nu):
    return ((1/3)*numpy.sqrt(2)*E/((1 - nu)*(nu + 1)), 1/numpy.sqrt(A),)
