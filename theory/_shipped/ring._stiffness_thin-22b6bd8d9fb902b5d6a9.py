# ringchain generated code v1 sha256=6e145fc17528a14f5abf8b3bedc0c56a3a66f39801331c8b90eda78b2619c341
# derivation: ring._stiffness_thin
# source key: 0881d513a06819d2e367 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: R, r, E, nu
# expression sha256: 7cfb2fe4947fea0f9c60f7d4d67aef8ea109d8ce5f5eab4827ed2152ea2aca40 (of its srepr)
def _lambdifygenerated(R, r, E, nu):
    x0 = numpy.pi**2
    return E*r**4*x0/(R**3*(x0 - 8))
