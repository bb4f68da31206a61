# ringchain generated code v1 sha256=01dd41428872ecce8e009f2393b3689a67f346f794e5e36d6aa0c693201ef03c
# derivation: series._displacement
# source key: 67895ff0807168ca9dd5 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: F, K_c, K_b
# expression sha256: a08fb03c70bf75ffc83e63b767fb3e19a809ae4726e6d7469f35823d2d158964 (of its srepr)
def _lambdifygenerated(F, K_c, K_b):
    return F**(2/3)/K_c**(2/3) + F/K_b
