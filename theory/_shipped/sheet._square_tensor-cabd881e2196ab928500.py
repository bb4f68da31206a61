# ringchain generated code v1 sha256=c9964747270e90d3a4de190dc3a52acf28f39f4ef59c8b515fad8d4f15918289
# derivation: sheet._square_tensor
# source key: 317867d47b5755454417 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: theta, kappa_0, kappa_1, tau_0, tau_1
# expression sha256: 1b725d030c092177071ee1fd6b3819d9d73cb7f6468d0cc0905c58c0a9c314a0 (of its srepr)
def _lambdifygenerated(theta, kappa_0, kappa_1, tau_0, tau_1):
    x0 = numpy.cos(theta)**2
    x1 = numpy.sin(theta)**2
    return (kappa_0*x0 + tau_1*x1, kappa_1*x1 + tau_0*x0, 0)
