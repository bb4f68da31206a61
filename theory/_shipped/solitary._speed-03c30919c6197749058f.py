# ringchain generated code v1 sha256=aa6d7099f43385c3cd14caaa6d7c49ba731857192986c144f4e9444b2582086d
# derivation: solitary._speed
# source key: ceca10620e89af986038 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: K, n, a, m
# expression sha256: 213cbf80e4ab25b1c9434c13030bd8f303f8dae9b416347fd8f1f20e27513371 (of its srepr)
def _lambdifygenerated(K, n, a, m):
    x0 = (1/2)/n
    return (x0*numpy.log(K) + numpy.log(a) - 1/2*numpy.log(m) - 1/2*numpy.log(n + 1) + (1/2)*numpy.log(2), x0*(n - 1),)
