# ringchain generated code v1 sha256=c4165ef9ed3c2d6f3180b07a17eb9a78f69257ef0c8ce8f42e9da7ec9294db29
# derivation: curved_beam._mode_matrices_out_of_plane
# source key: ceca10620e89af986038 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: k, R, rho, D_b, D_t, D_z, m_11, m_22, m_23, m_33
# expression sha256: 85a68cd2fcc1fcbde0e7a4160c6c884b568248c9f77e3aeab4e30ee4aea10c6d (of its srepr)
def _lambdifygenerated(k, R, rho, D_b, D_t, D_z, m_11, m_22, m_23, m_33):
    x0 = k**2
    x1 = R**(-1.0)
    x2 = numpy.pi*D_z
    x3 = k*x2
    x4 = numpy.pi*x1
    x5 = k*x1
    x6 = numpy.pi*x5*(-D_b - D_t)
    x7 = numpy.pi*R*rho
    x8 = m_23*x7
    x9 = -x5
    return numpy.array([[x0*x1*x2, x3, 0], [x3, x4*(D_b*x0 + D_t + D_z*R**2), x6], [0, x6, x4*(D_b + D_t*x0)], [m_11*x7, 0, x8], [0, m_22*x7, 0], [x8, 0, m_33*x7], [0, x5, -x1], [0, x1, x9], [x9, -1, 0]])
