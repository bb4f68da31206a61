# ringchain generated code v1 sha256=9db7f6bd3cf8a072312f49c4de449c80229382ffe5907c18b65aa23d847f5599
# derivation: solitary._width
# source key: f3be020559998432f519 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: n, a
# expression sha256: 4aa027b2f755104129bd07b7bcca6290607a7f917e9760a259dd9fdceb4098a1 (of its srepr)
def _lambdifygenerated(n, a):
    return (1/6)*numpy.sqrt(6)*numpy.pi*a*numpy.sqrt(n)*numpy.sqrt(n + 1)/(n - 1)
