# ringchain generated code v1 sha256=8e5d3895f6cc7102325f136ed8650d74bcbb9e3926ad2218fdf029c89646933a
# derivation: ring._stiffness_thin
# source key: c0b268e8f55b26f011d3 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: R, r, E, nu
# expression sha256: 7cfb2fe4947fea0f9c60f7d4d67aef8ea109d8ce5f5eab4827ed2152ea2aca40 (of its srepr)
def _lambdifygenerated(R, r, E, nu):
    x0 = numpy.pi**2
    return E*r**4*x0/(R**3*(x0 - 8))
