# ringchain generated code v1 sha256=866554dc72970f1b6164b8929328c3666eb8be5bc88318cafed8a3a6edf8f357
# derivation: series._exponent
# source key: a22a0557fcec1bc1abe9 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: F, K_c, K_b
# expression sha256: 25e67935be228e44fca46acf9cd0be092a2af45a6d2f8a8ededdee4857ab9123 (of its srepr)
def _lambdifygenerated(F, K_c, K_b):
    return 3/(2 + (numpy.exp(-1/3*numpy.log(F) + numpy.log(K_b) - 2/3*numpy.log(K_c)) + 1)**(-1.0))
