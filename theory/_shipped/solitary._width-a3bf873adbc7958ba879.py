# ringchain generated code v1 sha256=5818f6b3f2a60b9fa821de4304253d11e9cf92634baa7a050446ab10497c8ad9
# derivation: solitary._width
# source key: 67895ff0807168ca9dd5 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: n, a
# expression sha256: 4aa027b2f755104129bd07b7bcca6290607a7f917e9760a259dd9fdceb4098a1 (of its srepr)
def _lambdifygenerated(n, a):
    return (1/6)*numpy.sqrt(6)*numpy.pi*a*numpy.sqrt(n)*numpy.sqrt(n + 1)/(n - 1)
