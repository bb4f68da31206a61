# ringchain generated code v1 sha256=1a5b06ba0d07523317e5cabcd5e2988f8bedfbe95320a2de5f51e1e82fca89a5
# derivation: subsurface._elliptical_axis
# source key: ceca10620e89af986038 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: zeta, m_1, nu
# expression sha256: 816ea9de801370272dde5b0dc42d72d0c88dd37f3b59218b98f60e1fc7c16006 (of its srepr)
def _lambdifygenerated(zeta, m_1, nu):
    x0 = numpy.pi*nu
    x1 = 4*x0
    x2 = numpy.sqrt(m_1)
    x3 = 2*numpy.pi
    x4 = m_1*x3
    x5 = m_1*x1
    x6 = m_1*zeta**2
    x7 = x3*x6
    x8 = x1*x6
    x9 = x6 + 1
    x10 = m_1 + x6
    x11 = numpy.sqrt(x10)*numpy.sqrt(x9)
    x12 = x1*x11 - x11*x3
    x13 = x12 - x7 + x8
    x14 = (x13 - x4 + x5)**(-1.0)
    x15 = x14*x2
    x16 = x1*x15
    x17 = nu**2
    x18 = 8*numpy.pi*x17
    x19 = scipy.special.elliprd(x6, x10, x9)
    x20 = (12*x0 - 6*numpy.pi)**(-1.0)
    x21 = m_1*x20
    x22 = 4*numpy.pi
    x23 = x19*x21*x22
    x24 = scipy.special.elliprd(x6, x9, x10)
    x25 = x20*x5
    x26 = x24*x25
    x27 = (x1 + x13 - x3)**(-1.0)
    x28 = x2*x27
    x29 = x1*x28
    x30 = -2*numpy.pi*x2*x27 + x29
    x31 = x21*x22*x24
    x32 = x19*x25
    x33 = -2*numpy.pi*x14*x2 + x16
    x34 = -x11*x7 + x11*x8
    x35 = (x12 + x34)**(-1.0)
    x36 = m_1**(3/2)*zeta
    x37 = x3*x36
    x38 = x1*x36
    x39 = -x35*x37 + x35*x38
    x40 = (-x11*x4 + x11*x5 + x34)**(-1.0)
    x41 = -x37*x40 + x38*x40
    return (8*numpy.pi*m_1*nu*x19*x20*zeta + 8*numpy.pi*m_1*x17*x20*x24*zeta - x15*x18 + x16 - x23*zeta - x26*zeta - x30, 8*numpy.pi*m_1*nu*x20*x24*zeta + 8*numpy.pi*m_1*x17*x19*x20*zeta - x18*x28 + x29 - x31*zeta - x32*zeta - x33, -x30 - x33, 8*numpy.pi*m_1*nu*x19*x20 + 8*numpy.pi*m_1*x17*x20*x24 - x23 - x26 - x39, 8*numpy.pi*m_1*nu*x20*x24 + 8*numpy.pi*m_1*x17*x19*x20 - x31 - x32 - x41, x39 + x41,)
