# ringchain generated code v1 sha256=2142af36fcb730a3e4518c6cc9a2f3c366ff8243d1e377a3ee12dff8b6706f94
# derivation: plastic._yield_speed
# source key: c0b268e8f55b26f011d3 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: log_K_c, log_delta_y, log_m
# expression sha256: 0e0baae4527f83094855b6feed5ac26ae508d1e12b6e60c9107c205d53c8383f (of its srepr)
def _lambdifygenerated(log_K_c, log_delta_y, log_m):
    return (1/2)*log_K_c + (5/4)*log_delta_y - 1/2*log_m - 1/2*numpy.log(5) + numpy.log(2)
