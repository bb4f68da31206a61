# ringchain generated code v1 sha256=3441abe07aaadc96c6eddc84e40b9814aa7b881b09fbe181804ace4a709f4d42
# derivation: attenuation._travel_time
# source key: ceca10620e89af986038 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: x, V_0, n, \ell
# expression sha256: 947ef29bb8930f530ff6ce6fd3b7fd1fc57a9cc4136797bc981d52998ed515c6 (of its srepr)
def _lambdifygenerated(x, V_0, n, _dummy_0):
    x0 = n - 1
    x1 = (1/2)*x
    x2 = 2/(V_0*x0)
    return (_dummy_0*n*x2*numpy.expm1(x0*x1/(_dummy_0*n)), x2*(n*x1 - x1))
