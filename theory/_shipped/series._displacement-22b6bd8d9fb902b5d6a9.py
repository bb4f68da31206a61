# ringchain generated code v1 sha256=1c816ba3e0011a42aca01c2a100d26dd6b2b002e5dfbb85868dd82e963c353d0
# derivation: series._displacement
# source key: 0881d513a06819d2e367 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: F, K_c, K_b
# expression sha256: a08fb03c70bf75ffc83e63b767fb3e19a809ae4726e6d7469f35823d2d158964 (of its srepr)
def _lambdifygenerated(F, K_c, K_b):
    return F**(2/3)/K_c**(2/3) + F/K_b
