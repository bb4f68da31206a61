# ringchain generated code v1 sha256=2f0e9fcef0d3ddfe9dcef649efcdcb49ee5a0aabc0d1b7335a2c0171f91d654a
# derivation: solitary._speed
# source key: 67895ff0807168ca9dd5 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: K, n, a, m
# expression sha256: 213cbf80e4ab25b1c9434c13030bd8f303f8dae9b416347fd8f1f20e27513371 (of its srepr)
def _lambdifygenerated(K, n, a, m):
    x0 = (1/2)/n
    return (x0*numpy.log(K) + numpy.log(a) - 1/2*numpy.log(m) - 1/2*numpy.log(n + 1) + (1/2)*numpy.log(2), x0*(n - 1),)
