# ringchain generated code v1 sha256=9f49b2b0463137b7f1391d4f2773a9b235e9d91bccdc476adc8a5054d0202c63
# derivation: disorder._effective_speed
# source key: 0d3b9b67499038ff2889 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: log_mean_a, log_mean_m, log_mean_compliance
# expression sha256: a3f1bb5ec73402409d34d738c9ff16eb37040f5a3264e1a18ef289514c049200 (of its srepr)
def _lambdifygenerated(log_mean_a, log_mean_m, log_mean_compliance):
    return log_mean_a - 1/2*log_mean_compliance - 1/2*log_mean_m
