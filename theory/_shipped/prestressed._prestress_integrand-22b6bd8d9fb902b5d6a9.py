# ringchain generated code v1 sha256=ff65b0840d9394026ae81f2bbfa046abd5f94e95e94b82866648d84b1c3a6e9f
# derivation: prestressed._prestress_integrand
# source key: 0881d513a06819d2e367 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: x, F_m, F_0, n
# expression sha256: e1584ad8d2627ef178dbb3cfe209b01ebb1a5a1a3276256068839f4f9b7cbb20 (of its srepr)
def _lambdifygenerated(x, F_m, F_0, n):
    return n*x*(n + 1)*numpy.exp((n - 1)*numpy.log1p(x*numpy.expm1(numpy.log(F_0/F_m)/n)))
