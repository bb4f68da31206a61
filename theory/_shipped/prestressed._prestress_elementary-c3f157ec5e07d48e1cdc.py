# ringchain generated code v1 sha256=b83848ca1206f136e595c44dba5838f25ac0335b842fd2cb92842f05472cc72a
# derivation: prestressed._prestress_elementary
# source key: caeff341571871d5b69b (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: F_m, F_0, n
# expression sha256: a52b38dc2756e1a037fbc04c5359e4d9ea01bdd7824bc7cf09dcc0afb0f1a7ac (of its srepr)
def _lambdifygenerated(F_m, F_0, n):
    x0 = F_0/F_m
    x1 = numpy.expm1(numpy.log(x0)/n)
    return (n*x0*x1 - x0 + 1, x1**2,)
