# ringchain generated code v1 sha256=e8771d16ad9c244a2f74f0770e88dc2db70c09a12a819cd600d5b9a95c8bf94a
# derivation: ring._stiffness_thin
# source key: 317867d47b5755454417 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: R, r, E, nu
# expression sha256: 7cfb2fe4947fea0f9c60f7d4d67aef8ea109d8ce5f5eab4827ed2152ea2aca40 (of its srepr)
def _lambdifygenerated(R, r, E, nu):
    x0 = numpy.pi**2
    return E*r**4*x0/(R**3*(x0 - 8))
