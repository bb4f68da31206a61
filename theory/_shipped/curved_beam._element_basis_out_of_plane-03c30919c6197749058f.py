# ringchain generated code v1 sha256=d17d7aa94402a284e7059fdeb88710822744610e848f2308dd6c15cbbcec19f7
# derivation: curved_beam._element_basis_out_of_plane
# source key: ceca10620e89af986038 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: theta, R, D_b, D_t, D_z
# expression sha256: 349b8a7ee87a011d9546f61ad8eb51a66239fd211e4870bcd666f42f5797e1fd (of its srepr)
def _lambdifygenerated(theta, R, D_b, D_t, D_z):
    x0 = numpy.cos(theta)
    x1 = numpy.sin(theta)
    x2 = D_b**(-1.0)
    x3 = (1/2)*x2
    x4 = theta*x3*(D_b + D_t)
    x5 = R**2
    x6 = (D_t + D_z*x5)**(-1.0)
    x7 = D_z*x6
    x8 = R**(-1.0)
    x9 = x1*x8
    x10 = -x9
    x11 = x0*x8
    x12 = x4*x9
    x13 = x3*(D_b - D_t)
    x14 = x11*x4
    x15 = x5**(-1.0)
    x16 = x1*x15
    x17 = D_t*x2
    x18 = x0*x15
    return numpy.array([[1, theta, x0, x1, -x0*x4 + x1, x0 + x1*x4], [0, R*x7, x10, x11, x11*x13 + x12, -x13*x9 + x14], [0, 0, -x11, x10, x14, -x12], [0, 0, 0, 0, x16*x17, x17*x18], [0, x7, 0, 0, x18, -x16], [0, D_t*x6*x8, 0, 0, 0, 0]])
