# ringchain generated code v1 sha256=6bc2c92671e7b6adac907864fe3a687177dad4dd4297ea8ef6f7e9f2f58b2467
# derivation: linear._impact_speed
# source key: aaa6be78b00d30412b2b (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: h, g
# expression sha256: 78e19f22b1980e24ec3dd4fe4cae41965662f526eed175e5eee688ad141fb7c8 (of its srepr)
def _lambdifygenerated(h, g):
    return numpy.sqrt(2)*numpy.sqrt(g)*numpy.sqrt(h)
