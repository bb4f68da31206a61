# ringchain generated code v1 sha256=eaad427077d51d444238b0370da393107c7cb89f5afb3a464ed02b87691d6aae
# derivation: ring._stiffness_thick
# source key: ceca10620e89af986038 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: R, r, E, nu
# expression sha256: 0ca37db18c38885901cd6c00cc6007ab83b25364faa6bafb9b28251fa40778d0 (of its srepr)
def _lambdifygenerated(R, r, E, nu):
    x0 = numpy.pi**2
    x1 = R**2
    x2 = r**2
    x3 = R + numpy.sqrt(x1 - x2)
    x4 = 36*r**4
    x5 = R*x2*x3
    x6 = x1*x3**2
    return E*x0*x3*x4/(x0*x5*(20*nu + 11) + 18*x0*x6 - x4 + 144*x5 - 144*x6)
