# ringchain generated code v1 sha256=d18237e7c7bfb4dbe103d88b2cc82b4aa2d64ed29bacd0de4f5e2dff0f9726dc
# derivation: curved_beam._element_basis_in_plane
# source key: ceca10620e89af986038 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: theta, R, D_11, D_12, D_22, D_s
# expression sha256: b7023e49b3f65a3179da8a6bcab3bb0356cc18631bc85a40932bcfcba0858c48 (of its srepr)
def _lambdifygenerated(theta, R, D_11, D_12, D_22, D_s):
    x0 = numpy.sin(theta)
    x1 = numpy.cos(theta)
    x2 = D_22*D_s
    x3 = D_11*D_22 - D_12**2
    x4 = D_11*D_s*R**2 + x3
    x5 = (-x2 + x4)**(-1.0)
    x6 = x1*x5
    x7 = D_12*R
    x8 = 2*D_s
    x9 = theta*(x2 + x4 + x7*x8)
    x10 = x6*x9
    x11 = x0*x5
    x12 = x11*x9
    x13 = D_11*R
    x14 = D_12 + x13
    x15 = x14**(-1.0)
    x16 = R**(-1.0)
    x17 = D_11*x15
    x18 = x14*x8
    x19 = x18*x6
    x20 = x11*x18
    x21 = x16*x8*(-D_22 - x7)
    x22 = 2*x16
    return numpy.array([[x0, x1, 0, 1, x0 + x10, x1 - x12], [x1, -x0, 1, -theta*x13*x15, -x12, -x10], [0, 0, x16, -theta*x17, -x19, x20], [0, 0, 0, D_12*x15*x16, x11*x21, x21*x6], [0, 0, 0, 0, x22*x3*x6, -x11*x22*x3], [0, 0, 0, -x16*x17, x16*x20, x16*x19]])
