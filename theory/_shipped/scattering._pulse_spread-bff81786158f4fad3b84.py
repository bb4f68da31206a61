# ringchain generated code v1 sha256=1a9a1188f587d1e16067c4d026d57885a0a2dc4f812c913879bc0f44bdfb9b70
# derivation: scattering._pulse_spread
# source key: 07201ab9dccdbac32795 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: x, a, sigma_Z
# expression sha256: d4c08822564151009a627b349f2b49c3b01cbb66adf6888fd5393e5aabcb780a (of its srepr)
def _lambdifygenerated(x, a, sigma_Z):
    return numpy.sqrt(a)*sigma_Z*numpy.sqrt(x)
