# ringchain generated code v1 sha256=368ebf3a9d3b4c88d422f2cbebf1509a8c412c1fadf73e375a76f6df081ed6b4
# derivation: scattering._pulse_spread
# source key: 0d3b9b67499038ff2889 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: x, a, sigma_Z
# expression sha256: d4c08822564151009a627b349f2b49c3b01cbb66adf6888fd5393e5aabcb780a (of its srepr)
def _lambdifygenerated(x, a, sigma_Z):
    return numpy.sqrt(a)*sigma_Z*numpy.sqrt(x)
