# ringchain generated code v1 sha256=23e6df1bd902a5b6a103514998ddc0d703c1d0307eef0869bef2b75b29de17bd
# derivation: solitary._width
# source key: 0d3b9b67499038ff2889 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: n, a
# expression sha256: 4aa027b2f755104129bd07b7bcca6290607a7f917e9760a259dd9fdceb4098a1 (of its srepr)
def _lambdifygenerated(n, a):
    return (1/6)*numpy.sqrt(6)*numpy.pi*a*numpy.sqrt(n)*numpy.sqrt(n + 1)/(n - 1)
