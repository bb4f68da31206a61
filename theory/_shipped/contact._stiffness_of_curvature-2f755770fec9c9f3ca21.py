# ringchain generated code v1 sha256=386d94299575705367e4d13a61694daf40e29a1b4f2f8d734aa66fc3f3ac0e9d
# derivation: contact._stiffness_of_curvature
# source key: 0d3b9b67499038ff2889 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: A, E, nu
# expression sha256: abcf98825a2c2068bdbe744e62c52cc8bba54d77cb5ef6324781464f50b31407 (of its srepr)
def _lambdifygenerated(A, E, nu):
    return ((1/3)*numpy.sqrt(2)*E/((1 - nu)*(nu + 1)), 1/numpy.sqrt(A),)
