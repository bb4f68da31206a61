# ringchain generated code v1 sha256=4310e80d3ec9fad7ab758006e61ce28bed8a32612b7f05e73df099dfb5db8bdb
# derivation: subsurface._log_load_at_pressure
# source key: ceca10620e89af986038 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: log_p0, log_A, log_E, nu, m_1
# expression sha256: 96082ead1fa2cbd06864189b05e0e8a93618897d359ecb650afdbb988af53345 (of its srepr)
def _lambdifygenerated(log_p0, log_A, log_E, nu, m_1):
    x0 = nu - 1
    x1 = nu + 1
    x2 = scipy.special.elliprd(0, m_1, 1)
    return (-2*log_A - 2*log_E + 3*log_p0 + numpy.log((8/27)*numpy.pi*m_1**(3/2)*x0**2*x1**2*x2**2), -log_A - log_E + log_p0 + numpy.log(-2/3*numpy.sqrt(m_1)*x0*x1*x2),)
