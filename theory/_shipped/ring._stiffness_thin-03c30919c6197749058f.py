# ringchain generated code v1 sha256=36fe345e9bbc6ba35a9e7e8ccc1651aabb5d8dd8fa1dea5feff8ee814d705e75
# derivation: ring._stiffness_thin
# source key: ceca10620e89af986038 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: R, r, E, nu
# expression sha256: 7cfb2fe4947fea0f9c60f7d4d67aef8ea109d8ce5f5eab4827ed2152ea2aca40 (of its srepr)
def _lambdifygenerated(R, r, E, nu):
    x0 = numpy.pi**2
    return E*r**4*x0/(R**3*(x0 - 8))
