# ringchain generated code v1 sha256=bf1db34fde588d790c7e916a4520dce0c4b63ab0207db05ba58b8c3b391e391f
# derivation: scattering._pulse_spread
# source key: 67895ff0807168ca9dd5 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: x, a, sigma_Z
# expression sha256: d4c08822564151009a627b349f2b49c3b01cbb66adf6888fd5393e5aabcb780a (of its srepr)
def _lambdifygenerated(x, a, sigma_Z):
    return numpy.sqrt(a)*sigma_Z*numpy.sqrt(x)
