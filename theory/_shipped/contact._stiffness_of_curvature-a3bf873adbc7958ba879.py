# ringchain generated code v1 sha256=760edc05f720135af15d1b6aa59e54cafcfcda8a3d611cecd3e9ba2afe639385
# derivation: contact._stiffness_of_curvature
# source key: 67895ff0807168ca9dd5 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: A, E, nu
# expression sha256: abcf98825a2c2068bdbe744e62c52cc8bba54d77cb5ef6324781464f50b31407 (of its srepr)
def _lambdifygenerated(A, E, nu):
    return ((1/3)*numpy.sqrt(2)*E/((1 - nu)*(nu + 1)), 1/numpy.sqrt(A),)
