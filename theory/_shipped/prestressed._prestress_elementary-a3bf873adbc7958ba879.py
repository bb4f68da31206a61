# ringchain generated code v1 sha256=6d5cde8c8d1cb9894db63529b500c9d62cb21700cdd846e83cd513b50f793fd0
# derivation: prestressed._prestress_elementary
# source key: 67895ff0807168ca9dd5 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: F_m, F_0, n
# expression sha256: a52b38dc2756e1a037fbc04c5359e4d9ea01bdd7824bc7cf09dcc0afb0f1a7ac (of its srepr)
def _lambdifygenerated(F_m, F_0, n):
    x0 = F_0/F_m
    x1 = numpy.expm1(numpy.log(x0)/n)
    return (n*x0*x1 - x0 + 1, x1**2,)
