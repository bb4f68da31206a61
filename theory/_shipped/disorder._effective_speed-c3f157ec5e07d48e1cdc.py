# ringchain generated code v1 sha256=6dfeb343b76ce03417c5a2d83c99a81a2b6903192c6d8f542e8523069a74e704
# derivation: disorder._effective_speed
# source key: caeff341571871d5b69b (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: log_mean_a, log_mean_m, log_mean_compliance
# expression sha256: a3f1bb5ec73402409d34d738c9ff16eb37040f5a3264e1a18ef289514c049200 (of its srepr)
def _lambdifygenerated(log_mean_a, log_mean_m, log_mean_compliance):
    return log_mean_a - 1/2*log_mean_compliance - 1/2*log_mean_m
