# ringchain generated code v1 sha256=a5852db60a1f149e9ab8ed9a2654239212d33193c6838e9f26aa87c27f2cec8c
# derivation: disorder._effective_speed
# source key: c0b268e8f55b26f011d3 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: log_mean_a, log_mean_m, log_mean_compliance
# expression sha256: a3f1bb5ec73402409d34d738c9ff16eb37040f5a3264e1a18ef289514c049200 (of its srepr)
def _lambdifygenerated(log_mean_a, log_mean_m, log_mean_compliance):
    return log_mean_a - 1/2*log_mean_compliance - 1/2*log_mean_m
