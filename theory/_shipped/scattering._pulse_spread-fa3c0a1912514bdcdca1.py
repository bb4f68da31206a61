# ringchain generated code v1 sha256=4347a33ffd7cf4ae7ce5d7d22b46cf59d174243ff9be99d3f17317e171feefde
# derivation: scattering._pulse_spread
# source key: 10a35615fa68ecdff34f (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: x, a, sigma_Z
# expression sha256: d4c08822564151009a627b349f2b49c3b01cbb66adf6888fd5393e5aabcb780a (of its srepr)
def _lambdifygenerated(x, a, sigma_Z):
    return numpy.sqrt(a)*sigma_Z*numpy.sqrt(x)
