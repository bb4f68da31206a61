# ringchain generated code v1 sha256=8657657f0705a4d200a99364f57495be27e8d90c9afa82961194eb6f8b0092ab
# derivation: contact._curvatures
# source key: a22a0557fcec1bc1abe9 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: R, r, theta
# expression sha256: a3c47908c4600774d91efda3f68900d9150d3ab8ae78c19b5f613ee556e861ba (of its srepr)
def _lambdifygenerated(R, r, theta):
    x0 = -r
    x1 = numpy.sin((1/2)*theta)**2
    x2 = R*x1 + x0
    return (x2/(r*(R + x0)), R*(1 - 2*x1)/x2,)
