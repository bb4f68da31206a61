# ringchain generated code v1 sha256=8df1e2b1a6bf6f7ba74e7d80d2d230a629f9722707a1fb0369df10612fbfb3a8
# derivation: linear._dual_spring_speed
# source key: c0b268e8f55b26f011d3 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: F_0, K, n, m, a, K_b
# expression sha256: 93298b4af6d4a82d60a9d49f92f9749ef25235fb99dde6c3b3ac13ce2945cbcd (of its srepr)
def _lambdifygenerated(F_0, K, n, m, a, K_b):
    x0 = n**(-1.0)
    x1 = (1/2)*x0
    return F_0**(1/2 - x1)*K**x1*numpy.sqrt(K_b)*a*numpy.sqrt(n)/(numpy.sqrt(m)*numpy.sqrt(F_0**(1 - x0)*K**x0*n + K_b))
