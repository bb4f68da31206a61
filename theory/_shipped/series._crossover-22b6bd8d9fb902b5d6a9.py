# ringchain generated code v1 sha256=6e553187aa798340633a83d36ecfc8ff1995fb176728325414313014c1f02355
# derivation: series._crossover
# source key: 0881d513a06819d2e367 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: K_c, K_b
# expression sha256: 968e1c89b82bf7c74dc421ec67aa647d6f0bc94fbdb00f2c979a6439c735de69 (of its srepr)
def _lambdifygenerated(K_c, K_b):
    return numpy.exp(3*numpy.log(K_b) - 2*numpy.log(K_c))
