# ringchain generated code v1 sha256=d3a7785ab9281531ced7c940369108c6825beceee54dd3a690992f8ca6a18d79
# derivation: disorder._solitary_effective
# source key: aaa6be78b00d30412b2b (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: n, log_F_m, log_mean_a, log_mean_m, log_mean_K_compliance
# expression sha256: c8fb33f5e7d7aaefc49f2046aaece584bf1e6c35aa57027bc7e9e6d220c0bbbd (of its srepr)
def _lambdifygenerated(n, log_F_m, log_mean_a, log_mean_m, log_mean_K_compliance):
    return (1/2)*log_F_m - 1/2*log_F_m/n - 1/2*log_mean_K_compliance + log_mean_a - 1/2*log_mean_m - 1/2*numpy.log(n + 1) + (1/2)*numpy.log(2)
