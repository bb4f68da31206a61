# ringchain generated code v1 sha256=6d64ced147d67adb194500a28444687eac74876040e925f57548071d1610f4f7
# derivation: plastic._yield_speed
# source key: 67895ff0807168ca9dd5 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: log_K_c, log_delta_y, log_m
# expression sha256: 0e0baae4527f83094855b6feed5ac26ae508d1e12b6e60c9107c205d53c8383f (of its srepr)
def _lambdifygenerated(log_K_c, log_delta_y, log_m):
    return (1/2)*log_K_c + (5/4)*log_delta_y - 1/2*log_m - 1/2*numpy.log(5) + numpy.log(2)
