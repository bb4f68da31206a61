# ringchain generated code v1 sha256=5840b7b05b0ec04b15438b6abc8592b71e28a6744c10579fc869baf3695ff3c0
# derivation: series._exponent
# source key: 0d3b9b67499038ff2889 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: F, K_c, K_b
# expression sha256: 25e67935be228e44fca46acf9cd0be092a2af45a6d2f8a8ededdee4857ab9123 (of its srepr)
def _lambdifygenerated(F, K_c, K_b):
    return 3/(2 + (numpy.exp(-1/3*numpy.log(F) + numpy.log(K_b) - 2/3*numpy.log(K_c)) + 1)**(-1.0))
