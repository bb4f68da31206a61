# ringchain generated code v1 sha256=d6e1564199de7bd264d5f5a47aeae548d091105959659cf56275a02e4d322c98
# derivation: solitary._speed_from_velocity
# source key: c0b268e8f55b26f011d3 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: K, n, a, m
# expression sha256: ba28673b9a469812914114dc58d7631f90d2bb49b7868cddb4b18ec23cb45533 (of its srepr)
def _lambdifygenerated(K, n, a, m):
    x0 = n + 1
    x1 = x0**(-1.0)
    return (x1*numpy.log(K) - x1*numpy.log(m) - x1*numpy.log(x0) + x1*numpy.log(2) + numpy.log(a), x1*(n - 1),)
