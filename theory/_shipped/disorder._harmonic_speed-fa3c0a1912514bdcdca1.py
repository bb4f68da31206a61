# ringchain generated code v1 sha256=6e35e43dd8755185d0a28ce305e15e8342f9636716c635eec8cced7a2c1f66ec
# derivation: disorder._harmonic_speed
# source key: 10a35615fa68ecdff34f (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: log_mean_a, log_mean_transit
# expression sha256: 4b84c47ed8770e7bc9aa16ea18816c7acc29aaf87d5c71535fb1c5023b2394dd (of its srepr)
def _lambdifygenerated(log_mean_a, log_mean_transit):
    return log_mean_a - log_mean_transit
