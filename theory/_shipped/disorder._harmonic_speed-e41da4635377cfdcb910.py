# ringchain generated code v1 sha256=bcaf171b8bccdb790070ff7d0b3b2b8025845bb337b9c47b54fb1d1092a4444d
# derivation: disorder._harmonic_speed
# source key: aaa6be78b00d30412b2b (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: log_mean_a, log_mean_transit
# expression sha256: 4b84c47ed8770e7bc9aa16ea18816c7acc29aaf87d5c71535fb1c5023b2394dd (of its srepr)
def _lambdifygenerated(log_mean_a, log_mean_transit):
    return log_mean_a - log_mean_transit
