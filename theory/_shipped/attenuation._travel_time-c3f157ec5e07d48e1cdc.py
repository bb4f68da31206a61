# ringchain generated code v1 sha256=a6f6e95468c22abc4fd89d05440ee17ed1e76e19abd4cb199b119804561bbae9
# derivation: attenuation._travel_time
# source key: caeff341571871d5b69b (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: x, V_0, n, \ell
# expression sha256: 947ef29bb8930f530ff6ce6fd3b7fd1fc57a9cc4136797bc981d52998ed515c6 (of its srepr)
def _lambdifygenerated(x, V_0, n, _dummy_0):
    x0 = n - 1
    x1 = (1/2)*x
    x2 = 2/(V_0*x0)
    return (_dummy_0*n*x2*numpy.expm1(x0*x1/(_dummy_0*n)), x2*(n*x1 - x1))
