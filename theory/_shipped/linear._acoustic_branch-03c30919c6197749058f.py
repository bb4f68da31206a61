# ringchain generated code v1 sha256=2944eaa6c971935750bef6e157e55ac41721f5722976ce92e98acee05047aa35
# derivation: linear._acoustic_branch
# source key: ceca10620e89af986038 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: q, F_0, K, n, m, a, K_b
# expression sha256: c2745764048b008cacfb4595639c14f1f257f0d7eacf46959cb97c1be045c5be (of its srepr)
def _lambdifygenerated(q, F_0, K, n, m, a, K_b):
    x0 = m**(-1.0)
    x1 = (1/2)*a*q
    x2 = n**(-1.0)
    x3 = (1/2)*x2
    x4 = F_0**(1 - x2)*K**x2*n
    x5 = 2*x0
    return 4*F_0**(1/2 - x3)*K**x3*numpy.sqrt(K_b)*numpy.sqrt(n)*x0*abs(numpy.sin(x1))/numpy.sqrt(x5*(K_b + x4) + x5*numpy.sqrt(4*K_b*x4*numpy.cos(x1)**2 + (-K_b + x4)**2))
