# ringchain generated code v1 sha256=ed392f8da9a40f536f0dcfcf6e80be9c403ac7515d19bf9f99bb30fe8f488922
# derivation: disorder._harmonic_speed
# source key: 0d3b9b67499038ff2889 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: log_mean_a, log_mean_transit
# expression sha256: 4b84c47ed8770e7bc9aa16ea18816c7acc29aaf87d5c71535fb1c5023b2394dd (of its srepr)
def _lambdifygenerated(log_mean_a, log_mean_transit):
    return log_mean_a - log_mean_transit
