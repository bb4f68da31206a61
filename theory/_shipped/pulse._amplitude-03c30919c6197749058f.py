# ringchain generated code v1 sha256=9f96539d8da4eca38880b18dc66d227a6a240d40bf888e16be9f48d46a3bd42a
# derivation: pulse._amplitude
# source key: ceca10620e89af986038 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: K, n, m_s
# expression sha256: 6c2868f97a9c6c881c222ab72fdc69560e9eafb0d5a7565bf894bd4b4e51a608 (of its srepr)
def _lambdifygenerated(K, n, m_s):
    x0 = n + 1
    x1 = x0**(-1.0)
    x2 = n*x1
    x3 = 2*n
    x4 = n/(x3 + 2)
    x5 = (x3 - 2)**(-1.0)
    x6 = 3*x5
    return (x1*numpy.log(K) + x2*numpy.log(m_s) + x2*numpy.log(n - 1) - x2*numpy.log(scipy.special.beta(n*x5 + x6, 1/2) + scipy.special.beta(n*x6 + x5, 1/2)) - x2*numpy.log(2) - x4*numpy.log(n) + x4*numpy.log(x0) + x4*numpy.log(6), x1*x3,)
