# ringchain generated code v1 sha256=037452a6f2262d3dc280d1e7e5a31cc19166006e708c84c99f302d2f67f46b60
# derivation: rigid._moments
# source key: ceca10620e89af986038 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: R, r, m
# expression sha256: 37cf7913a9cd3a90009f34e5b85d707a02a3091d9afa6656ca353276f703f102 (of its srepr)
def _lambdifygenerated(R, r, m):
    x0 = 4*R**2
    x1 = r**2
    return ((1/8)*m*(x0 + 5*x1), (1/4)*m*(x0 + 3*x1),)
