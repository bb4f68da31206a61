# ringchain generated code v1 sha256=03d245410acf3e5ef331452ccc2d0e955c3c97daa036e1d05d9570521689427e
# derivation: gap._patches
# source key: ceca10620e89af986038 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: R, r, theta
# expression sha256: 88b854c13bc3df0b513e919a2c2f40460c47be6a711277930ec966691670c45a (of its srepr)
def _lambdifygenerated(R, r, theta):
    x0 = (1/2)*theta
    x1 = numpy.sin(x0)
    x2 = x1**(-1.0)
    x3 = R*x1
    x4 = r + x3
    x5 = -r
    x6 = x3 + x5
    x7 = x1**2
    x8 = R*x7
    return (x2*numpy.sqrt(-R**2*x1**4 + r**2), -2*R + 2*r + 2*x2*numpy.sqrt(x4)*numpy.sqrt(x6)*numpy.cos(x0), numpy.arctan(numpy.sqrt((-x5 - x8)/(x4*x6*x7))*numpy.sqrt(r + x8)),)
