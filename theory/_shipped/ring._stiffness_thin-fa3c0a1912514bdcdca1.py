# ringchain generated code v1 sha256=529ebfcf9e3fc19dfbefb303ac0c93ecd3229bf1b41fe4d71f35fda51ad4f487
# derivation: ring._stiffness_thin
# source key: 10a35615fa68ecdff34f (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: R, r, E, nu
# expression sha256: 7cfb2fe4947fea0f9c60f7d4d67aef8ea109d8ce5f5eab4827ed2152ea2aca40 (of its srepr)
def _lambdifygenerated(R, r, E, nu):
    x0 = numpy.pi**2
    return E*r**4*x0/(R**3*(x0 - 8))
