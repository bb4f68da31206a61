# ringchain generated code v1 sha256=f1b8659bae418c1bd97620d0e7af1c829197c37f1f54c3300ebf1805dbec9ab9
# derivation: contact._curvatures
# source key: c0b268e8f55b26f011d3 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: R, r, theta
# expression sha256: a3c47908c4600774d91efda3f68900d9150d3ab8ae78c19b5f613ee556e861ba (of its srepr)
def _lambdifygenerated(R, r, theta):
    x0 = -r
    x1 = numpy.sin((1/2)*theta)**2
    x2 = R*x1 + x0
    return (x2/(r*(R + x0)), R*(1 - 2*x1)/x2,)
