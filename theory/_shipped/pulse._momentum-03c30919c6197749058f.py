# ringchain generated code v1 sha256=8c94a3e5e15f0a349aee2eef55d51d4f298313c27fa21dcc0db87c070db611ae
# derivation: pulse._momentum
# source key: ceca10620e89af986038 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: K, n, m
# expression sha256: 3e769b8e195b603d62f0e8314f7eb3bf552c6bf93fe039152757f6a6965e52e7 (of its srepr)
def _lambdifygenerated(K, n, m):
    x0 = (1/2)/n
    x1 = (2*n - 2)**(-1.0)
    return (-x0*numpy.log(K) + (1/2)*numpy.log(m) + (1/2)*numpy.log(n) - numpy.log(n - 1) + numpy.log(scipy.special.beta(n*x1 + x1, 1/2)) - 1/2*numpy.log(3), x0*(n + 1),)
