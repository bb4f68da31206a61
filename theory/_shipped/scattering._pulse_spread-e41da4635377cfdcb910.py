# ringchain generated code v1 sha256=4c6f6b8079811b6fcda98b7a87a87591075d5c6580e420d2ed15fcb93dab4686
# derivation: scattering._pulse_spread
# source key: aaa6be78b00d30412b2b (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: x, a, sigma_Z
# expression sha256: d4c08822564151009a627b349f2b49c3b01cbb66adf6888fd5393e5aabcb780a (of its srepr)
def _lambdifygenerated(x, a, sigma_Z):
    return numpy.sqrt(a)*sigma_Z*numpy.sqrt(x)
