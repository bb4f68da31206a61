# ringchain generated code v1 sha256=32063d82651e75ae0dc167dc10cb667ce9aa26c87bd32a384169f167a0c0aff3
# derivation: series._displacement
# source key: caeff341571871d5b69b (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: F, K_c, K_b
# expression sha256: a08fb03c70bf75ffc83e63b767fb3e19a809ae4726e6d7469f35823d2d158964 (of its srepr)
def _lambdifygenerated(F, K_c, K_b):
    return F**(2/3)/K_c**(2/3) + F/K_b
