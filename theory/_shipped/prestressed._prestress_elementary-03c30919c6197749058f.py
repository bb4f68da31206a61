# ringchain generated code v1 sha256=9f6d9a94d821d4d7bf3ff8685383a994047eb50d304faf6f2fa3c19fde10e8b7
# derivation: prestressed._prestress_elementary
# source key: ceca10620e89af986038 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: F_m, F_0, n
# expression sha256: a52b38dc2756e1a037fbc04c5359e4d9ea01bdd7824bc7cf09dcc0afb0f1a7ac (of its srepr)
def _lambdifygenerated(F_m, F_0, n):
    x0 = F_0/F_m
    x1 = numpy.expm1(numpy.log(x0)/n)
    return (n*x0*x1 - x0 + 1, x1**2,)
