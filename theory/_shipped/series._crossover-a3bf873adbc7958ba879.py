# ringchain generated code v1 sha256=7ea067bc485a7a8c2d8bb106312503bbd8f6e103bffb9d02566683be8bd67022
# derivation: series._crossover
# source key: 67895ff0807168ca9dd5 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: K_c, K_b
# expression sha256: 968e1c89b82bf7c74dc421ec67aa647d6f0bc94fbdb00f2c979a6439c735de69 (of its srepr)
def _lambdifygenerated(K_c, K_b):
    return numpy.exp(3*numpy.log(K_b) - 2*numpy.log(K_c))
