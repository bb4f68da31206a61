# ringchain generated code v1 sha256=6336bbf259d46c237445b509a9e2d84e381e2f863bca85603c1798e959555e5e
# derivation: solitary._speed
# source key: c0b268e8f55b26f011d3 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: K, n, a, m
# expression sha256: 213cbf80e4ab25b1c9434c13030bd8f303f8dae9b416347fd8f1f20e27513371 (of its srepr)
def _lambdifygenerated(K, n, a, m):
    x0 = (1/2)/n
    return (x0*numpy.log(K) + numpy.log(a) - 1/2*numpy.log(m) - 1/2*numpy.log(n + 1) + (1/2)*numpy.log(2), x0*(n - 1),)
