# ringchain generated code v1 sha256=074da00e349d1ecc4fa7d52ae291b99632670ce21dc21fc1352872277eff40d1
# derivation: disorder._effective_speed
# source key: a22a0557fcec1bc1abe9 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: log_mean_a, log_mean_m, log_mean_compliance
# expression sha256: a3f1bb5ec73402409d34d738c9ff16eb37040f5a3264e1a18ef289514c049200 (of its srepr)
def _lambdifygenerated(log_mean_a, log_mean_m, log_mean_compliance):
    return log_mean_a - 1/2*log_mean_compliance - 1/2*log_mean_m
