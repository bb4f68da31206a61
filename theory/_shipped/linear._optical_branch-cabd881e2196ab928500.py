# ringchain generated code v1 sha256=5af72835b99898522e731f7a2e1c27f41200eb9f61612f36a775f55b5629a638
# derivation: linear._optical_branch
# source key: 317867d47b5755454417 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: q, F_0, K, n, m, a, K_b
# expression sha256: dcc8fe2096fa5bed8fd9a155ad084247551a68274fbabe767e7bd44f4a36373b (of its srepr)
def _lambdifygenerated(q, F_0, K, n, m, a, K_b):
    x0 = n**(-1.0)
    x1 = F_0**(1 - x0)*K**x0*n
    x2 = 2/m
    return numpy.sqrt(x2*(K_b + x1) + x2*numpy.sqrt(4*K_b*x1*numpy.cos((1/2)*a*q)**2 + (-K_b + x1)**2))
