# ringchain generated code v1 sha256=7129998ce478c263308434a9c87a8ff5337ce8d6b4f58c209b2b3bffe4ecdd36
# derivation: subsurface._circular_axis
# source key: ceca10620e89af986038 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: zeta, nu
# expression sha256: ed49cc25de3c1ab47a9978246387d9f3d202b2d2b9ac620da57b17f23a82adf0 (of its srepr)
def _lambdifygenerated(zeta, nu):
    x0 = 2*nu - 1
    x1 = x0**(-1.0)
    x2 = numpy.arctan(zeta)
    x3 = 2*x2
    x4 = x3 - numpy.pi
    x5 = x4*zeta + 2
    x6 = zeta**2 + 1
    x7 = 4*nu**2 - 1
    x8 = x6*x7
    x9 = 2*zeta
    x10 = x0*(x3*x6 - numpy.pi*x6 + x9)
    x11 = x1*(-x10*zeta - x5*x8)
    x12 = x6**(-1.0)
    x13 = x6**(-2.0)
    return ((1/4)*x11*x12, -x12, (1/4)*x1*x12*(-x0*zeta*(4*x2*zeta - numpy.pi*x9 + 4) - x10 - x5*x7*x9 - x8*(x12*x9 + x4)) - 1/2*x11*x13*zeta - x13*x9,)
