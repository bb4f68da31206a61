# ringchain generated code v1 sha256=346ebf10a342f664a79b8a6578cfa90f86f35edd4c04ea4b3b150b03e246ca8f
# derivation: series._crossover
# source key: c0b268e8f55b26f011d3 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: K_c, K_b
# expression sha256: 968e1c89b82bf7c74dc421ec67aa647d6f0bc94fbdb00f2c979a6439c735de69 (of its srepr)
def _lambdifygenerated(K_c, K_b):
    return numpy.exp(3*numpy.log(K_b) - 2*numpy.log(K_c))
