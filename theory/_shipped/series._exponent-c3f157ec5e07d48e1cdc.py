# ringchain generated code v1 sha256=b3a52005cd85c289321379344c93cec223e7dbe172c09a350d38613e179cd298
# derivation: series._exponent
# source key: caeff341571871d5b69b (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: F, K_c, K_b
# expression sha256: 25e67935be228e44fca46acf9cd0be092a2af45a6d2f8a8ededdee4857ab9123 (of its srepr)
def _lambdifygenerated(F, K_c, K_b):
    return 3/(2 + (numpy.exp(-1/3*numpy.log(F) + numpy.log(K_b) - 2/3*numpy.log(K_c)) + 1)**(-1.0))
