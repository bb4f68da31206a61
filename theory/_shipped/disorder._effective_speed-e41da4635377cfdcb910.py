# ringchain generated code v1 sha256=b18a952ab381d0b52e49be46aeafa5b0d88d2f9ce6953e5dde2b6e1516a98b8b
# derivation: disorder._effective_speed
# source key: aaa6be78b00d30412b2b (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: log_mean_a, log_mean_m, log_mean_compliance
# expression sha256: a3f1bb5ec73402409d34d738c9ff16eb37040f5a3264e1a18ef289514c049200 (of its srepr)
def _lambdifygenerated(log_mean_a, log_mean_m, log_mean_compliance):
    return log_mean_a - 1/2*log_mean_compliance - 1/2*log_mean_m
