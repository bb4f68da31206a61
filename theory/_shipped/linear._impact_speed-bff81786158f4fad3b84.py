# ringchain generated code v1 sha256=fe27f51be4fdc45819a6e0c638ea2891e270a6dce29bd19a8167ba3535e445c2
# derivation: linear._impact_speed
# source key: 07201ab9dccdbac32795 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: h, g
# expression sha256: 78e19f22b1980e24ec3dd4fe4cae41965662f526eed175e5eee688ad141fb7c8 (of its srepr)
def _lambdifygenerated(h, g):
    return numpy.sqrt(2)*numpy.sqrt(g)*numpy.sqrt(h)
