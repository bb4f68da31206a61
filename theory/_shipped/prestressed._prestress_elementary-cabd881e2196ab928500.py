# ringchain generated code v1 sha256=34bc37ed883872aab994aab74583b7d5a0b58b807a851e6d6b66a05b32e1b2d1
# derivation: prestressed._prestress_elementary
# source key: 317867d47b5755454417 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: F_m, F_0, n
# expression sha256: a52b38dc2756e1a037fbc04c5359e4d9ea01bdd7824bc7cf09dcc0afb0f1a7ac (of its srepr)
def _lambdifygenerated(F_m, F_0, n):
    x0 = F_0/F_m
    x1 = numpy.expm1(numpy.log(x0)/n)
    return (n*x0*x1 - x0 + 1, x1**2,)
