# ringchain generated code v1 sha256=8beecce34bcb91c161199eaf2c14ea0a5ba5b3c8232931025279f936b47078b2
# derivation: solitary._speed
# source key: a22a0557fcec1bc1abe9 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: K, n, a, m
# expression sha256: 213cbf80e4ab25b1c9434c13030bd8f303f8dae9b416347fd8f1f20e27513371 (of its srepr)
def _lambdifygenerated(K, n, a, m):
    x0 = (1/2)/n
    return (x0*numpy.log(K) + numpy.log(a) - 1/2*numpy.log(m) - 1/2*numpy.log(n + 1) + (1/2)*numpy.log(2), x0*(n - 1),)
