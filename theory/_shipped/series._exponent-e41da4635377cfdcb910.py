# ringchain generated code v1 sha256=6bded7a6ab66dc66fb4725274d103777243d4690d23e4390da1619290704316d
# derivation: series._exponent
# source key: aaa6be78b00d30412b2b (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: F, K_c, K_b
# expression sha256: 25e67935be228e44fca46acf9cd0be092a2af45a6d2f8a8ededdee4857ab9123 (of its srepr)
def _lambdifygenerated(F, K_c, K_b):
    return 3/(2 + (numpy.exp(-1/3*numpy.log(F) + numpy.log(K_b) - 2/3*numpy.log(K_c)) + 1)**(-1.0))
