# ringchain generated code v1 sha256=586889bbcec3c2dce5b7d3102e59c59cb7602cf725a3193451d27c98f8298bbc
# derivation: series._crossover
# source key: caeff341571871d5b69b (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: K_c, K_b
# expression sha256: 968e1c89b82bf7c74dc421ec67aa647d6f0bc94fbdb00f2c979a6439c735de69 (of its srepr)
def _lambdifygenerated(K_c, K_b):
    return numpy.exp(3*numpy.log(K_b) - 2*numpy.log(K_c))
