# ringchain generated code v1 sha256=0fb9149806260edbd5dce055b3d00c378ca14bebcd4239e92e7857cfdc58ead5
# derivation: linear._junction
# source key: 0d3b9b67499038ff2889 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: Z_1, Z_2
# expression sha256: 3e63e2007f8e45af9353295a405e69c7f1ffa327fc15a9b92ced42abba252f9d (of its srepr)
def _lambdifygenerated(Z_1, Z_2):
    x0 = (Z_1 + Z_2)**(-1.0)
    return (-x0*(Z_1 - Z_2), 2*Z_2*x0)
