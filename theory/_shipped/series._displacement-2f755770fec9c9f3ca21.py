# ringchain generated code v1 sha256=fb9edf4295adb775a9d4659580a29bb44e68b6018bb0198ab396a5ff6a8842bf
# derivation: series._displacement
# source key: 0d3b9b67499038ff2889 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: F, K_c, K_b
# expression sha256: a08fb03c70bf75ffc83e63b767fb3e19a809ae4726e6d7469f35823d2d158964 (of its srepr)
def _lambdifygenerated(F, K_c, K_b):
    return F**(2/3)/K_c**(2/3) + F/K_b
