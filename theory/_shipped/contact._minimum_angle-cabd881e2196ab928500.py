# ringchain generated code v1 sha256=cc0d01b616aeb613866e3f63b806e4fdeea21bea399e8a391aa5736a99581b2c
# derivation: contact._minimum_angle
# source key: 317867d47b5755454417 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: R, r
# expression sha256: b0971f127b319fc808d6eef3b9289bf28bc9e276790d81e084631cb852a05a11 (of its srepr)
def _lambdifygenerated(R, r):
    return 2*numpy.arcsin(numpy.sqrt(r)/numpy.sqrt(R))
