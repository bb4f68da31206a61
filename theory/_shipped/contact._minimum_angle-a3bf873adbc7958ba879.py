# ringchain generated code v1 sha256=275f6aa52d3010e21585386cfebda060e2688c50ce2e317e30b20e482552b134
# derivation: contact._minimum_angle
# source key: 67895ff0807168ca9dd5 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: R, r
# expression sha256: b0971f127b319fc808d6eef3b9289bf28bc9e276790d81e084631cb852a05a11 (of its srepr)
def _lambdifygenerated(R, r):
    return 2*numpy.arcsin(numpy.sqrt(r)/numpy.sqrt(R))
