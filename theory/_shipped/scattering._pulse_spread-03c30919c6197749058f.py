# ringchain generated code v1 sha256=00392ca86411c35f99b39afeb62c3d664b4f0bffa4a6e6015d6dae93cfab5763
# derivation: scattering._pulse_spread
# source key: ceca10620e89af986038 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: x, a, sigma_Z
# expression sha256: d4c08822564151009a627b349f2b49c3b01cbb66adf6888fd5393e5aabcb780a (of its srepr)
def _lambdifygenerated(x, a, sigma_Z):
    return numpy.sqrt(a)*sigma_Z*numpy.sqrt(x)
