# ringchain generated code v1 sha256=5f0d14a056e531dc93012d06568a1082148fbcb83d4c4681a86ab1dc6bcbc4d8
# derivation: gap._distance
# source key: 67895ff0807168ca9dd5 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: X, Y, Z, R, r
# expression sha256: 98f0579fc57382960da2b753c834854e1392d8cb5a043c3ab50b8dd7a5905e21 (of its srepr)
def _lambdifygenerated(X, Y, Z, R, r):
    x0 = numpy.sqrt(X**2 + Z**2)
    x1 = -R + x0
    x2 = numpy.sqrt(Y**2 + x1**2)
    x3 = x2**(-1.0)
    x4 = x1*x3/x0
    return (-r + x2, X*x4, Y*x3, Z*x4,)
