# ringchain generated code v1 sha256=7cf841abc291ddd02d7bbbc3a33a068989ab8c68b9ca539623f9cc9ea3f71abf
# derivation: disorder._harmonic_speed
# source key: 317867d47b5755454417 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: log_mean_a, log_mean_transit
# expression sha256: 4b84c47ed8770e7bc9aa16ea18816c7acc29aaf87d5c71535fb1c5023b2394dd (of its srepr)
def _lambdifygenerated(log_mean_a, log_mean_transit):
    return log_mean_a - log_mean_transit
