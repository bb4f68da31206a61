# ringchain generated code v1 sha256=f2e085ff312b9cb0f65d43fab8218294ca0925f90cbc236179e640eeebd3572f
# derivation: contact._minimum_angle
# source key: f3be020559998432f519 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: R, r
# expression sha256: b0971f127b319fc808d6eef3b9289bf28bc9e276790d81e084631cb852a05a11 (of its srepr)
def _lambdifygenerated(R, r):
    return 2*numpy.arcsin(numpy.sqrt(r)/numpy.sqrt(R))
