# ringchain generated code v1 sha256=0777b164e33e19c4a6b47c8fdf1193486839b4353d30d36f3bb8e82e2eddf092
# derivation: plastic._yield_speed
# source key: ceca10620e89af986038 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: log_K_c, log_delta_y, log_m
# expression sha256: 0e0baae4527f83094855b6feed5ac26ae508d1e12b6e60c9107c205d53c8383f (of its srepr)
def _lambdifygenerated(log_K_c, log_delta_y, log_m):
    return (1/2)*log_K_c + (5/4)*log_delta_y - 1/2*log_m - 1/2*numpy.log(5) + numpy.log(2)
