# ringchain generated code v1 sha256=0d1e1ecddcf824ff23d89f8ae0aa37b17b047e0fe1ab0aec33ca9c95345e1f63
# derivation: disorder._harmonic_speed
# source key: 0881d513a06819d2e367 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: log_mean_a, log_mean_transit
# expression sha256: 4b84c47ed8770e7bc9aa16ea18816c7acc29aaf87d5c71535fb1c5023b2394dd (of its srepr)
def _lambdifygenerated(log_mean_a, log_mean_transit):
    return log_mean_a - log_mean_transit
