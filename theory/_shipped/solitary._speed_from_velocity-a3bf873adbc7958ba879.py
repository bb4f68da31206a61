# ringchain generated code v1 sha256=943624c859d2c7ad571b13a4ea85601939c4150d9fdbed0eb2cadc7413f6e23f
# derivation: solitary._speed_from_velocity
# source key: 67895ff0807168ca9dd5 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: K, n, a, m
# expression sha256: ba28673b9a469812914114dc58d7631f90d2bb49b7868cddb4b18ec23cb45533 (of its srepr)
def _lambdifygenerated(K, n, a, m):
    x0 = n + 1
    x1 = x0**(-1.0)
    return (x1*numpy.log(K) - x1*numpy.log(m) - x1*numpy.log(x0) + x1*numpy.log(2) + numpy.log(a), x1*(n - 1),)
