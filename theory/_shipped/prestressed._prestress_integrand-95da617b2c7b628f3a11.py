# ringchain generated code v1 sha256=799bf26775e4ea67c6feb2cd3d06526f147d184cbd2cdb3465d695e56461b088
# derivation: prestressed._prestress_integrand
# source key: f3be020559998432f519 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: x, F_m, F_0, n
# expression sha256: e1584ad8d2627ef178dbb3cfe209b01ebb1a5a1a3276256068839f4f9b7cbb20 (of its srepr)
def _lambdifygenerated(x, F_m, F_0, n):
    return n*x*(n + 1)*numpy.exp((n - 1)*numpy.log1p(x*numpy.expm1(numpy.log(F_0/F_m)/n)))
