# ringchain generated code v1 sha256=24ff22ebca4328abd5d45009a4accfeb9676a010b82bc4e67ed681f9374b7b02
# derivation: prestressed._prestress_integrand
# source key: c0b268e8f55b26f011d3 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: x, F_m, F_0, n
# expression sha256: e1584ad8d2627ef178dbb3cfe209b01ebb1a5a1a3276256068839f4f9b7cbb20 (of its srepr)
def _lambdifygenerated(x, F_m, F_0, n):
    return n*x*(n + 1)*numpy.exp((n - 1)*numpy.log1p(x*numpy.expm1(numpy.log(F_0/F_m)/n)))
