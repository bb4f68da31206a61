# ringchain generated code v1 sha256=7e349bcd6e4fb1ec1064f9c4431b5671f95652112d7ae321564dc00b2d12f102
# derivation: contact._minimum_angle
# source key: 10a35615fa68ecdff34f (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: R, r
# expression sha256: b0971f127b319fc808d6eef3b9289bf28bc9e276790d81e084631cb852a05a11 (of its srepr)
def _lambdifygenerated(R, r):
    return 2*numpy.arcsin(numpy.sqrt(r)/numpy.sqrt(R))
