# ringchain generated code v1 sha256=c047ab5b27d1465bc181e61f73f172c77d1e3b30ff8cff6dee217ef084a05bff
# derivation: sheet._square_tensor
# source key: a22a0557fcec1bc1abe9 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: theta, kappa_0, kappa_1, tau_0, tau_1
# expression sha256: 1b725d030c092177071ee1fd6b3819d9d73cb7f6468d0cc0905c58c0a9c314a0 (of its srepr)
def _lambdifygenerated(theta, kappa_0, kappa_1, tau_0, tau_1):
    x0 = numpy.cos(theta)**2
    x1 = numpy.sin(theta)**2
    return (kappa_0*x0 + tau_1*x1, kappa_1*x1 + tau_0*x0, 0)
