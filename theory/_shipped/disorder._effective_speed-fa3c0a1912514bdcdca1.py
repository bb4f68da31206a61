# ringchain generated code v1 sha256=6c992d4eb7bd4931b5102b5e5eb2e399a73e8dfb2c21c591c98e960132e25c01
# derivation: disorder._effective_speed
# source key: 10a35615fa68ecdff34f (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: log_mean_a, log_mean_m, log_mean_compliance
# expression sha256: a3f1bb5ec73402409d34d738c9ff16eb37040f5a3264e1a18ef289514c049200 (of its srepr)
def _lambdifygenerated(log_mean_a, log_mean_m, log_mean_compliance):
    return log_mean_a - 1/2*log_mean_compliance - 1/2*log_mean_m
