# ringchain generated code v1 sha256=7fab93e0422bde6c124fbec5b981e340e714054f92642f1178bc71c75c3c7daf
# derivation: prestressed._prestress_integrand
# source key: aaa6be78b00d30412b2b (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: x, F_m, F_0, n
# expression sha256: e1584ad8d2627ef178dbb3cfe209b01ebb1a5a1a3276256068839f4f9b7cbb20 (of its srepr)
def _lambdifygenerated(x, F_m, F_0, n):
    return n*x*(n + 1)*numpy.exp((n - 1)*numpy.log1p(x*numpy.expm1(numpy.log(F_0/F_m)/n)))
