# ringchain generated code v1 sha256=d864f89e0a1cdbb01a54734b53d037428006f505d62aee62004a6874bfcb549a
# derivation: linear._impact_speed
# source key: f3be020559998432f519 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: h, g
# expression sha256: 78e19f22b1980e24ec3dd4fe4cae41965662f526eed175e5eee688ad141fb7c8 (of its srepr)
def _lambdifygenerated(h, g):
    return numpy.sqrt(2)*numpy.sqrt(g)*numpy.sqrt(h)
