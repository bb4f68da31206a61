# ringchain generated code v1 sha256=2b2ee07f68395ef2acd88d6b9bde3a01652774d030078b96f2ccb615ec66cd05
# derivation: scattering._pulse_spread
# source key: 317867d47b5755454417 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: x, a, sigma_Z
# expression sha256: d4c08822564151009a627b349f2b49c3b01cbb66adf6888fd5393e5aabcb780a (of its srepr)
def _lambdifygenerated(x, a, sigma_Z):
    return numpy.sqrt(a)*sigma_Z*numpy.sqrt(x)
