# ringchain generated code v1 sha256=4da1f7848f6ad1a0b1e4c9d79462b2eda5b94bb2372390b86011144639693f84
# derivation: pulse._energy
# source key: ceca10620e89af986038 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: K, n
# expression sha256: b80991f9e0febd749f67f58efaf794b45a14cb4af56042fbd07ed552c28d77da (of its srepr)
def _lambdifygenerated(K, n):
    x0 = n + 1
    x1 = n**(-1.0)
    x2 = (2*n - 2)**(-1.0)
    x3 = 3*x2
    return (-x1*numpy.log(K) + (1/2)*numpy.log(n) - 1/2*numpy.log(x0) - numpy.log(n - 1) + numpy.log((1/6)*scipy.special.beta(n*x2 + x3, 1/2) + (1/6)*scipy.special.beta(n*x3 + x2, 1/2)) + (1/2)*numpy.log(6), x0*x1,)
