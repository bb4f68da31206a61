# ringchain generated code v1 sha256=668ea97a0425e1976f1eeba467247b956a001cac0d77f29f26648ee4feace3d9
# derivation: series._crossover
# source key: f3be020559998432f519 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: K_c, K_b
# expression sha256: 968e1c89b82bf7c74dc421ec67aa647d6f0bc94fbdb00f2c979a6439c735de69 (of its srepr)
def _lambdifygenerated(K_c, K_b):
    return numpy.exp(3*numpy.log(K_b) - 2*numpy.log(K_c))
