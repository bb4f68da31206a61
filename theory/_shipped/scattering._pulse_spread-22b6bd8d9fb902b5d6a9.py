# ringchain generated code v1 sha256=eadab8b0956374243a5c8685af22724234a5b314f2358dcdd064fcd596b4a1bb
# derivation: scattering._pulse_spread
# source key: 0881d513a06819d2e367 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: x, a, sigma_Z
# expression sha256: d4c08822564151009a627b349f2b49c3b01cbb66adf6888fd5393e5aabcb780a (of its srepr)
def _lambdifygenerated(x, a, sigma_Z):
    return numpy.sqrt(a)*sigma_Z*numpy.sqrt(x)
