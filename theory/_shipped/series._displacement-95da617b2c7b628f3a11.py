# ringchain generated code v1 sha256=d4acf34a4e012255f7d11a7c2f03a41ed8dd3730fde65aebe970a4c828dac394
# derivation: series._displacement
# source key: f3be020559998432f519 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: F, K_c, K_b
# expression sha256: a08fb03c70bf75ffc83e63b767fb3e19a809ae4726e6d7469f35823d2d158964 (of its srepr)
def _lambdifygenerated(F, K_c, K_b):
    return F**(2/3)/K_c**(2/3) + F/K_b
