# ringchain generated code v1 sha256=5f0ec4968c7df845636c4cb325ec79a6c50c40eb7aa4a6c28754caf996c2a78c
# derivation: scattering._pulse_spread
# source key: caeff341571871d5b69b (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: x, a, sigma_Z
# expression sha256: d4c08822564151009a627b349f2b49c3b01cbb66adf6888fd5393e5aabcb780a (of its srepr)
def _lambdifygenerated(x, a, sigma_Z):
    return numpy.sqrt(a)*sigma_Z*numpy.sqrt(x)
