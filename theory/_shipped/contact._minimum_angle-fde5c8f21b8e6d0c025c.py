# ringchain generated code v1 sha256=3b6de2e86b158849c62862d24cda630cdbe307d75a521c04ba2b65f57f8546ec
# derivation: contact._minimum_angle
# source key: 263ab3517922b3fc21eb (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: R, r
# expression sha256: b0971f127b319fc808d6eef3b9289bf28bc9e276790d81e084631cb852a05a11 (of its srepr)
def _lambdifygenerated(R, r):
    return 2*numpy.arcsin(numpy.sqrt(r)/numpy.sqrt(R))
