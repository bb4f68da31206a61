# ringchain generated code v1 sha256=0964fb69d58017c3fd2e4f4abf91ff9f474e6749ce58f24d5d8ee219a1311a80
# derivation: disorder._harmonic_speed
# source key: ceca10620e89af986038 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: log_mean_a, log_mean_transit
# expression sha256: 4b84c47ed8770e7bc9aa16ea18816c7acc29aaf87d5c71535fb1c5023b2394dd (of its srepr)
def _lambdifygenerated(log_mean_a, log_mean_transit):
    return log_mean_a - log_mean_transit
