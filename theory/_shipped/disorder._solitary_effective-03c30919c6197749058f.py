# ringchain generated code v1 sha256=2753b2743a75def5e506fcfe044e0a1e820e685ee410788c4f38e23a3631a0c9
# derivation: disorder._solitary_effective
# source key: ceca10620e89af986038 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: n, log_F_m, log_mean_a, log_mean_m, log_mean_K_compliance
# expression sha256: c8fb33f5e7d7aaefc49f2046aaece584bf1e6c35aa57027bc7e9e6d220c0bbbd (of its srepr)
def _lambdifygenerated(n, log_F_m, log_mean_a, log_mean_m, log_mean_K_compliance):
    return (1/2)*log_F_m - 1/2*log_F_m/n - 1/2*log_mean_K_compliance + log_mean_a - 1/2*log_mean_m - 1/2*numpy.log(n + 1) + (1/2)*numpy.log(2)
