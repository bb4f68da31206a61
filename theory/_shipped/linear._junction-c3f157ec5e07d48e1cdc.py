# ringchain generated code v1 sha256=9410e2a45ec31722c509c8d0926ab7ec60be8a0f7aaa7b773798a91a16986e39
# derivation: linear._junction
# source key: caeff341571871d5b69b (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: Z_1, Z_2
# expression sha256: 3e63e2007f8e45af9353295a405e69c7f1ffa327fc15a9b92ced42abba252f9d (of its srepr)
def _lambdifygenerated(Z_1, Z_2):
    x0 = (Z_1 + Z_2)**(-1.0)
    return (-x0*(Z_1 - Z_2), 2*Z_2*x0)
