# ringchain generated code v1 sha256=781fc57d6a69101b5562b3d22adcadddcea26324a0c037f06a044aea48e27d04
# derivation: solitary._width
# source key: 0881d513a06819d2e367 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: n, a
# expression sha256: 4aa027b2f755104129bd07b7bcca6290607a7f917e9760a259dd9fdceb4098a1 (of its srepr)
def _lambdifygenerated(n, a):
    return (1/6)*numpy.sqrt(6)*numpy.pi*a*numpy.sqrt(n)*numpy.sqrt(n + 1)/(n - 1)
