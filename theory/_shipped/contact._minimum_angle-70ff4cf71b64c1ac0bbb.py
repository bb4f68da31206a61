# ringchain generated code v1 sha256=61f2f39898a3b321cf8b353fd4b339b51b47bf93ed65463ef58c1ec626868147
# derivation: contact._minimum_angle
# source key: a22a0557fcec1bc1abe9 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: R, r
# expression sha256: b0971f127b319fc808d6eef3b9289bf28bc9e276790d81e084631cb852a05a11 (of its srepr)
def _lambdifygenerated(R, r):
    return 2*numpy.arcsin(numpy.sqrt(r)/numpy.sqrt(R))
