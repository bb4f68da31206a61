# ringchain generated code v1 sha256=f2dab944839b85fe0b7abcea32464b9b88c0b8ffa5d9cda6940f2ed2610410a9
# derivation: linear._power_law_branch
# source key: a22a0557fcec1bc1abe9 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: q, F_0, K, n, m, a
# expression sha256: 25e0a9ef749ce9e63125d263320ffb62353a28fd1d4183b6ab582163aeeeb5b6 (of its srepr)
def _lambdifygenerated(q, F_0, K, n, m, a):
    x0 = (1/2)/n
    return 2*F_0**(1/2 - x0)*K**x0*numpy.sqrt(n)*abs(numpy.sin((1/2)*a*q))/numpy.sqrt(m)
