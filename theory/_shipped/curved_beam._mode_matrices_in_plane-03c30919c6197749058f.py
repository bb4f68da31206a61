# ringchain generated code v1 sha256=62077fcf89c22b35c8ba879bac8a390e036d476bde5ccbcd69d124fac692daf7
# derivation: curved_beam._mode_matrices_in_plane
# source key: ceca10620e89af986038 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: k, R, rho, D_11, D_12, D_22, D_s, m_11, m_23, m_33
# expression sha256: 20fd3c822de9471556a1f4507bf3576d74bec8afa455cbe1199c9ece5bdd2f44 (of its srepr)
def _lambdifygenerated(k, R, rho, D_11, D_12, D_22, D_s, m_11, m_23, m_33):
    x0 = k**2
    x1 = R**(-1.0)
    x2 = numpy.pi*x1
    x3 = k*x1
    x4 = numpy.pi*x3
    x5 = x4*(D_11 + D_s)
    x6 = -D_s*R
    x7 = x4*(D_12 + x6)
    x8 = x2*(D_12*x0 + x6)
    x9 = numpy.pi*R*rho
    x10 = m_11*x9
    x11 = m_23*x9
    return numpy.array([[x2*(D_11 + D_s*x0), x5, x7], [x5, x2*(D_11*x0 + D_s), x8], [x7, x8, x2*(D_22*x0 + D_s*R**2)], [x10, 0, 0], [0, x10, x11], [0, x11, m_33*x9], [x1, x3, 0], [-x3, -x1, 1], [0, 0, x3]])
