# ringchain generated code v1 sha256=f78b1d5902653865473be93fc6462c2df75118835cdd10a9fe6c26d8cc716086
# derivation: contact._minimum_angle
# source key: 0881d513a06819d2e367 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: R, r
# expression sha256: b0971f127b319fc808d6eef3b9289bf28bc9e276790d81e084631cb852a05a11 (of its srepr)
def _lambdifygenerated(R, r):
    return 2*numpy.arcsin(numpy.sqrt(r)/numpy.sqrt(R))
