# ringchain generated code v1 sha256=5d963df5d457b73b2a4a3f2357d0fa268634169dac4c1bcfc55057f3f332b87e
# derivation: contact._minimum_angle
# source key: 0d3b9b67499038ff2889 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: R, r
# expression sha256: b0971f127b319fc808d6eef3b9289bf28bc9e276790d81e084631cb852a05a11 (of its srepr)
def _lambdifygenerated(R, r):
    return 2*numpy.arcsin(numpy.sqrt(r)/numpy.sqrt(R))
