# ringchain generated code v1 sha256=86607be8cbc2dbcce6af14039282121a330bc0c3973880d7118883c144269634
# derivation: disorder._harmonic_speed
# source key: 67895ff0807168ca9dd5 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: log_mean_a, log_mean_transit
# expression sha256: 4b84c47ed8770e7bc9aa16ea18816c7acc29aaf87d5c71535fb1c5023b2394dd (of its srepr)
def _lambdifygenerated(log_mean_a, log_mean_transit):
    return log_mean_a - log_mean_transit
