# ringchain generated code v1 sha256=fa74c51fc843b9d05a08327bcf1a2f3230b81ac6855abf5a5db000fcfdf4dd01
# derivation: series._exponent
# source key: ceca10620e89af986038 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: F, K_c, K_b
# expression sha256: 25e67935be228e44fca46acf9cd0be092a2af45a6d2f8a8ededdee4857ab9123 (of its srepr)
def _lambdifygenerated(F, K_c, K_b):
    return 3/(2 + (numpy.exp(-1/3*numpy.log(F) + numpy.log(K_b) - 2/3*numpy.log(K_c)) + 1)**(-1.0))
