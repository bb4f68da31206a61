# ringchain generated code v1 sha256=2af3d0423bc1dc94d8f1a7b38aeb556d5bc7b11c7d40d213c5bb3234ade6c0eb
# derivation: scattering._pulse_spread
# source key: a22a0557fcec1bc1abe9 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: x, a, sigma_Z
# expression sha256: d4c08822564151009a627b349f2b49c3b01cbb66adf6888fd5393e5aabcb780a (of its srepr)
def _lambdifygenerated(x, a, sigma_Z):
    return numpy.sqrt(a)*sigma_Z*numpy.sqrt(x)
