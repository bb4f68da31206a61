# ringchain generated code v1 sha256=3c844aea1a12609fc459276f7a65b221f5864340f896804b37c0a448630932ee
# derivation: disorder._effective_speed
# source key: 67895ff0807168ca9dd5 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: log_mean_a, log_mean_m, log_mean_compliance
# expression sha256: a3f1bb5ec73402409d34d738c9ff16eb37040f5a3264e1a18ef289514c049200 (of its srepr)
def _lambdifygenerated(log_mean_a, log_mean_m, log_mean_compliance):
    return log_mean_a - 1/2*log_mean_compliance - 1/2*log_mean_m
