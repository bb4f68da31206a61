# ringchain generated code v1 sha256=c61a7c0f791c4673f57c3b020ca396ec4ca1020aaa9046781c91a8cb13d5f1d3
# derivation: solitary._width
# source key: caeff341571871d5b69b (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: n, a
# expression sha256: 4aa027b2f755104129bd07b7bcca6290607a7f917e9760a259dd9fdceb4098a1 (of its srepr)
def _lambdifygenerated(n, a):
    return (1/6)*numpy.sqrt(6)*numpy.pi*a*numpy.sqrt(n)*numpy.sqrt(n + 1)/(n - 1)
