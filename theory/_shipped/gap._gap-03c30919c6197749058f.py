# ringchain generated code v1 sha256=7ce33cfa1912f9948cbd523ee530b87ed0615ae2f28251a3e517294dc320e88a
# derivation: gap._gap
# source key: ceca10620e89af986038 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: x, y, R, r, theta
# expression sha256: 3347a0556c4b4c566175b1581f6f4e6455e8192ec13b689f7cc38a1e7a0a143b (of its srepr)
def _lambdifygenerated(x, y, R, r, theta):
    x0 = r**2
    x1 = numpy.cos(theta)
    x2 = numpy.sin(theta)
    return -2*R + 2*r + numpy.sqrt(-x**2 + (R - numpy.sqrt(x0 - y**2))**2) + numpy.sqrt((R - numpy.sqrt(x0 - (-x*x2 + x1*y)**2))**2 - (x*x1 + x2*y)**2)
