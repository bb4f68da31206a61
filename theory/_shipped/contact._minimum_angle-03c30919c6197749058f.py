# ringchain generated code v1 sha256=84b3f0d5420d132d03c603c7b16425c282d04ae54f01357c997d194a8dec5bfc
# derivation: contact._minimum_angle
# source key: ceca10620e89af986038 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: R, r
# expression sha256: b0971f127b319fc808d6eef3b9289bf28bc9e276790d81e084631cb852a05a11 (of its srepr)
def _lambdifygenerated(R, r):
    return 2*numpy.arcsin(numpy.sqrt(r)/numpy.sqrt(R))
