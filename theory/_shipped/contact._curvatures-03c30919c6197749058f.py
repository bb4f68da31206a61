# ringchain generated code v1 sha256=f18aec62bc9bb10e1fd2553a4c806d49d19c6c91b00ca0794b2daef2c117802f
# derivation: contact._curvatures
# source key: ceca10620e89af986038 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: R, r, theta
# expression sha256: a3c47908c4600774d91efda3f68900d9150d3ab8ae78c19b5f613ee556e861ba (of its srepr)
def _lambdifygenerated(R, r, theta):
    x0 = -r
    x1 = numpy.sin((1/2)*theta)**2
    x2 = R*x1 + x0
    return (x2/(r*(R + x0)), R*(1 - 2*x1)/x2,)
