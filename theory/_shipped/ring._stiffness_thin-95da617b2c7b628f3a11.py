# ringchain generated code v1 sha256=9051bfebc96b9c5bf53b2243984d27b8ca4a4cc4e76d6e16f3a5b1c9cffdfd8f
# derivation: ring._stiffness_thin
# source key: f3be020559998432f519 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: R, r, E, nu
# expression sha256: 7cfb2fe4947fea0f9c60f7d4d67aef8ea109d8ce5f5eab4827ed2152ea2aca40 (of its srepr)
def _lambdifygenerated(R, r, E, nu):
    x0 = numpy.pi**2
    return E*r**4*x0/(R**3*(x0 - 8))
