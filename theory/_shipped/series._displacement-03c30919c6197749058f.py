# ringchain generated code v1 sha256=c5b7d1f5bcafa3d2e059132e7cb1402c1ec85d38efaad279ff0a272b6a6515b9
# derivation: series._displacement
# source key: ceca10620e89af986038 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: F, K_c, K_b
# expression sha256: a08fb03c70bf75ffc83e63b767fb3e19a809ae4726e6d7469f35823d2d158964 (of its srepr)
def _lambdifygenerated(F, K_c, K_b):
    return F**(2/3)/K_c**(2/3) + F/K_b
