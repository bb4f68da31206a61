# ringchain generated code v1 sha256=123578ea0b10d04e9ee01224f427585a09af139df4bd5e8374fda61282a1862d
# derivation: linear._power_law_branch
# source key: ceca10620e89af986038 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: q, F_0, K, n, m, a
# expression sha256: 25e0a9ef749ce9e63125d263320ffb62353a28fd1d4183b6ab582163aeeeb5b6 (of its srepr)
def _lambdifygenerated(q, F_0, K, n, m, a):
    x0 = (1/2)/n
    return 2*F_0**(1/2 - x0)*K**x0*numpy.sqrt(n)*abs(numpy.sin((1/2)*a*q))/numpy.sqrt(m)
