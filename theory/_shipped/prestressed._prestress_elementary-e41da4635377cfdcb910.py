# ringchain generated code v1 sha256=939e4cfa593068b8575199ee67635ecaae400a143ac7d15b31e1c5deabb18373
# derivation: prestressed._prestress_elementary
# source key: aaa6be78b00d30412b2b (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: F_m, F_0, n
# expression sha256: a52b38dc2756e1a037fbc04c5359e4d9ea01bdd7824bc7cf09dcc0afb0f1a7ac (of its srepr)
def _lambdifygenerated(F_m, F_0, n):
    x0 = F_0/F_m
    x1 = numpy.expm1(numpy.log(x0)/n)
    return (n*x0*x1 - x0 + 1, x1**2,)
