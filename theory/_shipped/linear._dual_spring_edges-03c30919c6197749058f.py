# ringchain generated code v1 sha256=d070d5704f799bc19f92ac87011528a53358d89812a0cd97b3c3a3b4b0d5e7df
# derivation: linear._dual_spring_edges
# source key: ceca10620e89af986038 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: F_0, K, n, m, K_b
# expression sha256: a2c231809b9ba0d9a05a6a3e2de5ae4fe4f51bb37e8c94845638f5475b39710e (of its srepr)
def _lambdifygenerated(F_0, K, n, m, K_b):
    x0 = n**(-1.0)
    x1 = (1/2)*x0
    x2 = F_0**(1 - x0)*K**x0*n
    x3 = K_b + x2
    x4 = numpy.sqrt(x3 + abs(K_b - x2))
    x5 = 1/numpy.sqrt(m)
    x6 = numpy.sqrt(2)*x5
    return (2*F_0**(1/2 - x1)*K**x1*numpy.sqrt(K_b)*numpy.sqrt(n)*x6/x4, x4*x6, 2*numpy.sqrt(x3)*x5)
