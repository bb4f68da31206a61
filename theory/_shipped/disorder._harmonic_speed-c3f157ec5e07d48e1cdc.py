# ringchain generated code v1 sha256=b348c2b0d135cc4b9b3a315e1bd5768ecd1ead56d02a354eb0516c552e787074
# derivation: disorder._harmonic_speed
# source key: caeff341571871d5b69b (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: log_mean_a, log_mean_transit
# expression sha256: 4b84c47ed8770e7bc9aa16ea18816c7acc29aaf87d5c71535fb1c5023b2394dd (of its srepr)
def _lambdifygenerated(log_mean_a, log_mean_transit):
    return log_mean_a - log_mean_transit
