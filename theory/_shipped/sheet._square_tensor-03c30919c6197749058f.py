# ringchain generated code v1 sha256=bdcf5bf8c6840aad354ee1342ce5758d115a8fd2ae2be79fb7d8774b1a3004ad
# derivation: sheet._square_tensor
# source key: ceca10620e89af986038 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: theta, kappa_0, kappa_1, tau_0, tau_1
# expression sha256: 1b725d030c092177071ee1fd6b3819d9d73cb7f6468d0cc0905c58c0a9c314a0 (of its srepr)
def _lambdifygenerated(theta, kappa_0, kappa_1, tau_0, tau_1):
    x0 = numpy.cos(theta)**2
    x1 = numpy.sin(theta)**2
    return (kappa_0*x0 + tau_1*x1, kappa_1*x1 + tau_0*x0, 0)
