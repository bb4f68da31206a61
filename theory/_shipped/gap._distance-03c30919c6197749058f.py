# ringchain generated code v1 sha256=302977381eb325bfb510dff8f6a1cbc6f00f7e3bd1f819e96f3fe1eb0f98a379
# derivation: gap._distance
# source key: ceca10620e89af986038 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: X, Y, Z, R, r
# expression sha256: 98f0579fc57382960da2b753c834854e1392d8cb5a043c3ab50b8dd7a5905e21 (of its srepr)
def _lambdifygenerated(X, Y, Z, R, r):
    x0 = numpy.sqrt(X**2 + Z**2)
    x1 = -R + x0
    x2 = numpy.sqrt(Y**2 + x1**2)
    x3 = x2**(-1.0)
    x4 = x1*x3/x0
    return (-r + x2, X*x4, Y*x3, Z*x4,)
