# ringchain generated code v1 sha256=538aef6f7014aa72fb0185c5ab66522a745a2f135b30686d4d32a875ac8fbc80
# derivation: linear._junction
# source key: f3be020559998432f519 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: Z_1, Z_2
# expression sha256: 3e63e2007f8e45af9353295a405e69c7f1ffa327fc15a9b92ced42abba252f9d (of its srepr)
def _lambdifygenerated(Z_1, Z_2):
    x0 = (Z_1 + Z_2)**(-1.0)
    return (-x0*(Z_1 - Z_2), 2*Z_2*x0)
