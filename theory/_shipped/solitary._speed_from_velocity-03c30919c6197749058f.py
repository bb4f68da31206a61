# ringchain generated code v1 sha256=c8a3f1816eaa329f730fe9e45c492e2cf9e582f4f37bf4b5d4aa4b4e48968672
# derivation: solitary._speed_from_velocity
# source key: ceca10620e89af986038 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: K, n, a, m
# expression sha256: ba28673b9a469812914114dc58d7631f90d2bb49b7868cddb4b18ec23cb45533 (of its srepr)
def _lambdifygenerated(K, n, a, m):
    x0 = n + 1
    x1 = x0**(-1.0)
    return (x1*numpy.log(K) - x1*numpy.log(m) - x1*numpy.log(x0) + x1*numpy.log(2) + numpy.log(a), x1*(n - 1),)
