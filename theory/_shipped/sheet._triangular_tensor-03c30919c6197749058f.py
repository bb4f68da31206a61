# ringchain generated code v1 sha256=3077aabeffc0f5206337b1eb121bf5d9f39b86437d7736d30b2e7348a58484a7
# derivation: sheet._triangular_tensor
# source key: ceca10620e89af986038 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: theta, kappa_0, kappa_1, kappa_2, tau_0, tau_1, tau_2
# expression sha256: 79d547ac9cb7fb32576e48adaeaf4acb08bc41cbf1e77cd8747e48cea6319514 (of its srepr)
def _lambdifygenerated(theta, kappa_0, kappa_1, kappa_2, tau_0, tau_1, tau_2):
    x0 = numpy.cos(theta)**2
    x1 = numpy.sin(theta + (1/6)*numpy.pi)**2
    x2 = (1/4)*x1
    x3 = numpy.cos(theta + (1/3)*numpy.pi)**2
    x4 = (1/4)*x3
    return (kappa_0*x0 + x2*(kappa_1 + 3*tau_1) + x4*(kappa_2 + 3*tau_2), tau_0*x0 + x2*(3*kappa_1 + tau_1) + x4*(3*kappa_2 + tau_2), (1/4)*numpy.sqrt(3)*(x1*(kappa_1 - tau_1) + x3*(-kappa_2 + tau_2)))
