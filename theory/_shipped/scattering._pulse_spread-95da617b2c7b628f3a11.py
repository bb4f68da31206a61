# ringchain generated code v1 sha256=b570f9f4a04232d90b5c4a473376dd035ab7cdf277be1713fd8d5894cda14253
# derivation: scattering._pulse_spread
# source key: f3be020559998432f519 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: x, a, sigma_Z
# expression sha256: d4c08822564151009a627b349f2b49c3b01cbb66adf6888fd5393e5aabcb780a (of its srepr)
def _lambdifygenerated(x, a, sigma_Z):
    return numpy.sqrt(a)*sigma_Z*numpy.sqrt(x)
