# ringchain generated code v1 sha256=e7df503f7dffc2c378240dab102c59874f139d7df45abdac371f99184a83ccce
# derivation: linear._optical_branch
# source key: a22a0557fcec1bc1abe9 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: q, F_0, K, n, m, a, K_b
# expression sha256: dcc8fe2096fa5bed8fd9a155ad084247551a68274fbabe767e7bd44f4a36373b (of its srepr)
def _lambdifygenerated(q, F_0, K, n, m, a, K_b):
    x0 = n**(-1.0)
    x1 = F_0**(1 - x0)*K**x0*n
    x2 = 2/m
    return numpy.sqrt(x2*(K_b + x1) + x2*numpy.sqrt(4*K_b*x1*numpy.cos((1/2)*a*q)**2 + (-K_b + x1)**2))
