# ringchain generated code v1 sha256=9e8834b1d783a378203fe27eaa8ed94642e379b65dbe60ca10346b15afd09cbf
# derivation: linear._junction
# source key: 317867d47b5755454417 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: Z_1, Z_2
# expression sha256: 3e63e2007f8e45af9353295a405e69c7f1ffa327fc15a9b92ced42abba252f9d (of its srepr)
def _lambdifygenerated(Z_1, Z_2):
    x0 = (Z_1 + Z_2)**(-1.0)
    return (-x0*(Z_1 - Z_2), 2*Z_2*x0)
