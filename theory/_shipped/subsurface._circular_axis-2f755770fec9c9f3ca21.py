# ringchain generated code v1 sha256=451157bcf76fc3ed5097b1905d7f1a1954654b5ef90031457bb43576908f4695
# derivation: subsurface._circular_axis
# source key: 0d3b9b67499038ff2889 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: zeta, nu
# expression sha256: f168a3e2e4602f63ac562c1f7985c12e5ca85da7de81022deb5cee7c9b1f83b2 (of its srepr)
def _lambdifygenerated(zeta, nu):
    x0 = 2*nu - 1
    x1 = x0**(-1.0)
    x2 = numpy.arctan(zeta)
    x3 = 2*zeta
    x4 = x2*x3 - numpy.pi*zeta + 2
    x5 = zeta**2 + 1
    x6 = 4*nu**2 - 1
    x7 = x5*x6
    x8 = 2*x2 - numpy.pi
    x9 = x0*(x3 + x5*x8)
    x10 = x1*(-x4*x7 - x9*zeta)
    x11 = x5**(-1.0)
    x12 = x5**(-2.0)
    return ((1/4)*x10*x11, -x11, (1/4)*x1*x11*(-x0*zeta*(x3*x8 + 4) - x3*x4*x6 - x7*(x11*x3 + x8) - x9) - 1/2*x10*x12*zeta - x12*x3,)
