# ringchain generated code v1 sha256=54b621d7bbf85f1dcf5a8d85dd2a5e275a744a396e73b07cf71fe3b0be651343
# derivation: disorder._harmonic_speed
# source key: f3be020559998432f519 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: log_mean_a, log_mean_transit
# expression sha256: 4b84c47ed8770e7bc9aa16ea18816c7acc29aaf87d5c71535fb1c5023b2394dd (of its srepr)
def _lambdifygenerated(log_mean_a, log_mean_transit):
    return log_mean_a - log_mean_transit
