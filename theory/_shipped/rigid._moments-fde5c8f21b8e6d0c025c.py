# ringchain generated code v1 sha256=e61b9a8c25bcfe1670aaed30e57911ae882b2116aba8af181bc31a58b2b68d32
# derivation: rigid._moments
# source key: 263ab3517922b3fc21eb (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: R, r, m
# expression sha256: 37cf7913a9cd3a90009f34e5b85d707a02a3091d9afa6656ca353276f703f102 (of its srepr)
def _lambdifygenerated(R, r, m):
    x0 = 4*R**2
    x1 = r**2
    return ((1/8)*m*(x0 + 5*x1), (1/4)*m*(x0 + 3*x1),)
