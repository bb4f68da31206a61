# ringchain generated code v1 sha256=9e0f42f129f3ad6f498a1af57dd1432e8c56d5d4e058a2732ff9257bc588c3e3
# derivation: contact._minimum_angle
# source key: caeff341571871d5b69b (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: R, r
# expression sha256: b0971f127b319fc808d6eef3b9289bf28bc9e276790d81e084631cb852a05a11 (of its srepr)
def _lambdifygenerated(R, r):
    return 2*numpy.arcsin(numpy.sqrt(r)/numpy.sqrt(R))
