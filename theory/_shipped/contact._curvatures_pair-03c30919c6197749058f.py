# ringchain generated code v1 sha256=ee5ffdd030b1abcd3a2b2ecc55e2dfe8c1420efcfc86271148fa2e4f8b93af8b
# derivation: contact._curvatures_pair
# source key: ceca10620e89af986038 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: R_1, r_1, R_2, r_2, theta
# expression sha256: f9b93b6dc0a3ab971f41c8176272b085750a62dcff3e2a702b8f647533ff8234 (of its srepr)
def _lambdifygenerated(R_1, r_1, R_2, r_2, theta):
    x0 = R_1*r_1
    x1 = R_1*r_2
    x2 = 2*r_2
    x3 = R_2*r_1
    x4 = r_2**2
    x5 = r_1**2
    x6 = 2*r_1
    x7 = r_1**(-1.0)
    x8 = r_2**(-1.0)
    x9 = R_1 - r_1
    x10 = R_2 - r_2
    x11 = (1/2)*x7*x8/(x10*x9)
    x12 = -1/x9
    x13 = -x8 - 1/x10
    x14 = (1/2)*numpy.sqrt(-x13*(-4*x12 + 4*x7)*numpy.cos(theta)**2 + (-x12 + x13 + x7)**2)
    return (x11*(R_1*R_2*numpy.sin(theta)**2 - R_2*r_2 + r_2*x6 - x0 - x1 - x3 + x4 + x5)/(x11*(-R_1*x4 + R_2*x0 + R_2*x1 - R_2*x5 - x0*x2 - x2*x3 + x2*x5 + x4*x6) + x14), x14,)
