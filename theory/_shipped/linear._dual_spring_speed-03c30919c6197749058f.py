# ringchain generated code v1 sha256=4e3e3bfebaebbc60f2a69ce1d58cdd50e9a432bc22af3ccf6358e1447d64771d
# derivation: linear._dual_spring_speed
# source key: ceca10620e89af986038 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: F_0, K, n, m, a, K_b
# expression sha256: 93298b4af6d4a82d60a9d49f92f9749ef25235fb99dde6c3b3ac13ce2945cbcd (of its srepr)
def _lambdifygenerated(F_0, K, n, m, a, K_b):
    x0 = n**(-1.0)
    x1 = (1/2)*x0
    return F_0**(1/2 - x1)*K**x1*numpy.sqrt(K_b)*a*numpy.sqrt(n)/(numpy.sqrt(m)*numpy.sqrt(F_0**(1 - x0)*K**x0*n + K_b))
