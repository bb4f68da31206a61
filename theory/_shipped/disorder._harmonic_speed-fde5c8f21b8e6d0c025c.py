# ringchain generated code v1 sha256=8ee35a0030bae8ba839cf2da331cc14cd5576271d857d2e2226b90e4d06c4685
# derivation: disorder._harmonic_speed
# source key: 263ab3517922b3fc21eb (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: log_mean_a, log_mean_transit
# expression sha256: 4b84c47ed8770e7bc9aa16ea18816c7acc29aaf87d5c71535fb1c5023b2394dd (of its srepr)
def _lambdifygenerated(log_mean_a, log_mean_transit):
    return log_mean_a - log_mean_transit
