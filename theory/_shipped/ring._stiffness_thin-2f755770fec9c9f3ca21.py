# ringchain generated code v1 sha256=07b579fb7e3e2c79ed2a4d823e8e1ccc7e7b6cbd8962d7632c87252553b23a2b
# derivation: ring._stiffness_thin
# source key: 0d3b9b67499038ff2889 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: R, r, E, nu
# expression sha256: 7cfb2fe4947fea0f9c60f7d4d67aef8ea109d8ce5f5eab4827ed2152ea2aca40 (of its srepr)
def _lambdifygenerated(R, r, E, nu):
    x0 = numpy.pi**2
    return E*r**4*x0/(R**3*(x0 - 8))
