# ringchain generated code v1 sha256=ab975d090fb0db453b3f98dfa52f5ab6fe613863ec8a3c9843af56f2cbf8ac5b
# derivation: contact._stiffness_of_curvature
# source key: c0b268e8f55b26f011d3 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: A, E, nu
# expression sha256: abcf98825a2c2068bdbe744e62c52cc8bba54d77cb5ef6324781464f50b31407 (of its srepr)
def _lambdifygenerated(A, E, nu):
    return ((1/3)*numpy.sqrt(2)*E/((1 - nu)*(nu + 1)), 1/numpy.sqrt(A),)
