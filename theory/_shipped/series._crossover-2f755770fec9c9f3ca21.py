# ringchain generated code v1 sha256=e4c04c9a1fa665f8799321196107c719ba6d002fe575380b5962971c5ebb481e
# derivation: series._crossover
# source key: 0d3b9b67499038ff2889 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: K_c, K_b
# expression sha256: 968e1c89b82bf7c74dc421ec67aa647d6f0bc94fbdb00f2c979a6439c735de69 (of its srepr)
def _lambdifygenerated(K_c, K_b):
    return numpy.exp(3*numpy.log(K_b) - 2*numpy.log(K_c))
