# ringchain generated code v1 sha256=63d873f608c40cfab2cd9aa14815533f4f21c2569d276fd40291a2077e4b90b5
# derivation: curved_beam._section_matrices
# source key: ceca10620e89af986038 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: R, r, E, nu
# expression sha256: db7f9cb5f678cab05cbe7bb206d95eeed29a6762c1f250144f81600e1a4016cf (of its srepr)
def _lambdifygenerated(R, r, E, nu):
    x0 = R**2
    x1 = r**2
    x2 = -x1
    x3 = numpy.sqrt(x0 + x2)
    x4 = 2*x3
    x5 = R*x4 + 2*x0 + x2
    x6 = x5**(-1.0)
    x7 = numpy.pi*x1
    x8 = E*x7
    x9 = numpy.pi*r**4
    x10 = E*x9
    x11 = R*x10
    x12 = -x11/x5
    x13 = (nu + 1)**(-1.0)
    x14 = (9/20)*x13*x8
    x15 = (1/4)*x9
    x16 = E*x15
    x17 = x13*x16
    x18 = x15/R
    x19 = -x18
    x20 = (1/2)*x9
    return numpy.array([[2*R*x6*x8*(R + x3), 0, x12], [0, x14, 0], [x12, 0, x0*x10*x6], [(1/3)*x11*x6*(R + x4), 0, 0], [0, x17, 0], [0, 0, x14], [x7, 0, 0], [0, x7, x18], [0, x18, x15], [x7, 0, x19], [0, x15, 0], [x19, 0, x20], [x8, 0, 0], [0, x14, 0], [0, 0, x16], [x16, 0, 0], [0, x17, 0], [0, 0, x14], [x7, 0, 0], [0, x7, 0], [0, 0, x15], [x7, 0, 0], [0, x15, 0], [0, 0, x20]])
