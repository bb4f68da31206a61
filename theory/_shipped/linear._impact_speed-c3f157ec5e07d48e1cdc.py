# ringchain generated code v1 sha256=33bc11f5d09adb4683819faaa3c1e6276ad7ce55424592597e8e5334ec39c70e
# derivation: linear._impact_speed
# source key: caeff341571871d5b69b (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: h, g
# expression sha256: 78e19f22b1980e24ec3dd4fe4cae41965662f526eed175e5eee688ad141fb7c8 (of its srepr)
def _lambdifygenerated(h, g):
    return numpy.sqrt(2)*numpy.sqrt(g)*numpy.sqrt(h)
