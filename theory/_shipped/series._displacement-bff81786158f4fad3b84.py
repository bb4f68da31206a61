# ringchain generated code v1 sha256=ec73cc9643da9d6e2dc5c5c4fe74602863b20f529849621928b9ab4397e7fcee
# derivation: series._displacement
# source key: 07201ab9dccdbac32795 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: F, K_c, K_b
# expression sha256: a08fb03c70bf75ffc83e63b767fb3e19a809ae4726e6d7469f35823d2d158964 (of its srepr)
def _lambdifygenerated(F, K_c, K_b):
    return F**(2/3)/K_c**(2/3) + F/K_b
