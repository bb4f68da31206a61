# ringchain generated code v1 sha256=6d8bbbe57dc62da62a8fd5baac6a5839c3868f2a1c929275e59d74a47774a1b8
# derivation: contact._curvatures
# source key: 67895ff0807168ca9dd5 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: R, r, theta
# expression sha256: a3c47908c4600774d91efda3f68900d9150d3ab8ae78c19b5f613ee556e861ba (of its srepr)
def _lambdifygenerated(R, r, theta):
    x0 = -r
    x1 = numpy.sin((1/2)*theta)**2
    x2 = R*x1 + x0
    return (x2/(r*(R + x0)), R*(1 - 2*x1)/x2,)
