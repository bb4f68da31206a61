# ringchain generated code v1 sha256=bdc8f234e51e092f8c8f6ff8f4b8da42096d26cdec5ef2980087e004057ddbcd
# derivation: disorder._effective_speed
# source key: 317867d47b5755454417 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: log_mean_a, log_mean_m, log_mean_compliance
# expression sha256: a3f1bb5ec73402409d34d738c9ff16eb37040f5a3264e1a18ef289514c049200 (of its srepr)
def _lambdifygenerated(log_mean_a, log_mean_m, log_mean_compliance):
    return log_mean_a - 1/2*log_mean_compliance - 1/2*log_mean_m
