# ringchain generated code v1 sha256=007aaf6e7e8697212498ad06390c92a1b7821b86a64232a381289e12aaad9ded
# derivation: prestressed._prestress_elementary
# source key: f3be020559998432f519 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: F_m, F_0, n
# expression sha256: a52b38dc2756e1a037fbc04c5359e4d9ea01bdd7824bc7cf09dcc0afb0f1a7ac (of its srepr)
def _lambdifygenerated(F_m, F_0, n):
    x0 = F_0/F_m
    x1 = numpy.expm1(numpy.log(x0)/n)
    return (n*x0*x1 - x0 + 1, x1**2,)
