# ringchain generated code v1 sha256=c78639f8b658807bb7f2275927d8b0826fd05015437497768258f39e9e013428
# derivation: disorder._harmonic_speed
# source key: 07201ab9dccdbac32795 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: log_mean_a, log_mean_transit
# expression sha256: 4b84c47ed8770e7bc9aa16ea18816c7acc29aaf87d5c71535fb1c5023b2394dd (of its srepr)
def _lambdifygenerated(log_mean_a, log_mean_transit):
    return log_mean_a - log_mean_transit
