# ringchain generated code v1 sha256=807f767a099fe2ec99d3a2751beaaff379da274c0f84211a142846481c13ee2f
# derivation: rigid._moments
# source key: 67895ff0807168ca9dd5 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: R, r, m
# expression sha256: 37cf7913a9cd3a90009f34e5b85d707a02a3091d9afa6656ca353276f703f102 (of its srepr)
def _lambdifygenerated(R, r, m):
    x0 = 4*R**2
    x1 = r**2
    return ((1/8)*m*(x0 + 5*x1), (1/4)*m*(x0 + 3*x1),)
