# ringchain generated code v1 sha256=13c66cebc9bfd94b84f2fb58ebf7c1fafe9b31a8c9812e9c5f27104220bf4f9a
# derivation: linear._junction
# source key: 67895ff0807168ca9dd5 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: Z_1, Z_2
# expression sha256: 3e63e2007f8e45af9353295a405e69c7f1ffa327fc15a9b92ced42abba252f9d (of its srepr)
def _lambdifygenerated(Z_1, Z_2):
    x0 = (Z_1 + Z_2)**(-1.0)
    return (-x0*(Z_1 - Z_2), 2*Z_2*x0)
