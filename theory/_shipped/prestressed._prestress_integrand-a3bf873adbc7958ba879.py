# ringchain generated code v1 sha256=8610d917e20a157d5591c84caa311a721275be2145afb379bbb35c4886f66e0d
# derivation: prestressed._prestress_integrand
# source key: 67895ff0807168ca9dd5 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: x, F_m, F_0, n
# expression sha256: e1584ad8d2627ef178dbb3cfe209b01ebb1a5a1a3276256068839f4f9b7cbb20 (of its srepr)
def _lambdifygenerated(x, F_m, F_0, n):
    return n*x*(n + 1)*numpy.exp((n - 1)*numpy.log1p(x*numpy.expm1(numpy.log(F_0/F_m)/n)))
