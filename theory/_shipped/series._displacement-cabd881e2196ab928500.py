# ringchain generated code v1 sha256=545ff11017c0fc84890ae23b68f6324e43392f5b31ee12c18f5eb871453a2dbd
# derivation: series._displacement
# source key: 317867d47b5755454417 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: F, K_c, K_b
# expression sha256: a08fb03c70bf75ffc83e63b767fb3e19a809ae4726e6d7469f35823d2d158964 (of its srepr)
def _lambdifygenerated(F, K_c, K_b):
    return F**(2/3)/K_c**(2/3) + F/K_b
