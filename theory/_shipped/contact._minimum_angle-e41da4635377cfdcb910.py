# ringchain generated code v1 sha256=ad1a98fb8951fd45a853cd0b7d3ba26fb1fd5106131c2afdc845832bb41adc18
# derivation: contact._minimum_angle
# source key: aaa6be78b00d30412b2b (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: R, r
# expression sha256: b0971f127b319fc808d6eef3b9289bf28bc9e276790d81e084631cb852a05a11 (of its srepr)
def _lambdifygenerated(R, r):
    return 2*numpy.arcsin(numpy.sqrt(r)/numpy.sqrt(R))
