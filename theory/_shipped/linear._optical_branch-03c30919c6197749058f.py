# ringchain generated code v1 sha256=2f1385453ac67e4a3a142b4c1207b656e1d88792274c4629e67c63bf653df30b
# derivation: linear._optical_branch
# source key: ceca10620e89af986038 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: q, F_0, K, n, m, a, K_b
# expression sha256: dcc8fe2096fa5bed8fd9a155ad084247551a68274fbabe767e7bd44f4a36373b (of its srepr)
def _lambdifygenerated(q, F_0, K, n, m, a, K_b):
    x0 = n**(-1.0)
    x1 = F_0**(1 - x0)*K**x0*n
    x2 = 2/m
    return numpy.sqrt(x2*(K_b + x1) + x2*numpy.sqrt(4*K_b*x1*numpy.cos((1/2)*a*q)**2 + (-K_b + x1)**2))
